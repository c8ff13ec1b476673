// Built-ins implemented in C++ that the compiled code calls with NATIVE: the string functions
// (on the PLC's fixed-capacity strings in VM memory), numeric functions, conversions to and from
// text, and the clock. Each pops its arguments from the machine's value stack and pushes its
// result; functions that return a string write it to a destination address the caller pushed
// first (in.b = the destination's capacity in characters).
#pragma once

#include "runner/vm/machine.hpp"

namespace rung::run {

// What a value conversion to or from text reads or writes (NATIVE aux).
enum class TextKind : uint16_t {
  Signed,
  Unsigned,
  Real,
  LReal,
  Bool,
  Time,
  LTime,
  Date,
  TimeOfDay,
  DateAndTime,
  LDate,
  LTimeOfDay,
  LDateAndTime,
  Byte,  // bit strings print as numbers, like unsigned integers
};

void native_string_compare(Machine& machine, const Instr& in);
void native_wstring_compare(Machine& machine, const Instr& in);
void native_expt_lreal(Machine& machine, const Instr& in);

// Strings: (dst, args...) -> dst
void native_len(Machine& machine, const Instr& in);
void native_left(Machine& machine, const Instr& in);
void native_right(Machine& machine, const Instr& in);
void native_mid(Machine& machine, const Instr& in);
void native_concat(Machine& machine, const Instr& in);
void native_insert(Machine& machine, const Instr& in);
void native_delete(Machine& machine, const Instr& in);
void native_replace(Machine& machine, const Instr& in);
void native_find(Machine& machine, const Instr& in);
void native_wlen(Machine& machine, const Instr& in);
void native_wleft(Machine& machine, const Instr& in);
void native_wright(Machine& machine, const Instr& in);
void native_wmid(Machine& machine, const Instr& in);
void native_wconcat(Machine& machine, const Instr& in);
void native_winsert(Machine& machine, const Instr& in);
void native_wdelete(Machine& machine, const Instr& in);
void native_wreplace(Machine& machine, const Instr& in);
void native_wfind(Machine& machine, const Instr& in);
void native_string_to_wstring(Machine& machine, const Instr& in);
void native_wstring_to_string(Machine& machine, const Instr& in);

// Numeric functions on LREAL.
void native_sqrt(Machine& machine, const Instr& in);
void native_ln(Machine& machine, const Instr& in);
void native_log(Machine& machine, const Instr& in);
void native_exp(Machine& machine, const Instr& in);
void native_sin(Machine& machine, const Instr& in);
void native_cos(Machine& machine, const Instr& in);
void native_tan(Machine& machine, const Instr& in);
void native_asin(Machine& machine, const Instr& in);
void native_acos(Machine& machine, const Instr& in);
void native_atan(Machine& machine, const Instr& in);
void native_atan2(Machine& machine, const Instr& in);
void native_trunc_lreal(Machine& machine, const Instr& in);

// Text conversions: (dst, value) -> dst with aux = TextKind of the value; (src) -> value.
void native_to_string(Machine& machine, const Instr& in);
void native_to_wstring(Machine& machine, const Instr& in);
void native_string_to(Machine& machine, const Instr& in);
void native_wstring_to(Machine& machine, const Instr& in);

// BCD: (value) -> value, aux = width in bits.
void native_to_bcd(Machine& machine, const Instr& in);
void native_from_bcd(Machine& machine, const Instr& in);

// The clock: TIME() in milliseconds, LTIME() in nanoseconds since the start.
void native_time_ms(Machine& machine, const Instr& in);
void native_time_ns(Machine& machine, const Instr& in);

// CONCAT_DATE (year, month, day), CONCAT_TOD (hour, minute, second, millisecond), CONCAT_DT (the
// seven) -> the stored count (DATE/DT seconds since 1970, TOD milliseconds); aux = DateField.
enum class DateField : uint16_t { Date, TimeOfDay, DateAndTime };
void native_concat_date_time(Machine& machine, const Instr& in);

// __NEW (bytes) -> address, __DELETE (address) -> nothing.
void native_new(Machine& machine, const Instr& in);
void native_delete_block(Machine& machine, const Instr& in);

}  // namespace rung::run
