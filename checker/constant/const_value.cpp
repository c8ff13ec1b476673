#include "checker/constant/const_value.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cstdlib>

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

std::optional<__int128> parse_duration_literal(std::string_view text, std::string* error) {
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
  long double total = 0;
  int last_unit = -1;
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
    last_unit = unit_index;
    total += std::strtold(number.c_str(), nullptr) * kUnits[static_cast<size_t>(unit_index)].second;
    any = true;
  }
  if (!any) return std::nullopt;
  const __int128 nanoseconds = static_cast<__int128>(total + 0.5L);
  return negative ? -nanoseconds : nanoseconds;
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

}  // namespace rung::check
