#include "runner/stdlib/natives.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <string>

#include <fmt/format.h>

#include "checker/constant/const_value.hpp"
#include "runner/stdlib/datetime.hpp"
#include "runner/stdlib/text.hpp"

namespace rung::run {
namespace {

// --- strings in VM memory ---------------------------------------------------------------------

// The characters of the string at `address` (up to its NUL, never past memory).
std::string read_string(Machine& machine, uint64_t address) {
  if (!machine.checked(address, 1)) return {};
  const uint8_t* begin = machine.memory() + address;
  const uint64_t limit = machine.memory_size() - address;
  const void* nul = std::memchr(begin, 0, limit);
  const uint64_t length = nul ? static_cast<uint64_t>(static_cast<const uint8_t*>(nul) - begin) : limit;
  return std::string(reinterpret_cast<const char*>(begin), length);
}

std::u16string read_wstring(Machine& machine, uint64_t address) {
  if (!machine.checked(address, 2)) return {};
  std::u16string out;
  for (uint64_t at = address; at + 2 <= machine.memory_size(); at += 2) {
    uint16_t unit = 0;
    std::memcpy(&unit, machine.memory() + at, 2);
    if (unit == 0) break;
    out += static_cast<char16_t>(unit);
  }
  return out;
}

// Writes `text` truncated to `capacity` characters and a NUL.
void write_string(Machine& machine, uint64_t address, std::string_view text, uint64_t capacity) {
  const uint64_t length = std::min<uint64_t>(text.size(), capacity);
  uint8_t* at = machine.checked(address, length + 1);
  if (!at) return;
  std::memcpy(at, text.data(), length);
  at[length] = 0;
}

void write_wstring(Machine& machine, uint64_t address, const std::u16string& text, uint64_t capacity) {
  const uint64_t length = std::min<uint64_t>(text.size(), capacity);
  uint8_t* at = machine.checked(address, (length + 1) * 2);
  if (!at) return;
  std::memcpy(at, text.data(), length * 2);
  at[length * 2] = 0;
  at[length * 2 + 1] = 0;
}

int64_t clamp_count(int64_t value) { return std::max<int64_t>(0, value); }

// The string operations, one template for STRING (std::string) and WSTRING (std::u16string).
template <typename S>
S left(const S& s, int64_t n) {
  return s.substr(0, static_cast<size_t>(std::min<int64_t>(clamp_count(n), static_cast<int64_t>(s.size()))));
}
template <typename S>
S right(const S& s, int64_t n) {
  const auto count = static_cast<size_t>(std::min<int64_t>(clamp_count(n), static_cast<int64_t>(s.size())));
  return s.substr(s.size() - count);
}
// MID(STR, LEN, POS): LEN characters from position POS (1-based).
template <typename S>
S mid(const S& s, int64_t length, int64_t position) {
  if (position < 1 || position > static_cast<int64_t>(s.size())) return S();
  return s.substr(static_cast<size_t>(position - 1), static_cast<size_t>(clamp_count(length)));
}
// INSERT(STR1, STR2, POS): STR2 after position POS of STR1.
template <typename S>
S insert(const S& s, const S& what, int64_t position) {
  const auto at = static_cast<size_t>(std::clamp<int64_t>(position, 0, static_cast<int64_t>(s.size())));
  return s.substr(0, at) + what + s.substr(at);
}
// DELETE(STR, LEN, POS): LEN characters from position POS removed.
template <typename S>
S erase(const S& s, int64_t length, int64_t position) {
  if (position < 1 || position > static_cast<int64_t>(s.size())) return s;
  S out = s;
  out.erase(static_cast<size_t>(position - 1), static_cast<size_t>(clamp_count(length)));
  return out;
}
// REPLACE(STR1, STR2, L, P): L characters of STR1 from position P replaced by STR2.
template <typename S>
S replace(const S& s, const S& with, int64_t length, int64_t position) {
  if (position < 1) position = 1;
  if (position > static_cast<int64_t>(s.size()) + 1) return s;
  S out = s;
  out.replace(static_cast<size_t>(position - 1), static_cast<size_t>(clamp_count(length)), with);
  return out;
}
// FIND(STR1, STR2): the 1-based position of STR2 in STR1, 0 when absent.
template <typename S>
int64_t find(const S& s, const S& what) {
  if (what.empty()) return 0;
  const size_t at = s.find(what);
  return at == S::npos ? 0 : static_cast<int64_t>(at) + 1;
}

std::u16string to_u16(std::string_view utf8) {
  const std::string bytes = utf8_to_utf16le(utf8);
  std::u16string out(bytes.size() / 2, u'\0');
  std::memcpy(out.data(), bytes.data(), out.size() * 2);
  return out;
}

std::string from_u16(const std::u16string& text) {
  return utf16_to_utf8(reinterpret_cast<const uint16_t*>(text.data()), text.size());
}

// --- numbers as text ----------------------------------------------------------------------------

std::string real_text(double value, bool single) {
  if (std::isnan(value)) return "NaN";
  if (std::isinf(value)) return value > 0 ? "INF" : "-INF";
  std::string text = single ? fmt::format("{}", static_cast<float>(value)) : fmt::format("{}", value);
  return text;
}

std::string value_text(Slot value, TextKind kind) {
  switch (kind) {
    case TextKind::Signed: return std::to_string(value.i);
    case TextKind::Unsigned:
    case TextKind::Byte: return std::to_string(value.u);
    case TextKind::Real: return real_text(value.f32, true);
    case TextKind::LReal: return real_text(value.f64, false);
    case TextKind::Bool: return value.u != 0 ? "TRUE" : "FALSE";
    case TextKind::Time: return duration_text(static_cast<int32_t>(value.u) < 0 ? static_cast<int64_t>(static_cast<uint32_t>(value.u)) : value.i, TimeUnit::Milliseconds, false);
    case TextKind::LTime: return duration_text(value.i, TimeUnit::Nanoseconds, true);
    case TextKind::Date: return date_text(value.i, TimeUnit::Seconds, false);
    case TextKind::TimeOfDay: return time_of_day_text(value.i, TimeUnit::Milliseconds, false);
    case TextKind::DateAndTime: return date_and_time_text(value.i, TimeUnit::Seconds, false);
    case TextKind::LDate: return date_text(value.i, TimeUnit::Nanoseconds, true);
    case TextKind::LTimeOfDay: return time_of_day_text(value.i, TimeUnit::Nanoseconds, true);
    case TextKind::LDateAndTime: return date_and_time_text(value.i, TimeUnit::Nanoseconds, true);
  }
  return {};
}

std::string trim(std::string_view text) {
  size_t begin = 0;
  size_t end = text.size();
  while (begin < end && (text[begin] == ' ' || text[begin] == '\t')) ++begin;
  while (end > begin && (text[end - 1] == ' ' || text[end - 1] == '\t')) --end;
  return std::string(text.substr(begin, end - begin));
}

// STRING_TO_*: the leading number of the text (CODESYS reads '123abc' as 123), 0 when none.
Slot parse_text(std::string_view raw, TextKind kind) {
  Slot out{};
  const std::string text = trim(raw);
  switch (kind) {
    case TextKind::Bool: out.u = check::parse_integer_literal(text).value_or(0) != 0 ||
                                 (text.size() == 4 && (text[0] == 'T' || text[0] == 't'));
      return out;
    case TextKind::Real:
    case TextKind::LReal: {
      double value = 0;
      size_t consumed = 0;
      try {
        value = std::stod(text, &consumed);
      } catch (...) {
        value = 0;
      }
      if (kind == TextKind::Real) {
        out.f32 = static_cast<float>(value);
      } else {
        out.f64 = value;
      }
      return out;
    }
    case TextKind::Time:
    case TextKind::LTime: {
      std::string literal = text;
      if (literal.find('#') == std::string::npos) literal = "T#" + literal;
      const auto ns = check::parse_duration_literal(literal).value_or(0);
      out.i = kind == TextKind::Time ? static_cast<int64_t>(ns / 1'000'000) : static_cast<int64_t>(ns);
      return out;
    }
    case TextKind::Date:
    case TextKind::LDate:
      out.i = parse_point_literal(text, PointKind::Date, kind == TextKind::Date ? TimeUnit::Seconds : TimeUnit::Nanoseconds).value_or(0);
      return out;
    case TextKind::TimeOfDay:
    case TextKind::LTimeOfDay:
      out.i = parse_point_literal(text, PointKind::TimeOfDay, kind == TextKind::TimeOfDay ? TimeUnit::Milliseconds : TimeUnit::Nanoseconds).value_or(0);
      return out;
    case TextKind::DateAndTime:
    case TextKind::LDateAndTime:
      out.i = parse_point_literal(text, PointKind::DateAndTime, kind == TextKind::DateAndTime ? TimeUnit::Seconds : TimeUnit::Nanoseconds).value_or(0);
      return out;
    default: {
      // Integers: an optional sign, then digits or an IEC based literal (16#FF).
      if (auto literal = check::parse_integer_literal(text)) {
        out.i = static_cast<int64_t>(*literal);
        return out;
      }
      size_t at = 0;
      bool negative = false;
      if (at < text.size() && (text[at] == '-' || text[at] == '+')) negative = text[at++] == '-';
      int64_t value = 0;
      while (at < text.size() && text[at] >= '0' && text[at] <= '9') value = value * 10 + (text[at++] - '0');
      out.i = negative ? -value : value;
      return out;
    }
  }
}

}  // namespace

void native_string_compare(Machine& machine, const Instr&) {
  const std::string right_text = read_string(machine, machine.pop().u);
  const std::string left_text = read_string(machine, machine.pop().u);
  const int order = left_text.compare(right_text);
  machine.push_i(order < 0 ? -1 : (order > 0 ? 1 : 0));
}

void native_wstring_compare(Machine& machine, const Instr&) {
  const std::u16string right_text = read_wstring(machine, machine.pop().u);
  const std::u16string left_text = read_wstring(machine, machine.pop().u);
  const int order = left_text.compare(right_text);
  machine.push_i(order < 0 ? -1 : (order > 0 ? 1 : 0));
}

void native_expt_lreal(Machine& machine, const Instr&) {
  const double exponent = machine.pop().f64;
  machine.top().f64 = std::pow(machine.top().f64, exponent);
}

#define RUNG_STRING_NATIVES(PREFIX, READ, WRITE)                                          \
  void native_##PREFIX##len(Machine& machine, const Instr&) {                            \
    const auto s = READ(machine, machine.pop().u);                                        \
    machine.push_i(static_cast<int64_t>(s.size()));                                       \
  }                                                                                       \
  void native_##PREFIX##left(Machine& machine, const Instr& in) {                        \
    const int64_t n = machine.pop().i;                                                    \
    const auto s = READ(machine, machine.pop().u);                                        \
    const uint64_t dst = machine.top().u;                                                 \
    WRITE(machine, dst, left(s, n), static_cast<uint64_t>(in.b));                         \
  }                                                                                       \
  void native_##PREFIX##right(Machine& machine, const Instr& in) {                       \
    const int64_t n = machine.pop().i;                                                    \
    const auto s = READ(machine, machine.pop().u);                                        \
    WRITE(machine, machine.top().u, right(s, n), static_cast<uint64_t>(in.b));            \
  }                                                                                       \
  void native_##PREFIX##mid(Machine& machine, const Instr& in) {                         \
    const int64_t position = machine.pop().i;                                             \
    const int64_t length = machine.pop().i;                                               \
    const auto s = READ(machine, machine.pop().u);                                        \
    WRITE(machine, machine.top().u, mid(s, length, position), static_cast<uint64_t>(in.b)); \
  }                                                                                       \
  void native_##PREFIX##concat(Machine& machine, const Instr& in) {                      \
    const auto b = READ(machine, machine.pop().u);                                        \
    const auto a = READ(machine, machine.pop().u);                                        \
    WRITE(machine, machine.top().u, a + b, static_cast<uint64_t>(in.b));                  \
  }                                                                                       \
  void native_##PREFIX##insert(Machine& machine, const Instr& in) {                      \
    const int64_t position = machine.pop().i;                                             \
    const auto what = READ(machine, machine.pop().u);                                     \
    const auto s = READ(machine, machine.pop().u);                                        \
    WRITE(machine, machine.top().u, insert(s, what, position), static_cast<uint64_t>(in.b)); \
  }                                                                                       \
  void native_##PREFIX##delete(Machine& machine, const Instr& in) {                      \
    const int64_t position = machine.pop().i;                                             \
    const int64_t length = machine.pop().i;                                               \
    const auto s = READ(machine, machine.pop().u);                                        \
    WRITE(machine, machine.top().u, erase(s, length, position), static_cast<uint64_t>(in.b)); \
  }                                                                                       \
  void native_##PREFIX##replace(Machine& machine, const Instr& in) {                     \
    const int64_t position = machine.pop().i;                                             \
    const int64_t length = machine.pop().i;                                               \
    const auto with = READ(machine, machine.pop().u);                                     \
    const auto s = READ(machine, machine.pop().u);                                        \
    WRITE(machine, machine.top().u, replace(s, with, length, position), static_cast<uint64_t>(in.b)); \
  }                                                                                       \
  void native_##PREFIX##find(Machine& machine, const Instr&) {                           \
    const auto what = READ(machine, machine.pop().u);                                     \
    const auto s = READ(machine, machine.pop().u);                                        \
    machine.push_i(find(s, what));                                                        \
  }

