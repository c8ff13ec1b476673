#include "checker/profile.hpp"

namespace rung::check {

Profile make_profile(project::Profile id) {
  Profile profile;
  profile.id = id;
  switch (id) {
    case project::Profile::Codesys:
      // TIME counts milliseconds; us and ns need LTIME (MP300 manual L17797-17852).
      profile.duration_rules.sub_millisecond_time = false;
      break;  // the other defaults are CODESYS V3 behaviour
    case project::Profile::Twincat:
      // TwinCAT 3 is CODESYS V3 underneath; its task priorities are not CODESYS's 0..31 and no
      // manual rung follows gives their range.
      profile.max_task_priority = 0;
      profile.duration_rules.sub_millisecond_time = false;
      break;
    case project::Profile::Iec:
      profile.narrowing_is_error = true;
      profile.bits_and_integers_mix = false;
      profile.enums_are_integers = false;
      profile.enum_values_typed_by_context = true;
      profile.bit_literals_to_bool = false;
      profile.time_and_integers_mix = false;
      profile.address_size_mismatch_is_error = true;
      profile.freewheeling_tasks = false;
      profile.max_task_priority = 0;
      profile.program_globals = true;
      profile.located_retain = true;
      profile.external_initial_values = false;
      profile.retain_in_functions_is_error = true;
      profile.located_block_locals_are_error = true;
      profile.constant_parameters = false;
      profile.instances_in_functions = false;
      profile.generic_parameters = false;
      profile.bit_string_arithmetic = false;
      profile.short_circuit_logic = true;
      profile.integer_promotion = false;
      // IEC 61131-3 3rd edition: only the first unit of a duration may overflow; TIME and LTIME
      // both take us and ns.
      profile.duration_rules.later_units_bounded = true;
      break;
    case project::Profile::Openpcs:
      // OpenPCS (infoteam) follows IEC 61131-3 2nd edition strictly and, unlike CODESYS, gives a
      // PROGRAM no parameters (OpenPCS manual: VAR_INPUT/VAR_OUTPUT only in FUNCTION_BLOCK).
      profile = make_profile(project::Profile::Iec);
      profile.id = id;
      profile.program_parameters = false;
      profile.generic_arguments_widen = false;
      profile.call_input_instances = false;
      profile.formal_arguments_in_order = true;
      profile.string_positions_are_uint = true;
      profile.il_extensible_two_inputs = true;
      // `%QW1.0` is the output word starting at the second output byte (OpenPCS manual L7091).
      profile.addressing = AddressingMode::ByteOffset;
      profile.compound_types_at_addresses = false;
      profile.located_retain = false;
      profile.located_initial_values = false;
      profile.located_constants = false;
      profile.constant_externals = false;
      profile.retain_inputs = false;
      profile.qualified_instances = false;
      profile.instances_in_data = false;
      profile.function_outputs_and_externals = false;
      profile.function_needs_input = true;
      profile.function_result_defaults_to_bool = true;
      profile.en_eno_rules = true;
      profile.literal_initial_values_only = true;
      profile.unique_names = true;
      profile.step_names_start_with_letter = true;
      profile.max_step_name_length = 31;
      // STRING without a length holds 32 characters, STRING(n) at most 253 (L4363-4389, C10049).
      profile.default_string_length = 32;
      profile.max_string_length = 253;
      // IEC 2nd edition TIME: d, h, m, s, ms, 32 signed bits of milliseconds (L4440-4450, C10108).
      profile.duration_rules.sub_millisecond_time = false;
      profile.max_time_milliseconds = 0x7FFFFFFFll;
      // Appendix D and the error lists (L11264-11269, L5860-5872, L12081-12086, L14240-14254,
      // L14451-14501).
      profile.max_identifier_length = 64;
      profile.max_array_dimensions = 6;
      profile.max_names_per_declaration = 60;
      profile.array_bound_limit = 32767;
      profile.nested_calls = false;
      break;
  }
  return profile;
}

Profile make_profile(const project::ProjectConfig& config) {
  Profile profile = make_profile(config.profile);
  // rung.toml's [target] max_string_length overrides the profile's limit only when it is set.
  if (config.max_string_length != project::ProjectConfig{}.max_string_length) {
    profile.max_string_length = config.max_string_length;
  }
  if (config.addressing == "byte") profile.addressing = AddressingMode::Byte;
  if (config.addressing == "word") profile.addressing = AddressingMode::Word;
  if (config.addressing == "byte-offset") profile.addressing = AddressingMode::ByteOffset;
  profile.defines = config.defines;
  return profile;
}

}  // namespace rung::check
