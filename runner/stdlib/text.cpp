#include "runner/stdlib/text.hpp"

#include <vector>

namespace rung::run {
namespace {

// Decodes one UTF-8 sequence at `at`; malformed bytes decode as themselves (Latin-1), so no input
// is lost.
uint32_t next_code_point(std::string_view text, size_t& at) {
  const auto first = static_cast<unsigned char>(text[at]);
  auto continuation = [&](size_t offset) -> int {
    if (at + offset >= text.size()) return -1;
    const auto byte = static_cast<unsigned char>(text[at + offset]);
    return (byte & 0xC0) == 0x80 ? (byte & 0x3F) : -1;
  };
  if (first < 0x80) {
    ++at;
    return first;
  }
  if ((first & 0xE0) == 0xC0) {
    const int c1 = continuation(1);
    if (c1 >= 0) {
      at += 2;
      return ((first & 0x1Fu) << 6) | static_cast<uint32_t>(c1);
    }
  } else if ((first & 0xF0) == 0xE0) {
    const int c1 = continuation(1);
    const int c2 = continuation(2);
    if (c1 >= 0 && c2 >= 0) {
      at += 3;
      return ((first & 0x0Fu) << 12) | (static_cast<uint32_t>(c1) << 6) | static_cast<uint32_t>(c2);
    }
  } else if ((first & 0xF8) == 0xF0) {
    const int c1 = continuation(1);
    const int c2 = continuation(2);
    const int c3 = continuation(3);
    if (c1 >= 0 && c2 >= 0 && c3 >= 0) {
      at += 4;
      return ((first & 0x07u) << 18) | (static_cast<uint32_t>(c1) << 12) | (static_cast<uint32_t>(c2) << 6) |
             static_cast<uint32_t>(c3);
    }
  }
  ++at;
  return first;
}

void append_utf8(std::string& out, uint32_t code) {
  if (code < 0x80) {
    out += static_cast<char>(code);
  } else if (code < 0x800) {
    out += static_cast<char>(0xC0 | (code >> 6));
    out += static_cast<char>(0x80 | (code & 0x3F));
  } else if (code < 0x10000) {
    out += static_cast<char>(0xE0 | (code >> 12));
    out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (code & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (code >> 18));
    out += static_cast<char>(0x80 | ((code >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (code & 0x3F));
  }
}

}  // namespace

std::string utf8_to_single_byte(std::string_view utf8) {
  std::string out;
  out.reserve(utf8.size());
  for (size_t at = 0; at < utf8.size();) {
    const uint32_t code = next_code_point(utf8, at);
    out += code <= 0xFF ? static_cast<char>(code) : '?';
  }
  return out;
}

std::string single_byte_to_utf8(std::string_view bytes) {
  std::string out;
  out.reserve(bytes.size());
  for (char c : bytes) append_utf8(out, static_cast<unsigned char>(c));
  return out;
}

std::string utf8_to_utf16le(std::string_view utf8) {
  std::string out;
  auto unit = [&](uint32_t value) {
    out += static_cast<char>(value & 0xFF);
    out += static_cast<char>((value >> 8) & 0xFF);
  };
  for (size_t at = 0; at < utf8.size();) {
    const uint32_t code = next_code_point(utf8, at);
    if (code >= 0x10000) {
      const uint32_t v = code - 0x10000;
      unit(0xD800 | (v >> 10));
      unit(0xDC00 | (v & 0x3FF));
    } else {
      unit(code);
    }
  }
  return out;
}

std::string utf16_to_utf8(const uint16_t* units, size_t count) {
  std::string out;
  for (size_t i = 0; i < count; ++i) {
    uint32_t code = units[i];
    if (code >= 0xD800 && code < 0xDC00 && i + 1 < count && units[i + 1] >= 0xDC00 && units[i + 1] < 0xE000) {
      code = 0x10000 + ((code - 0xD800) << 10) + (units[i + 1] - 0xDC00);
      ++i;
    }
    append_utf8(out, code);
  }
  return out;
}

}  // namespace rung::run