RUNG_STRING_NATIVES(, read_string, write_string)
RUNG_STRING_NATIVES(w, read_wstring, write_wstring)
#undef RUNG_STRING_NATIVES

void native_string_to_wstring(Machine& machine, const Instr& in) {
  const std::string s = read_string(machine, machine.pop().u);
  write_wstring(machine, machine.top().u, to_u16(single_byte_to_utf8(s)), static_cast<uint64_t>(in.b));
}

void native_wstring_to_string(Machine& machine, const Instr& in) {
  const std::u16string s = read_wstring(machine, machine.pop().u);
  write_string(machine, machine.top().u, utf8_to_single_byte(from_u16(s)), static_cast<uint64_t>(in.b));
}

#define RUNG_MATH(NAME, EXPR)                          \
  void native_##NAME(Machine& machine, const Instr&) { \
    const double x = machine.top().f64;                \
    machine.top().f64 = (EXPR);                        \
  }
RUNG_MATH(sqrt, std::sqrt(x))
RUNG_MATH(ln, std::log(x))
RUNG_MATH(log, std::log10(x))
RUNG_MATH(exp, std::exp(x))
RUNG_MATH(sin, std::sin(x))
RUNG_MATH(cos, std::cos(x))
RUNG_MATH(tan, std::tan(x))
RUNG_MATH(asin, std::asin(x))
RUNG_MATH(acos, std::acos(x))
RUNG_MATH(atan, std::atan(x))
RUNG_MATH(trunc_lreal, std::trunc(x))
#undef RUNG_MATH

