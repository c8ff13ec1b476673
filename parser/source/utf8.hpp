// UTF-8 primitives shared by the decoder, the encoder and the line index.
// Validation follows the Unicode "maximal subpart" rule so that every invalid
// sequence becomes exactly one U+FFFD, the same way editors and browsers do it.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace rung::source {

inline constexpr char32_t replacement_character = 0xFFFD;

// One step of UTF-8 decoding at `pos`.
struct Utf8Step {
  char32_t code_point;  // U+FFFD when !valid
  uint32_t length;      // bytes consumed, >= 1 (for invalid input: the maximal subpart)
  bool valid;
};

// Decodes the code point starting at text[pos]; pos must be < text.size().
Utf8Step decode_utf8_at(std::string_view text, size_t pos);

// Length of the all-ASCII prefix of text[pos..], checked 8 bytes at a time: the fast path that
// keeps decoding, validating and encoding large files well under a second.
size_t ascii_run(std::string_view text, size_t pos);

// Appends the UTF-8 form of `cp` (which must be a scalar value, not a surrogate).
void append_utf8(std::string& out, char32_t cp);

// True for bytes 10xxxxxx, which never start a code point.
inline bool is_utf8_continuation(unsigned char byte) {
  return (byte & 0xC0) == 0x80;
}

// Number of UTF-16 code units the code point needs (1 or 2).
inline uint32_t utf16_length(char32_t cp) {
  return cp >= 0x10000 ? 2 : 1;
}

}  // namespace rung::source
