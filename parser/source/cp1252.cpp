#include "parser/source/cp1252.hpp"

#include <array>

namespace rung::source {
namespace {

// 0x80..0x9F are the only bytes where cp1252 differs from Latin-1; 0 marks undefined.
constexpr std::array<char32_t, 32> high_block = {
    0x20AC, 0,      0x201A, 0x0192, 0x201E, 0x2026, 0x2020, 0x2021,  // 80-87
    0x02C6, 0x2030, 0x0160, 0x2039, 0x0152, 0,      0x017D, 0,       // 88-8F
    0,      0x2018, 0x2019, 0x201C, 0x201D, 0x2022, 0x2013, 0x2014,  // 90-97
    0x02DC, 0x2122, 0x0161, 0x203A, 0x0153, 0,      0x017E, 0x0178,  // 98-9F
};

}  // namespace

std::optional<char32_t> cp1252_to_unicode(unsigned char byte) {
  if (byte < 0x80 || byte > 0x9F) return byte;
  const char32_t cp = high_block[byte - 0x80];
  if (cp == 0) return std::nullopt;
  return cp;
}

std::optional<unsigned char> unicode_to_cp1252(char32_t cp) {
  if (cp < 0x80 || (cp >= 0xA0 && cp <= 0xFF)) return static_cast<unsigned char>(cp);
  for (unsigned i = 0; i < high_block.size(); ++i) {
    if (high_block[i] != 0 && high_block[i] == cp) return static_cast<unsigned char>(0x80 + i);
  }
  return std::nullopt;
}

}  // namespace rung::source
