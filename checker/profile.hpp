// The semantics profile: every place where CODESYS, TwinCAT and the IEC standard disagree at
// compile time is one field of this table. The checker reads only this table (never the profile
// name), so a new dialect is a new row. The runner reads the same table for run-time choices.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <string_view>

#include "checker/project/project_config.hpp"

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
  // The literals 0 and 1 assign to BOOL (CODESYS types them as BIT).
  bool bit_literals_to_bool = true;
  // A PROGRAM may declare VAR_INPUT / VAR_OUTPUT / VAR_IN_OUT (CODESYS, TwinCAT, IEC); OpenPCS not.
  bool program_parameters = true;
  // TIME and integers convert implicitly (CODESYS 2.3 heritage: TIME is a DWORD of ms).
  bool time_and_integers_mix = true;
  // Target: longest STRING(n) and the length of STRING without (n).
  uint32_t max_string_length = 255;
  uint32_t default_string_length = 80;
  // {IF defined(NAME)} symbols.
  std::map<std::string, std::string> defines;
};

Profile make_profile(project::Profile id);
Profile make_profile(const project::ProjectConfig& config);

}  // namespace rung::check
