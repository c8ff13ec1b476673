#include "runner/stdlib/datetime.hpp"

#include <fmt/format.h>

#include "checker/constant/const_value.hpp"

namespace rung::run {
namespace {

int64_t unit_per_second(TimeUnit unit) {
  switch (unit) {
    case TimeUnit::Milliseconds: return 1000;
    case TimeUnit::Nanoseconds: return 1'000'000'000;
    case TimeUnit::Seconds: return 1;
  }
  return 1;
}

std::string without_underscores(std::string_view text) {
  std::string out;
  for (char c : text) {
    if (c != '_') out += c;
  }
  return out;
}

std::optional<int64_t> read_number(std::string_view text, size_t& at, size_t max_digits = 10) {
  size_t digits = 0;
  int64_t value = 0;
  while (at < text.size() && text[at] >= '0' && text[at] <= '9' && digits < max_digits) {
    value = value * 10 + (text[at] - '0');
    ++at;
    ++digits;
  }
  if (digits == 0) return std::nullopt;
  return value;
}

std::optional<int64_t> parse_date_at(std::string_view text, size_t& at) {
  auto year = read_number(text, at);
  if (!year || at >= text.size() || text[at++] != '-') return std::nullopt;
  auto month = read_number(text, at);
  if (!month || at >= text.size() || text[at++] != '-') return std::nullopt;
  auto day = read_number(text, at);
  if (!day || *month < 1 || *month > 12 || *day < 1 || *day > 31) return std::nullopt;
  return days_from_civil(*year, static_cast<unsigned>(*month), static_cast<unsigned>(*day));
}

// Nanoseconds since midnight.
std::optional<int64_t> parse_tod_at(std::string_view text, size_t& at) {
  auto hours = read_number(text, at);
  if (!hours || at >= text.size() || text[at++] != ':') return std::nullopt;
  auto minutes = read_number(text, at);
  if (!minutes) return std::nullopt;
  int64_t seconds = 0;
  int64_t fraction_ns = 0;
  if (at < text.size() && text[at] == ':') {
    ++at;
    auto whole = read_number(text, at);
    if (!whole) return std::nullopt;
    seconds = *whole;
    if (at < text.size() && text[at] == '.') {
      ++at;
      int64_t scale = 100'000'000;
      while (at < text.size() && text[at] >= '0' && text[at] <= '9') {
        fraction_ns += (text[at] - '0') * scale;
        scale /= 10;
        ++at;
      }
    }
  }
  if (*hours > 24 || *minutes > 59 || seconds > 60) return std::nullopt;
  return ((*hours * 60 + *minutes) * 60 + seconds) * 1'000'000'000 + fraction_ns;
}

std::optional<int64_t> finish(std::optional<int64_t> nanoseconds, TimeUnit unit) {
  if (!nanoseconds) return std::nullopt;
  return *nanoseconds / (1'000'000'000 / unit_per_second(unit));
}

}  // namespace

int64_t days_from_civil(int64_t year, unsigned month, unsigned day) {
  year -= month <= 2;
  const int64_t era = (year >= 0 ? year : year - 399) / 400;
  const auto yoe = static_cast<unsigned>(year - era * 400);
  const unsigned doy = (153 * (month + (month > 2 ? -3 : 9)) + 2) / 5 + day - 1;
  const unsigned doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
  return era * 146097 + static_cast<int64_t>(doe) - 719468;
}

void civil_from_days(int64_t days, int64_t& year, unsigned& month, unsigned& day) {
  days += 719468;
  const int64_t era = (days >= 0 ? days : days - 146096) / 146097;
  const auto doe = static_cast<unsigned>(days - era * 146097);
  const unsigned yoe = (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365;
  const unsigned doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
  const unsigned mp = (5 * doy + 2) / 153;
  day = doy - (153 * mp + 2) / 5 + 1;
  month = mp < 10 ? mp + 3 : mp - 9;
  year = static_cast<int64_t>(yoe) + era * 400 + (month <= 2);
}

std::optional<int64_t> parse_date_text(std::string_view text, TimeUnit unit) {
  const std::string clean = without_underscores(text);
  size_t at = 0;
  auto days = parse_date_at(clean, at);
  if (!days || at != clean.size()) return std::nullopt;
  return *days * 86400 * unit_per_second(unit);
}

std::optional<int64_t> parse_time_of_day_text(std::string_view text, TimeUnit unit) {
  const std::string clean = without_underscores(text);
  size_t at = 0;
  auto ns = parse_tod_at(clean, at);
  if (!ns || at != clean.size()) return std::nullopt;
  return finish(ns, unit);
}

std::optional<int64_t> parse_date_and_time_text(std::string_view text, TimeUnit unit) {
  const std::string clean = without_underscores(text);
  size_t at = 0;
  auto days = parse_date_at(clean, at);
  if (!days || at >= clean.size() || clean[at++] != '-') return std::nullopt;
  auto ns = parse_tod_at(clean, at);
  if (!ns || at != clean.size()) return std::nullopt;
  return finish(*days * 86400 * int64_t{1'000'000'000} + *ns, unit);
}

std::optional<int64_t> parse_point_literal(std::string_view literal, PointKind kind, TimeUnit unit) {
  const size_t hash = literal.find('#');
  const std::string_view text = hash == std::string_view::npos ? literal : literal.substr(hash + 1);
  switch (kind) {
    case PointKind::Date: return parse_date_text(text, unit);
    case PointKind::TimeOfDay: return parse_time_of_day_text(text, unit);
    case PointKind::DateAndTime: return parse_date_and_time_text(text, unit);
  }
  return std::nullopt;
}

std::string duration_text(int64_t value, TimeUnit unit, bool long_form) {
  const __int128 ns = static_cast<__int128>(value) * (1'000'000'000 / unit_per_second(unit));
  // Whole milliseconds as the checker writes them, then the microseconds and nanoseconds an LTIME
  // holds below them (LTIME#1ms500us, LTIME#600us, LTIME#1us5ns).
  const __int128 magnitude = ns < 0 ? -ns : ns;
  const auto below_ms = static_cast<int64_t>(magnitude % 1'000'000);
  std::string text = check::duration_literal_text(magnitude - below_ms);
  if (below_ms != 0) {
    if (text.ends_with("#0ms")) text.resize(text.size() - 3);
    if (below_ms >= 1000) text += fmt::format("{}us", below_ms / 1000);
    if (below_ms % 1000 != 0) text += fmt::format("{}ns", below_ms % 1000);
  }
  if (ns < 0) text.insert(text.find('#') + 1, "-");
  if (long_form && text.starts_with("T#")) text = "LTIME#" + text.substr(2);
  if (long_form && text.starts_with("-T#")) text = "-LTIME#" + text.substr(3);
  return text;
}

namespace {

std::string date_part(int64_t seconds) {
  int64_t year = 0;
  unsigned month = 0;
  unsigned day = 0;
  civil_from_days(seconds >= 0 ? seconds / 86400 : (seconds - 86399) / 86400, year, month, day);
  return fmt::format("{:04}-{:02}-{:02}", year, month, day);
}

std::string tod_part(int64_t ns_of_day) {
  const int64_t total_seconds = ns_of_day / 1'000'000'000;
  int64_t fraction = ns_of_day % 1'000'000'000;
  std::string text = fmt::format("{:02}:{:02}:{:02}", total_seconds / 3600, (total_seconds / 60) % 60, total_seconds % 60);
  if (fraction != 0) {
    std::string digits = fmt::format("{:09}", fraction);
    while (!digits.empty() && digits.back() == '0') digits.pop_back();
    text += "." + digits;
  }
  return text;
}

int64_t to_ns(int64_t value, TimeUnit unit) { return value * (1'000'000'000 / unit_per_second(unit)); }

}  // namespace

std::string date_text(int64_t value, TimeUnit unit, bool long_form) {
  return (long_form ? "LDATE#" : "D#") + date_part(to_ns(value, unit) / 1'000'000'000);
}

std::string time_of_day_text(int64_t value, TimeUnit unit, bool long_form) {
  return (long_form ? "LTOD#" : "TOD#") + tod_part(to_ns(value, unit) % (int64_t{86400} * 1'000'000'000));
}

std::string date_and_time_text(int64_t value, TimeUnit unit, bool long_form) {
  const int64_t ns = to_ns(value, unit);
  const int64_t day_ns = int64_t{86400} * 1'000'000'000;
  const int64_t seconds = ns / 1'000'000'000;
  int64_t of_day = ns % day_ns;
  if (of_day < 0) of_day += day_ns;
  return (long_form ? "LDT#" : "DT#") + date_part(seconds) + "-" + tod_part(of_day);
}

}  // namespace rung::run
