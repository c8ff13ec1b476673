// Checks of initial values in declarations: that their shape fits the type (a structure value for
// a STRUCT, an array value for an ARRAY and no more elements than it has), that every value fits
// its element or member, that a member is initialised once, and the per-vendor limits on what an
// initial value may be (OpenPCS: literals and enum values only, none on VAR_EXTERNAL or AT
// variables).
#pragma once

#include <vector>

#include "checker/project_model.hpp"

namespace rung::check {

// The initial value of `variable` (declared in `owner`: a POU, global list or STRUCT).
void check_initial_value(const ProjectModel& model, const Symbol& owner, const Symbol& variable,
                         std::vector<Diagnostic>& out);

// The initial value of a data type: `END_STRUCT := (m1 := 4)`, `TYPE T : INT := 5`, an enum's default.
void check_type_initializer(const ProjectModel& model, const Symbol& type_symbol, std::vector<Diagnostic>& out);

}  // namespace rung::check
