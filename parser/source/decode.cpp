#include "parser/source/decode.hpp"

#include <fmt/format.h>

#include <cstring>

#include "parser/source/cp1252.hpp"
#include "parser/source/utf8.hpp"

namespace rung::source {
namespace {

constexpr size_t sample_size = size_t{8} * 1024;

// Collects issues up to the cap, then only counts; flush() adds the summary.
class IssueSink {
 public:
  explicit IssueSink(std::vector<DecodeIssue>& issues) : issues_(issues) {}

  void flush() {
    if (dropped_ > 0) {
      issues_.push_back({last_offset_, fmt::format("{} more encoding problems not listed", dropped_)});
      dropped_ = 0;
    }
  }

  template <typename... Args>
  void add(size_t offset, fmt::format_string<Args...> format, Args&&... args) {
    if (issues_.size() < max_decode_issues) {
      issues_.push_back({static_cast<uint32_t>(offset), fmt::format(format, std::forward<Args>(args)...)});
    } else {
      ++dropped_;
      last_offset_ = static_cast<uint32_t>(offset);
    }
  }

 private:
  std::vector<DecodeIssue>& issues_;
  size_t dropped_ = 0;
  uint32_t last_offset_ = 0;
};

bool starts_with(std::string_view bytes, std::string_view prefix) {
  return bytes.size() >= prefix.size() && bytes.substr(0, prefix.size()) == prefix;
}

struct Utf8Survey {
  size_t multibyte = 0;  // valid sequences of 2-4 bytes
  size_t invalid = 0;    // maximal invalid subparts
};

Utf8Survey survey_utf8(std::string_view text) {
  Utf8Survey survey;
  size_t pos = 0;
  while (pos < text.size()) {
    pos += ascii_run(text, pos);
    if (pos >= text.size()) break;
    const Utf8Step step = decode_utf8_at(text, pos);
    if (step.valid) {
      ++survey.multibyte;
    } else {
      ++survey.invalid;
    }
    pos += step.length;
  }
  return survey;
}

void decode_utf8_lossy(std::string_view text, std::string& out, IssueSink& sink) {
  out.reserve(text.size() + text.size() / 8);
  size_t pos = 0;
  while (pos < text.size()) {
    const size_t run = ascii_run(text, pos);
    out.append(text.substr(pos, run));
    pos += run;
    if (pos >= text.size()) break;
    const Utf8Step step = decode_utf8_at(text, pos);
    if (step.valid) {
      out.append(text.substr(pos, step.length));
    } else {
      sink.add(out.size(), "invalid UTF-8 byte 0x{:02X} replaced by U+FFFD",
               static_cast<unsigned>(static_cast<unsigned char>(text[pos])));
      append_utf8(out, replacement_character);
    }
    pos += step.length;
  }
}

void decode_cp1252(std::string_view text, std::string& out, IssueSink& sink) {
  out.reserve(text.size() + text.size() / 8);
  size_t pos = 0;
  while (pos < text.size()) {
    const size_t run = ascii_run(text, pos);
    out.append(text.substr(pos, run));
    pos += run;
    if (pos >= text.size()) break;
    const auto byte = static_cast<unsigned char>(text[pos]);
    if (const auto cp = cp1252_to_unicode(byte)) {
      append_utf8(out, *cp);
    } else {
      sink.add(out.size(), "byte 0x{:02X} is undefined in cp1252; replaced by U+FFFD", static_cast<unsigned>(byte));
      append_utf8(out, replacement_character);
    }
    ++pos;
  }
}

void decode_utf16(std::string_view bytes, bool big_endian, std::string& out, IssueSink& sink) {
  out.reserve(bytes.size() / 2 + bytes.size() / 8);
  const auto unit_at = [&](size_t i) -> char16_t {
    const auto b0 = static_cast<unsigned char>(bytes[i]);
    const auto b1 = static_cast<unsigned char>(bytes[i + 1]);
    return static_cast<char16_t>(big_endian ? (b0 << 8) | b1 : (b1 << 8) | b0);
  };
  const size_t even = bytes.size() & ~size_t{1};
  size_t i = 0;
  while (i < even) {
    const char16_t unit = unit_at(i);
    i += 2;
    if (unit >= 0xD800 && unit <= 0xDBFF) {
      if (i < even) {
        const char16_t low = unit_at(i);
        if (low >= 0xDC00 && low <= 0xDFFF) {
          i += 2;
          append_utf8(out, 0x10000 + ((char32_t(unit) - 0xD800) << 10) + (char32_t(low) - 0xDC00));
          continue;
        }
      }
      sink.add(out.size(), "unpaired UTF-16 surrogate 0x{:04X} replaced by U+FFFD", static_cast<unsigned>(unit));
      append_utf8(out, replacement_character);
    } else if (unit >= 0xDC00 && unit <= 0xDFFF) {
      sink.add(out.size(), "unpaired UTF-16 surrogate 0x{:04X} replaced by U+FFFD", static_cast<unsigned>(unit));
      append_utf8(out, replacement_character);
    } else {
      append_utf8(out, unit);
    }
  }
  if (even != bytes.size()) {
    sink.add(out.size(), "UTF-16 file ends in the middle of a code unit");
    append_utf8(out, replacement_character);
  }
}

// BOM-less UTF-16: most characters of PLC source are ASCII, so one byte of each
// pair is zero. Requires a clear majority so that binary data with scattered
// zeros is not taken for text.
std::optional<Encoding> sniff_utf16(std::string_view bytes) {
  const std::string_view sample = bytes.substr(0, sample_size);
  const size_t pairs = sample.size() / 2;
  if (pairs < 2) return std::nullopt;
  size_t le = 0, be = 0;
  for (size_t p = 0; p < pairs; ++p) {
    const bool first_zero = sample[2 * p] == '\0';
    const bool second_zero = sample[2 * p + 1] == '\0';
    if (!first_zero && second_zero) ++le;
    if (first_zero && !second_zero) ++be;
  }
  if (le * 10 >= pairs * 7) return Encoding::Utf16Le;
  if (be * 10 >= pairs * 7) return Encoding::Utf16Be;
  return std::nullopt;
}

void finish_utf16(DecodedText& result, std::string_view payload, bool big_endian) {
  IssueSink sink(result.issues);
  decode_utf16(payload, big_endian, result.utf8, sink);
  sink.flush();
  if (looks_binary(std::string_view(result.utf8).substr(0, sample_size))) {
    result.is_binary = true;
    result.utf8.clear();
    result.issues.clear();
  }
}

}  // namespace

std::string_view encoding_name(Encoding encoding) {
  switch (encoding) {
    case Encoding::Utf8: return "UTF-8";
    case Encoding::Cp1252: return "cp1252";
    case Encoding::Utf16Le: return "UTF-16LE";
    case Encoding::Utf16Be: return "UTF-16BE";
  }
  return "UTF-8";
}

bool looks_binary(std::string_view sample) {
  if (sample.empty()) return false;
  size_t control = 0;
  for (const char c : sample) {
    const auto b = static_cast<unsigned char>(c);
    if (b == 0) return true;
    // Tab, line ends, form feed and the DOS end-of-file mark (0x1A) occur in real sources.
    const bool text_control = b == '\t' || b == '\n' || b == '\r' || b == '\f' || b == '\v' || b == 0x1A;
    if ((b < 0x20 && !text_control) || b == 0x7F) ++control;
  }
  return control * 10 > sample.size();  // more than 10 %
}

// Some export tools pad files with NUL bytes up to a block size. A run of NULs at the very end of
// otherwise 8-bit text is that padding, not binary content: it is dropped, with a warning.
size_t trailing_nul_padding(std::string_view bytes) {
  size_t n = 0;
  while (n < bytes.size() && bytes[bytes.size() - 1 - n] == '\0') ++n;
  if (n == 0 || n == bytes.size()) return 0;
  return bytes.substr(0, bytes.size() - n).find('\0') == std::string_view::npos ? n : 0;
}

void note_padding(DecodedText& result, size_t padding) {
  if (padding == 0) return;
  result.issues.push_back({static_cast<uint32_t>(result.utf8.size()),
                           fmt::format("{} NUL bytes at the end of the file were ignored", padding)});
}

DecodedText decode(std::string_view bytes) {
  DecodedText result;

  if (starts_with(bytes, "\xEF\xBB\xBF")) {
    result.had_bom = true;
    const size_t padding = trailing_nul_padding(bytes.substr(3));
    const std::string_view payload = bytes.substr(3, bytes.size() - 3 - padding);
    if (looks_binary(payload.substr(0, sample_size))) {
      result.is_binary = true;
      return result;
    }
    IssueSink sink(result.issues);
    decode_utf8_lossy(payload, result.utf8, sink);
    sink.flush();
    note_padding(result, padding);
    return result;
  }
  if (starts_with(bytes, "\xFF\xFE") || starts_with(bytes, "\xFE\xFF")) {
    const bool big_endian = bytes[0] == '\xFE';
    result.had_bom = true;
    result.encoding = big_endian ? Encoding::Utf16Be : Encoding::Utf16Le;
    finish_utf16(result, bytes.substr(2), big_endian);
    return result;
  }
  // (UTF-16 text has NULs throughout, so it never counts as padded.)
  const size_t padding = trailing_nul_padding(bytes);
  bytes.remove_suffix(padding);
  if (const auto utf16 = sniff_utf16(bytes)) {
    result.encoding = *utf16;
    finish_utf16(result, bytes, *utf16 == Encoding::Utf16Be);
    return result;
  }
  if (looks_binary(bytes.substr(0, sample_size))) {
    result.is_binary = true;
    return result;
  }

  const Utf8Survey survey = survey_utf8(bytes);
  if (survey.invalid == 0) {
    result.utf8.assign(bytes);
    note_padding(result, padding);
    return result;
  }
  IssueSink sink(result.issues);
  // A file that is mostly good UTF-8 with a few damaged bytes is UTF-8;
  // reading it as cp1252 would garble every correct non-ASCII character.
  if (survey.multibyte >= 2 * survey.invalid) {
    decode_utf8_lossy(bytes, result.utf8, sink);
  } else {
    result.encoding = Encoding::Cp1252;
    decode_cp1252(bytes, result.utf8, sink);
  }
  sink.flush();
  note_padding(result, padding);
  return result;
}

}  // namespace rung::source