void native_atan2(Machine& machine, const Instr&) {
  const double x = machine.pop().f64;
  machine.top().f64 = std::atan2(machine.top().f64, x);
}

void native_to_string(Machine& machine, const Instr& in) {
  const Slot value = machine.pop();
  write_string(machine, machine.top().u, utf8_to_single_byte(value_text(value, static_cast<TextKind>(in.aux))),
               static_cast<uint64_t>(in.b));
}

void native_to_wstring(Machine& machine, const Instr& in) {
  const Slot value = machine.pop();
  write_wstring(machine, machine.top().u, to_u16(value_text(value, static_cast<TextKind>(in.aux))),
                static_cast<uint64_t>(in.b));
}

void native_string_to(Machine& machine, const Instr& in) {
  const std::string s = read_string(machine, machine.pop().u);
  machine.push(parse_text(single_byte_to_utf8(s), static_cast<TextKind>(in.aux)));
}

void native_wstring_to(Machine& machine, const Instr& in) {
  const std::u16string s = read_wstring(machine, machine.pop().u);
  machine.push(parse_text(from_u16(s), static_cast<TextKind>(in.aux)));
}

void native_to_bcd(Machine& machine, const Instr& in) {
  uint64_t value = machine.top().u;
  uint64_t out = 0;
  for (unsigned shift = 0; shift < in.aux && value != 0; shift += 4) {
    out |= (value % 10) << shift;
    value /= 10;
  }
  machine.top().u = out;
}

