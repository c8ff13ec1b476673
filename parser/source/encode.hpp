// Writing UTF-8 text back in a file's original encoding (the formatter and
// refactorings must not change a cp1252 or UTF-16 file into UTF-8 behind the user's back).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "parser/source/decode.hpp"

namespace rung::source {

// The bytes of `utf8` in `encoding`, with a BOM first when `bom` is true (ignored
// for cp1252, which has none). nullopt when the text holds a character the
// encoding cannot represent (cp1252: anything outside its 251 characters,
// including U+FFFD) or when `utf8` itself is not valid UTF-8.
std::optional<std::string> encode(std::string_view utf8, Encoding encoding, bool bom);

// The byte offset in `utf8` of the first character that `encode` cannot write
// in `encoding`, or nullopt when everything can be written: lets the caller say
// *where* the file cannot be saved.
std::optional<uint32_t> first_unencodable(std::string_view utf8, Encoding encoding);

}  // namespace rung::source
