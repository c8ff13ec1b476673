// Points in time and durations as the PLC stores them (CODESYS V3): TIME counts milliseconds in 32
// bits, LTIME nanoseconds in 64; DATE and DATE_AND_TIME count seconds since 1970-01-01 in 32 bits,
// TIME_OF_DAY milliseconds since midnight; LDATE, LTOD and LDT count nanoseconds in 64 bits.
// Conversions between those numbers and IEC literal text, in both directions.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace rung::run {

enum class TimeUnit : uint8_t { Milliseconds, Nanoseconds, Seconds };

int64_t days_from_civil(int64_t year, unsigned month, unsigned day);
void civil_from_days(int64_t days, int64_t& year, unsigned& month, unsigned& day);

// Literal text after the prefix's '#' ("2024-01-31", "12:30:15.25", "2024-01-31-12:30:15"); the
// value in `unit`; nullopt when malformed.
std::optional<int64_t> parse_date_text(std::string_view text, TimeUnit unit);
std::optional<int64_t> parse_time_of_day_text(std::string_view text, TimeUnit unit);
std::optional<int64_t> parse_date_and_time_text(std::string_view text, TimeUnit unit);
// A whole literal: D#..., TOD#..., DT#... (and long forms), with `_` separators.
enum class PointKind : uint8_t { Date, TimeOfDay, DateAndTime };
std::optional<int64_t> parse_point_literal(std::string_view literal, PointKind kind, TimeUnit unit);

// IEC literal text of stored values: T#1h2m3s4ms, LTIME#1us, D#2024-01-31, TOD#12:30:15.25,
// DT#2024-01-31-12:30:15.
std::string duration_text(int64_t value, TimeUnit unit, bool long_form);
std::string date_text(int64_t value, TimeUnit unit, bool long_form);
std::string time_of_day_text(int64_t value, TimeUnit unit, bool long_form);
std::string date_and_time_text(int64_t value, TimeUnit unit, bool long_form);

}  // namespace rung::run