void native_from_bcd(Machine& machine, const Instr& in) {
  const uint64_t value = machine.top().u;
  uint64_t out = 0;
  uint64_t scale = 1;
  for (unsigned shift = 0; shift < in.aux; shift += 4) {
    out += ((value >> shift) & 0xF) * scale;
    scale *= 10;
  }
  machine.top().u = out;
}

void native_time_ms(Machine& machine, const Instr&) {
  machine.push_i(static_cast<int64_t>(static_cast<uint32_t>(machine.time_ns() / 1'000'000)));
}

void native_time_ns(Machine& machine, const Instr&) { machine.push_i(static_cast<int64_t>(machine.time_ns())); }

void native_concat_date_time(Machine& machine, const Instr& in) {
  const auto what = static_cast<DateField>(in.aux);
  const size_t count = what == DateField::Date ? 3 : what == DateField::TimeOfDay ? 4 : 7;
  int64_t field[7] = {};
  for (size_t i = count; i-- > 0;) field[i] = machine.pop().i;
  // A time of day in milliseconds; fields beyond their range carry over (61 minutes = 1 h 1 min).
  auto time_of_day = [](const int64_t* at) { return ((at[0] * 60 + at[1]) * 60 + at[2]) * 1000 + at[3]; };
  // A date in days since 1970; a month outside 1..12 carries into the year, a day beyond the
  // month's end into the next month (the day count is added to the month's first day).
  auto days = [](int64_t year, int64_t month, int64_t day) {
    const int64_t month_index = month - 1;
    const int64_t years = month_index >= 0 ? month_index / 12 : (month_index - 11) / 12;
    return days_from_civil(year + years, static_cast<unsigned>(month_index - years * 12 + 1), 1) + day - 1;
  };
  int64_t out = 0;
  if (what == DateField::TimeOfDay) {
    out = time_of_day(field);
  } else if (what == DateField::Date) {
    out = days(field[0], field[1], field[2]) * 86400;
  } else {
    out = days(field[0], field[1], field[2]) * 86400 + time_of_day(field + 3) / 1000;
  }
  machine.push_i(out);
}

void native_new(Machine& machine, const Instr&) {
  const uint64_t bytes = machine.pop().u;
  machine.push_i(static_cast<int64_t>(machine.allocate(bytes)));
}

void native_delete_block(Machine& machine, const Instr&) { machine.release(machine.pop().u); }

}  // namespace rung::run
