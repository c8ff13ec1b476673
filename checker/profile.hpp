// The semantics profile: every place where CODESYS, TwinCAT and the IEC standard disagree at
// compile time is one field of this table. The checker reads only this table (never the profile
// name), so a new dialect is a new row. The runner reads the same table for run-time choices.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <string_view>

#include "checker/constant/const_value.hpp"
#include "checker/project/project_config.hpp"
#include "checker/semantic/direct_address.hpp"

namespace rung::check {

struct Profile {
  project::Profile id = project::Profile::Codesys;
  // Implicit conversions that may lose data (DINT into INT, REAL into INT, signed into
  // unsigned): CODESYS and TwinCAT compile them with a warning, the IEC standard forbids them.
  bool narrowing_is_error = false;
  // Integer and bit-string types mix implicitly (WORD := INT): CODESYS yes, IEC no.
  bool bits_and_integers_mix = true;
  // Integers assign to enum variables and enums take part in arithmetic (CODESYS V3 without
  // {attribute 'strict'}); IEC enums are closed.
  bool enums_are_integers = true;
  // A bare enum value name that two enumerations define is resolved by the type its context
  // expects (IEC, MatIEC: `colorvar := blue` picks the enum of colorvar). CODESYS and TwinCAT
  // reject it even there (MP300 manual L14551-14561): only COLORS_1.blue is unambiguous.
  bool enum_values_typed_by_context = false;
  // + - * / on bit strings (WORD - 3): CODESYS and TwinCAT compute them like unsigned integers;
  // IEC keeps bit strings out of arithmetic (OpenPCS S3035 "numeric, date or time operand").
  bool bit_string_arithmetic = true;
  // The literals 0 and 1 assign to BOOL (CODESYS types them as BIT).
  bool bit_literals_to_bool = true;
  // A PROGRAM may declare VAR_INPUT / VAR_OUTPUT / VAR_IN_OUT (CODESYS, TwinCAT, IEC); OpenPCS not.
  bool program_parameters = true;
  // TIME and integers convert implicitly (CODESYS 2.3 heritage: TIME is a DWORD of ms).
  bool time_and_integers_mix = true;
  // Arguments of a generic standard function may be of different types that widen to one
  // (MAX(INT, REAL), LN(INT)): CODESYS, TwinCAT, IEC 3rd ed. OpenPCS binds T to one type, and an
  // integer constant adapts only to integer and bit types (S5024 LD 1 / LN, S5027 LD 1 / MAX r).
  bool generic_arguments_widen = true;
  // --- Calls (semantic/call_checker.cpp) --------------------------------------------------
  // Formal arguments follow the callee's declaration order: OpenPCS translates an ST call to IL
  // without the declaration and gets the order wrong otherwise (S3047). Elsewhere any order.
  bool formal_arguments_in_order = false;
  // The length and position inputs of LEFT, RIGHT and MID are UINT, not any integer (OpenPCS
  // C10035, L14045-14068, although its reference pages say ANY_INT).
  bool string_positions_are_uint = false;
  // OpenPCS: in IL an extensible function (ADD, MAX, ...) takes the current result and one
  // operand; more inputs need LD/FBD or ST.
  bool il_extensible_two_inputs = false;
  // A function block may call an instance it received as VAR_INPUT: not in OpenPCS (S5029).
  bool call_input_instances = true;
  // How the numbers of %I/%Q/%M addresses map to bytes: CODESYS V3 counts units of the address's
  // size (%MW1 = bytes 2..3), OpenPCS byte offsets (%QW1.0 starts at output byte 1).
  AddressingMode addressing = AddressingMode::Byte;
  // An elementary type of another size at a byte/word/dword address (a DINT AT %MW2): CODESYS
  // reads the address as the start (AK800 manual L1200), so only a warning; IEC/OpenPCS: error.
  bool address_size_mismatch_is_error = false;
  // ARRAY/STRUCT/STRING AT an address: CODESYS yes (start address), OpenPCS no (L10030).
  bool compound_types_at_addresses = true;
  // A TASK without INTERVAL or SINGLE: CODESYS/TwinCAT run it freewheeling; IEC never starts it.
  bool freewheeling_tasks = true;
  // Highest TASK PRIORITY (0 is the highest priority); 0 means the manuals give no limit.
  uint32_t max_task_priority = 31;
  // --- Declaration rules (semantic/declaration_checker.cpp) ---------------------------------
  // A PROGRAM may declare VAR_GLOBAL (IEC, OpenPCS S4017); CODESYS only in global variable lists.
  bool program_globals = false;
  // RETAIN/PERSISTENT in a FUNCTION or METHOD: CODESYS accepts it without effect (a warning);
  // IEC and OpenPCS (S4019) refuse it.
  bool retain_in_functions_is_error = false;
  // A FUNCTION_BLOCK or FUNCTION local AT a complete address: CODESYS lets every instance share
  // it (a warning); IEC and OpenPCS (S4011, C10019) allow AT only in programs and global lists.
  bool located_block_locals_are_error = false;
  // An AT variable in a RETAIN block: the IEC grammar allows it; CODESYS (MP300 manual L10830)
  // and OpenPCS (L10033) keep located variables in the process image, never in retain memory.
  bool located_retain = false;
  // An initial value on a VAR_EXTERNAL: the CODESYS manuals show one (MP300 L11151-11299, it has
  // no effect); the IEC grammar has none and OpenPCS refuses it (S4024).
  bool external_initial_values = true;
  // An initial value or CONSTANT on an AT variable: not in OpenPCS (L10031, L10034).
  bool located_initial_values = true;
  bool located_constants = true;
  // VAR_INPUT / VAR_IN_OUT CONSTANT (CODESYS); the IEC grammar has CONSTANT only on VAR,
  // VAR_GLOBAL and VAR_EXTERNAL, and never together with RETAIN.
  bool constant_parameters = true;
  // VAR_EXTERNAL CONSTANT (IEC, CODESYS); OpenPCS allows CONSTANT only on VAR and VAR_GLOBAL (S4018).
  bool constant_externals = true;
  // VAR_INPUT RETAIN (IEC, CODESYS); OpenPCS: RETAIN only on VAR, VAR_OUTPUT, VAR_GLOBAL (S4019).
  bool retain_inputs = true;
  // FB instances in VAR CONSTANT or VAR RETAIN blocks: not in OpenPCS (S5003, S5042).
  bool qualified_instances = true;
  // FB instances in a FUNCTION's variables: CODESYS yes; IEC no (a function has no state, S5004).
  bool instances_in_functions = true;
  // FB instances as STRUCT members, ARRAY elements or a FUNCTION's result: not in OpenPCS
  // (S5004, S5011, S5005).
  bool instances_in_data = true;
  // VAR_OUTPUT, VAR_IN_OUT and VAR_EXTERNAL in a FUNCTION: not in OpenPCS (S4014-S4016).
  bool function_outputs_and_externals = true;
  // A FUNCTION needs at least one VAR_INPUT (OpenPCS S4036).
  bool function_needs_input = false;
  // A FUNCTION without a result type returns BOOL (OpenPCS L8698); elsewhere it returns nothing.
  bool function_result_defaults_to_bool = false;
  // EN and ENO are the IEC enable input/output: EN only a BOOL VAR_INPUT, ENO only a BOOL
  // VAR_OUTPUT, neither RETAIN, no ENO without EN (OpenPCS S1031, S1032, S3041, S3042).
  bool en_eno_rules = false;
  // Initial values must be literals or enum values, not constants or variables (OpenPCS S5043).
  bool literal_initial_values_only = false;
  // One namespace for POUs, types and variables: a variable may not be named like a POU, a type
  // or a global variable (OpenPCS S3046, linker L10001). CODESYS lets locals shadow them.
  bool unique_names = false;
  // Generic types (ANY_INT, ...) as parameter types of a user FUNCTION (CODESYS allows ANY and
  // ANY_<type> inputs; IEC and OpenPCS S5035 keep them for standard functions).
  bool generic_parameters = true;
  // --- SFC (semantic/sfc_checker.cpp) -----------------------------------------------------
  // Step names begin with a letter a-z and go on with letters, digits and '_' (OpenPCS
  // L2500-2506: `_Step1` is not a step name); 0 = any identifier, else at most this many characters.
  bool step_names_start_with_letter = false;
  uint32_t max_step_name_length = 0;
  // --- Literals (semantic/expression_typer.cpp) ---------------------------------------------
  // Duration literal units (T#1d_25h_15m, T#3us): see DurationRules in constant/const_value.hpp.
  DurationRules duration_rules;
  // The largest TIME in milliseconds: CODESYS counts 32 unsigned bits (T#49d17h2m47s295ms,
  // textbook L4659), OpenPCS 32 signed bits (+/- 24.85 days, L5849-5851, C10108).
  int64_t max_time_milliseconds = 0xFFFFFFFFll;
  // --- Implementation limits (semantic/limits_checker.cpp, E704); 0 = no limit ---------------
  // Significant characters of an identifier (OpenPCS S1028: 64).
  uint32_t max_identifier_length = 0;
  // Subscripts of one ARRAY[...] (OpenPCS Appendix D: 6).
  uint32_t max_array_dimensions = 0;
  // Names in one declaration `a, b, c : INT;` (OpenPCS S4001: 60).
  uint32_t max_names_per_declaration = 0;
  // Array bounds lie in -limit..limit (OpenPCS C10076/C10077: 32767).
  uint32_t array_bound_limit = 0;
  // A call as an argument of another call, MAX(ABS(x), 3): not in OpenPCS (C10110).
  bool nested_calls = true;
  // Target: longest STRING(n) and the length of STRING without (n).
  uint32_t max_string_length = 255;
  uint32_t default_string_length = 80;
  // --- Run-time behaviour (runner/) --------------------------------------------------------
  // REAL_TO_INT and friends on a .5 tie: CODESYS and OpenPCS round half away from zero
  // (2.5 -> 3, -2.5 -> -3; CODESYS V3 textbook, conversion operators); MatIEC and 4diac round
  // half to even. 0 = half away from zero, 1 = half to even (runner RoundRule).
  uint32_t real_to_int_rounding = 0;
  // Negative REAL to an unsigned type: keep the two's complement bits (CODESYS on x86, 4diac)
  // or clamp to 0 (MatIEC).
  bool negative_real_to_unsigned_clamps = false;
  // AND / OR on BOOL evaluate both operands (CODESYS, TwinCAT: only AND_THEN / OR_ELSE
  // short-circuit); strict IEC leaves it to the implementation, rung's iec profile short-circuits.
  bool short_circuit_logic = false;
  // Arithmetic on integers narrower than 32 bits is computed in 32 bits, like the registers of
  // CODESYS's code generator: INT + INT assigned to a DINT keeps 40000 instead of wrapping at
  // 16 bits. IEC: the operation's type is the operands' type and wraps there.
  bool integer_promotion = true;
  // {IF defined(NAME)} symbols.
  std::map<std::string, std::string> defines;
};

Profile make_profile(project::Profile id);
Profile make_profile(const project::ProjectConfig& config);

}  // namespace rung::check
