#include "parser/source/encode.hpp"

#include "parser/source/cp1252.hpp"
#include "parser/source/utf8.hpp"

namespace rung::source {
namespace {

void append_utf16_unit(std::string& out, char16_t unit, bool big_endian) {
  const auto hi = static_cast<char>(unit >> 8);
  const auto lo = static_cast<char>(unit & 0xFF);
  if (big_endian) {
    out.push_back(hi);
    out.push_back(lo);
  } else {
    out.push_back(lo);
    out.push_back(hi);
  }
}

// Walks the UTF-8 text once; `emit` returns false to stop at an unencodable
// character. Returns the offset where it stopped, or nullopt when done.
template <typename Emit>
std::optional<uint32_t> walk(std::string_view utf8, Emit&& emit) {
  size_t pos = 0;
  while (pos < utf8.size()) {
    // ASCII needs no decoding; most PLC source is ASCII but for its comments.
    const size_t ascii_end = pos + ascii_run(utf8, pos);
    for (; pos < ascii_end; ++pos) {
      if (!emit(static_cast<char32_t>(utf8[pos]))) return static_cast<uint32_t>(pos);
    }
    if (pos >= utf8.size()) break;
    const Utf8Step step = decode_utf8_at(utf8, pos);
    if (!step.valid || !emit(step.code_point)) return static_cast<uint32_t>(pos);
    pos += step.length;
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::string> encode(std::string_view utf8, Encoding encoding, bool bom) {
  std::string out;
  switch (encoding) {
    case Encoding::Utf8: {
      if (walk(utf8, [](char32_t) { return true; })) return std::nullopt;
      if (bom) out = "\xEF\xBB\xBF";
      out.append(utf8);
      return out;
    }
    case Encoding::Cp1252: {
      out.reserve(utf8.size());
      const auto stop = walk(utf8, [&](char32_t cp) {
        const auto byte = unicode_to_cp1252(cp);
        if (!byte) return false;
        out.push_back(static_cast<char>(*byte));
        return true;
      });
      if (stop) return std::nullopt;
      return out;
    }
    case Encoding::Utf16Le:
    case Encoding::Utf16Be: {
      const bool big_endian = encoding == Encoding::Utf16Be;
      out.reserve(utf8.size() * 2 + 2);
      if (bom) append_utf16_unit(out, 0xFEFF, big_endian);
      const auto stop = walk(utf8, [&](char32_t cp) {
        if (cp >= 0x10000) {
          const char32_t v = cp - 0x10000;
          append_utf16_unit(out, static_cast<char16_t>(0xD800 + (v >> 10)), big_endian);
          append_utf16_unit(out, static_cast<char16_t>(0xDC00 + (v & 0x3FF)), big_endian);
        } else {
          append_utf16_unit(out, static_cast<char16_t>(cp), big_endian);
        }
        return true;
      });
      if (stop) return std::nullopt;
      return out;
    }
  }
  return std::nullopt;
}

std::optional<uint32_t> first_unencodable(std::string_view utf8, Encoding encoding) {
  if (encoding == Encoding::Cp1252) {
    return walk(utf8, [](char32_t cp) { return unicode_to_cp1252(cp).has_value(); });
  }
  return walk(utf8, [](char32_t) { return true; });
}

}  // namespace rung::source
