// Windows code page 1252, the encoding of CODESYS V2 exports and the OSCAT libraries.
#pragma once

#include <optional>

namespace rung::source {

// The code point of a cp1252 byte, or nullopt for the five bytes cp1252 leaves
// undefined (0x81, 0x8D, 0x8F, 0x90, 0x9D).
std::optional<char32_t> cp1252_to_unicode(unsigned char byte);

// The cp1252 byte for a code point, or nullopt when cp1252 cannot represent it.
std::optional<unsigned char> unicode_to_cp1252(char32_t cp);

}  // namespace rung::source
