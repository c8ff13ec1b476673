#include "checker/profile.hpp"

namespace rung::check {

Profile make_profile(project::Profile id) {
  Profile profile;
  profile.id = id;
  switch (id) {
    case project::Profile::Codesys:
    case project::Profile::Twincat:
      break;  // the defaults are CODESYS V3 behaviour; TwinCAT 3 is CODESYS V3 underneath
    case project::Profile::Iec:
      profile.narrowing_is_error = true;
      profile.bits_and_integers_mix = false;
      profile.enums_are_integers = false;
      profile.bit_literals_to_bool = false;
      profile.time_and_integers_mix = false;
      break;
    case project::Profile::Openpcs:
      // OpenPCS (infoteam) follows IEC 61131-3 2nd edition strictly and, unlike CODESYS, gives a
      // PROGRAM no parameters (OpenPCS manual: VAR_INPUT/VAR_OUTPUT only in FUNCTION_BLOCK).
      profile = make_profile(project::Profile::Iec);
      profile.id = id;
      profile.program_parameters = false;
      break;
  }
  return profile;
}

Profile make_profile(const project::ProjectConfig& config) {
  Profile profile = make_profile(config.profile);
  profile.max_string_length = config.max_string_length;
  profile.defines = config.defines;
  return profile;
}

}  // namespace rung::check
