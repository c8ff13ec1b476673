// Values known at compile time: literals, CONSTANT variables, enum values and arithmetic on them.
// Integers are kept in 128 bits so that every ULINT and LINT value and their sums are exact.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace rung::check {

struct ConstValue {
  enum class Kind : uint8_t { Integer, Real, Bool, String, Duration, Date };
  Kind kind = Kind::Integer;
  __int128 integer = 0;  // Integer, Bool (0/1), Duration (nanoseconds), Date (seconds since 1970)
  double real = 0;
  std::string text;  // String (decoded)

  static ConstValue of_integer(__int128 value) { return ConstValue{Kind::Integer, value, 0, {}}; }
  static ConstValue of_real(double value) { return ConstValue{Kind::Real, 0, value, {}}; }
  static ConstValue of_bool(bool value) { return ConstValue{Kind::Bool, value ? 1 : 0, 0, {}}; }
  static ConstValue of_duration(__int128 nanoseconds) { return ConstValue{Kind::Duration, nanoseconds, 0, {}}; }
  bool is_integer() const { return kind == Kind::Integer; }
  bool is_number() const { return kind == Kind::Integer || kind == Kind::Real; }
  double as_real() const { return kind == Kind::Real ? real : static_cast<double>(integer); }
};

std::string to_string(const ConstValue& value);
// A duration in its largest units, as a literal: T#49d17h2m47s295ms (whole milliseconds).
std::string duration_literal_text(__int128 nanoseconds);
std::string int128_to_string(__int128 value);

// Literal text (as the grammar's literal tokens) to a value; nullopt when malformed or too big.
std::optional<__int128> parse_integer_literal(std::string_view text);  // 123, 16#FF, 2#1010_0101
std::optional<double> parse_real_literal(std::string_view text);
// Which unit values a duration literal may have. The defaults are CODESYS's rules (textbook
// L4176-4202): only the smallest of several TIME units is bounded (T#3d29h is normalised, t#5m68s
// is an error), and TIME accepts us and ns like LTIME.
struct DurationRules {
  // Every unit after the first lies in its range (hours 0..23, ...), TIME and LTIME alike:
  // T#25h_15m is valid, T#1d_25h_15m is not (IEC 61131-3, OpenPCS S1013-S1016).
  bool later_units_bounded = false;
  // us and ns in a TIME (not LTIME) literal. CODESYS TIME counts milliseconds and only LTIME has
  // the smaller units (MP300 manual L17797-17852).
  bool sub_millisecond_time = true;
};
// T#1h2m3s4ms, TIME#-5s, LT#1.5d: nanoseconds. `error` says why it is rejected (unit order, ...).
std::optional<__int128> parse_duration_literal(std::string_view text, std::string* error = nullptr,
                                               const DurationRules& rules = {});
// Why a REAL (`single` = 32-bit) or LREAL value cannot be stored; empty when it fits. IEEE 754
// single precision ends at 3.4028235E38 (OpenPCS S1010: exponent -37..38 for REAL).
std::string real_range_problem(double value, bool single);
// What is wrong with a DATE, TIME_OF_DAY or DATE_AND_TIME literal (D#2024-02-30, TOD#45:40:30,
// DT#2106-02-06-06:28:16 beyond the 32-bit range); empty when it is a valid point in time.
std::string point_in_time_literal_problem(std::string_view text);
// '...' or "..." with $-escapes decoded; `wide` for double quotes.
std::optional<std::string> parse_string_literal(std::string_view text, bool* wide = nullptr);
// How many characters a decoded string value holds, as the PLC counts them: a STRING has one
// byte per character in the target's code page, whatever encoding the source file had, so each
// UTF-8 sequence is one character; a WSTRING counts UTF-16 units. A byte that starts no valid
// sequence (a $E4 escape) is one character.
size_t string_length(std::string_view value, bool wide);
// The first '$' escape of a string literal that means nothing ('$Q'), as an error message; empty
// when all are valid: $$ $' $" $L $N $P $R $T (either case) and $hh (OpenPCS S1022).
std::string string_escape_problem(std::string_view text);

}  // namespace rung::check
