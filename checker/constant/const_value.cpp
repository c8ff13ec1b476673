#include "checker/constant/const_value.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <limits>

#include "parser/source/utf8.hpp"

namespace rung::check {
namespace {

int digit_value(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return 99;
}

char lower(char c) { return (c >= 'A' && c <= 'Z') ? static_cast<char>(c + 32) : c; }

}  // namespace

std::string int128_to_string(__int128 value) {
  if (value == 0) return "0";
  const bool negative = value < 0;
  unsigned __int128 magnitude = negative ? -static_cast<unsigned __int128>(value) : static_cast<unsigned __int128>(value);
  std::string digits;
  while (magnitude > 0) {
    digits += static_cast<char>('0' + static_cast<int>(magnitude % 10));
    magnitude /= 10;
  }
  if (negative) digits += '-';
  std::reverse(digits.begin(), digits.end());
  return digits;
}

std::string to_string(const ConstValue& value) {
  switch (value.kind) {
    case ConstValue::Kind::Integer:
      return int128_to_string(value.integer);
    case ConstValue::Kind::Real:
      return fmt::format("{}", value.real);
    case ConstValue::Kind::Bool:
      return value.integer ? "TRUE" : "FALSE";
    case ConstValue::Kind::String:
      return "'" + value.text + "'";
    case ConstValue::Kind::Duration:
      return fmt::format("T#{}ms", int128_to_string(value.integer / 1000000));
    case ConstValue::Kind::Date:
      return int128_to_string(value.integer);
  }
  return "?";
}

std::string duration_literal_text(__int128 nanoseconds) {
  std::string text = nanoseconds < 0 ? "T#-" : "T#";
  __int128 rest = (nanoseconds < 0 ? -nanoseconds : nanoseconds) / 1'000'000;
  constexpr std::array<std::pair<std::string_view, int64_t>, 5> kUnits = {
      {{"d", 86'400'000}, {"h", 3'600'000}, {"m", 60'000}, {"s", 1000}, {"ms", 1}}};
  for (const auto& [unit, milliseconds] : kUnits) {
    if (rest < milliseconds) continue;
    text += int128_to_string(rest / milliseconds) + std::string(unit);
    rest %= milliseconds;
  }
  return text.back() == '#' || text.back() == '-' ? text + "0ms" : text;
}

std::optional<__int128> parse_integer_literal(std::string_view text) {
  int base = 10;
  if (const size_t hash = text.find('#'); hash != std::string_view::npos) {
    const std::string_view prefix = text.substr(0, hash);
    if (prefix == "2") {
      base = 2;
    } else if (prefix == "8") {
      base = 8;
    } else if (prefix == "16") {
      base = 16;
    } else if (prefix == "10") {
      base = 10;
    } else {
      return std::nullopt;
    }
    text.remove_prefix(hash + 1);
  }
  const __int128 limit = static_cast<__int128>(~static_cast<unsigned __int128>(0) >> 2);  // far above ULINT
  __int128 value = 0;
  bool any = false;
  for (char c : text) {
    if (c == '_') continue;
    const int digit = digit_value(c);
    if (digit >= base) return std::nullopt;
    value = value * base + digit;
    if (value > limit) return std::nullopt;
    any = true;
  }
  if (!any) return std::nullopt;
  return value;
}

std::optional<double> parse_real_literal(std::string_view text) {
  std::string clean;
  for (char c : text) {
    if (c != '_') clean += c;
  }
  char* end = nullptr;
  const double value = std::strtod(clean.c_str(), &end);
  if (end == clean.c_str() || *end != '\0') return std::nullopt;
  return value;
}

std::optional<__int128> parse_duration_literal(std::string_view text, std::string* error, const DurationRules& rules) {
  const size_t hash = text.find('#');
  if (hash == std::string_view::npos) return std::nullopt;
  std::string_view rest = text.substr(hash + 1);
  while (!rest.empty() && (rest.front() == ' ' || rest.front() == '\t')) rest.remove_prefix(1);
  bool negative = false;
  if (!rest.empty() && (rest.front() == '-' || rest.front() == '+')) {
    negative = rest.front() == '-';
    rest.remove_prefix(1);
  }
  // Units from largest to smallest; each may appear once, in this order (IEC 61131-3 6.3.3).
  constexpr std::array<std::pair<std::string_view, int64_t>, 7> kUnits = {{
      {"d", 86400000000000},
      {"h", 3600000000000},
      {"m", 60000000000},
      {"s", 1000000000},
      {"ms", 1000000},
      {"us", 1000},
      {"ns", 1},
  }};
  // The largest value each unit may have when a larger unit precedes it.
  constexpr std::array<long double, 7> kLimits = {0, 24, 60, 60, 1000, 1000, 1000};
  const bool long_time = !text.empty() && (text.front() == 'L' || text.front() == 'l');
  long double total = 0;
  int last_unit = -1;
  long double last_value = 0;
  int units = 0;
  size_t i = 0;
  bool any = false;
  while (i < rest.size()) {
    if (rest[i] == '_') {
      ++i;
      continue;
    }
    const size_t number_start = i;
    while (i < rest.size() && ((rest[i] >= '0' && rest[i] <= '9') || rest[i] == '_' || rest[i] == '.')) ++i;
    if (i == number_start) {
      if (error) *error = fmt::format("'{}' is not a number", rest.substr(i, 1));
      return std::nullopt;
    }
    std::string number;
    for (char c : rest.substr(number_start, i - number_start)) {
      if (c != '_') number += c;
    }
    std::string unit;
    while (i < rest.size() && std::isalpha(static_cast<unsigned char>(rest[i]))) unit += lower(rest[i++]);
    int unit_index = -1;
    for (size_t u = 0; u < kUnits.size(); ++u) {
      if (kUnits[u].first == unit) unit_index = static_cast<int>(u);
    }
    if (unit_index < 0) {
      if (error) *error = fmt::format("unknown time unit '{}'", unit);
      return std::nullopt;
    }
    if (unit_index <= last_unit) {
      if (error) *error = fmt::format("time units must go from days to nanoseconds ('{}' after a smaller or equal unit)", unit);
      return std::nullopt;
    }
    const long double value = std::strtold(number.c_str(), nullptr);
    const auto unit_slot = static_cast<size_t>(unit_index);
    if (!long_time && !rules.sub_millisecond_time && unit_index >= 5) {
      if (error) *error = fmt::format("a TIME counts milliseconds, '{}' needs an LTIME literal (LTIME#...)", unit);
      return std::nullopt;
    }
    if (rules.later_units_bounded && units > 0 && value >= kLimits[unit_slot]) {
      if (error) {
        *error = fmt::format("{}{} after a larger unit must be below {} (only the first unit may overflow)",
                             static_cast<long long>(value), unit, static_cast<long long>(kLimits[unit_slot]));
      }
      return std::nullopt;
    }
    last_unit = unit_index;
    last_value = value;
    total += last_value * kUnits[static_cast<size_t>(unit_index)].second;
    ++units;
    any = true;
  }
  if (!any) return std::nullopt;
  // TIME: the largest unit may overflow (T#100s12ms) and CODESYS normalises middle ones (T#3d29h
  // is T#4d5h), but the smallest of several may not: T#5m68s is an error (CODESYS textbook,
  // L4198). LTIME has no such rule: the CODESYS V3 manual's own example is
  // LTIME#3445343m3424732874823ns (MP300 manual).
  if (!long_time && units > 1 && last_unit > 0 && last_value >= kLimits[static_cast<size_t>(last_unit)]) {
    if (error) {
      *error = fmt::format("the smallest unit overflows ({}{} is {} or more; carry it into the next larger unit)",
                           static_cast<long long>(last_value), kUnits[static_cast<size_t>(last_unit)].first,
                           static_cast<long long>(kLimits[static_cast<size_t>(last_unit)]));
    }
    return std::nullopt;
  }
  const __int128 nanoseconds = static_cast<__int128>(total + 0.5L);
  return negative ? -nanoseconds : nanoseconds;
}

std::string real_range_problem(double value, bool single) {
  if (!std::isfinite(value)) return "beyond the largest LREAL (about 1.8E308)";
  if (single && std::fabs(value) > static_cast<double>(std::numeric_limits<float>::max())) {
    return "beyond the largest REAL (3.4028235E38)";
  }
  return {};
}

namespace {

// Reads digits (and '_' separators) at `pos`; nullopt when there are none.
std::optional<int64_t> read_number(std::string_view text, size_t& pos) {
  const size_t start = pos;
  int64_t value = 0;
  while (pos < text.size() && (std::isdigit(static_cast<unsigned char>(text[pos])) || text[pos] == '_')) {
    if (text[pos] != '_') value = std::min<int64_t>(value * 10 + (text[pos] - '0'), 1'000'000'000);
    ++pos;
  }
  if (pos == start) return std::nullopt;
  return value;
}

bool is_leap_year(int64_t year) { return (year % 4 == 0 && year % 100 != 0) || year % 400 == 0; }

int64_t days_in_month(int64_t year, int64_t month) {
  static constexpr std::array<int64_t, 12> kDays = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  return month == 2 && is_leap_year(year) ? 29 : kDays[static_cast<size_t>(month - 1)];
}

// Days from 1970-01-01 (proleptic Gregorian calendar).
int64_t days_since_epoch(int64_t year, int64_t month, int64_t day) {
  int64_t days = 0;
  for (int64_t y = 1970; y < year; ++y) days += is_leap_year(y) ? 366 : 365;
  for (int64_t m = 1; m < month; ++m) days += days_in_month(year, m);
  return days + day - 1;
}

struct DateFields {
  int64_t year = 0, month = 0, day = 0;
};

std::string read_date(std::string_view text, size_t& pos, DateFields& date) {
  auto year = read_number(text, pos);
  if (!year || pos >= text.size() || text[pos++] != '-') return "a date is written YYYY-MM-DD";
  auto month = read_number(text, pos);
  if (!month || pos >= text.size() || text[pos++] != '-') return "a date is written YYYY-MM-DD";
  auto day = read_number(text, pos);
  if (!day) return "a date is written YYYY-MM-DD";
  if (*year < 1970) return fmt::format("year {} is before 1970, where dates start", *year);
  if (*month < 1 || *month > 12) return fmt::format("month {} does not exist", *month);
  if (*day < 1 || *day > days_in_month(*year, *month)) {
    return fmt::format("{:04}-{:02} has no day {}", *year, *month, *day);
  }
  date = {*year, *month, *day};
  return {};
}

// hh:mm:ss[.fff]; `seconds_of_day` receives the whole seconds.
std::string read_time_of_day(std::string_view text, size_t& pos, int64_t& seconds_of_day) {
  auto hours = read_number(text, pos);
  if (!hours || pos >= text.size() || text[pos++] != ':') return "a time of day is written hh:mm:ss";
  auto minutes = read_number(text, pos);
  if (!minutes) return "a time of day is written hh:mm:ss";
  int64_t seconds = 0;
  if (pos < text.size() && text[pos] == ':') {
    ++pos;
    auto read = read_number(text, pos);
    if (!read) return "a time of day is written hh:mm:ss";
    seconds = *read;
    if (pos < text.size() && text[pos] == '.') {
      ++pos;
      if (!read_number(text, pos)) return "a fraction of a second needs digits after '.'";
    }
  }
  if (*hours > 23) return fmt::format("hour {} does not exist (0..23)", *hours);
  if (*minutes > 59) return fmt::format("minute {} does not exist (0..59)", *minutes);
  if (seconds > 59) return fmt::format("second {} does not exist (0..59)", seconds);
  seconds_of_day = *hours * 3600 + *minutes * 60 + seconds;
  return {};
}

}  // namespace

std::string point_in_time_literal_problem(std::string_view text) {
  const size_t hash = text.find('#');
  if (hash == std::string_view::npos) return "a '#' is missing";
  std::string prefix;
  for (char c : text.substr(0, hash)) prefix += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  const std::string_view value = text.substr(hash + 1);
  const bool long_variant = prefix.starts_with("L");  // LDATE, LTOD, LDT: 64 bits of ns, up to 2554
  if (long_variant) prefix.erase(0, 1);
  if (prefix == "DATE_AND_TIME") prefix = "DT";
  if (prefix == "TIME_OF_DAY") prefix = "TOD";
  if (prefix == "DATE") prefix = "D";
  size_t pos = 0;
  std::string problem;
  int64_t seconds = 0;
  DateFields date;
  if (prefix == "TOD") {
    problem = read_time_of_day(value, pos, seconds);
  } else {
    problem = read_date(value, pos, date);
    if (problem.empty() && prefix == "DT") {
      if (pos >= value.size() || value[pos++] != '-') return "a date and time is written YYYY-MM-DD-hh:mm:ss";
      problem = read_time_of_day(value, pos, seconds);
    }
  }
  if (!problem.empty()) return problem;
  if (pos != value.size()) return fmt::format("unexpected '{}'", value.substr(pos));
  if (long_variant || prefix == "TOD") return {};
  // DATE and DT count seconds since 1970 in 32 bits: the last one is 2106-02-07-06:28:15 (the
  // CODESYS textbook prints 02-06, one day early: 2^32 - 1 s is 49,710 days and 6:28:15).
  const int64_t total = days_since_epoch(date.year, date.month, date.day) * 86400 + seconds;
  if (total > 0xFFFFFFFFll) {
    return prefix == "DT" ? "beyond DT#2106-02-07-06:28:15, the last point a DT holds (use LDT)"
                          : "beyond D#2106-02-07, the last day a DATE holds (use LDATE)";
  }
  return {};
}

std::optional<std::string> parse_string_literal(std::string_view text, bool* wide) {
  if (text.size() < 2) return std::nullopt;
  const char quote = text.front();
  if ((quote != '\'' && quote != '"') || text.back() != quote) return std::nullopt;
  if (wide) *wide = quote == '"';
  std::string out;
  for (size_t i = 1; i + 1 < text.size(); ++i) {
    const char c = text[i];
    if (c != '$' || i + 2 >= text.size()) {
      out += c;
      continue;
    }
    const char next = text[++i];
    switch (lower(next)) {
      case 'n':
      case 'l':
        out += '\n';
        break;
      case 'r':
        out += '\r';
        break;
      case 't':
        out += '\t';
        break;
      case 'p':
        out += '\f';
        break;
      default:
        if (digit_value(next) < 16 && i + 1 < text.size() - 1 && digit_value(text[i + 1]) < 16) {
          out += static_cast<char>(digit_value(next) * 16 + digit_value(text[i + 1]));
          ++i;
        } else {
          out += next;  // $$ $' $"
        }
    }
  }
  return out;
}

size_t string_length(std::string_view value, bool wide) {
  size_t length = 0;
  for (size_t at = 0; at < value.size();) {
    const source::Utf8Step step = source::decode_utf8_at(value, at);
    length += wide && step.valid ? source::utf16_length(step.code_point) : 1;
    at += step.length;
  }
  return length;
}

std::string string_escape_problem(std::string_view text) {
  if (text.size() < 2) return {};
  // $hh is a byte; a WSTRING's $hhhh starts with two hex digits as well.
  constexpr size_t kHexDigits = 2;
  for (size_t i = 1; i + 1 < text.size(); ++i) {
    if (text[i] != '$') continue;
    const size_t next = i + 1;
    if (next + 1 >= text.size()) return "a '$' at the end of the string escapes nothing (write $$ for a dollar sign)";
    const char c = lower(text[next]);
    if (c == '$' || c == '\'' || c == '"' || c == 'l' || c == 'n' || c == 'p' || c == 'r' || c == 't') {
      i = next;
      continue;
    }
    size_t digits = 0;
    while (digits < kHexDigits && next + digits + 1 < text.size() && digit_value(text[next + digits]) < 16) ++digits;
    if (digits == kHexDigits) {
      i = next + digits - 1;
      continue;
    }
    return fmt::format("'${}' is not an escape: after '$' come $ ' L N P R T or two hex digits", text[next]);
  }
  return {};
}

}  // namespace rung::check
