// Text encodings of PLC strings. A STRING holds one byte per character in the target's code page
// (CODESYS and TwinCAT: Windows-1252, whose printable range rung reads as Latin-1); a WSTRING holds
// UTF-16 code units. rung's own text is UTF-8: these convert at the edges (literals in, reports out).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace rung::run {

// UTF-8 to one byte per character; characters beyond U+00FF become '?'.
std::string utf8_to_single_byte(std::string_view utf8);
std::string single_byte_to_utf8(std::string_view bytes);
// UTF-8 to UTF-16LE code units, as bytes.
std::string utf8_to_utf16le(std::string_view utf8);
std::string utf16_to_utf8(const uint16_t* units, size_t count);

}  // namespace rung::run
