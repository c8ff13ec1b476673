// Checks of declarations (not bodies): which VAR sections a POU kind may have, RETAIN where it
// is not allowed, initial values against their types, array bounds, enum values, VAR_EXTERNAL
// against VAR_GLOBAL, interfaces a POU claims to implement, instances of abstract blocks.
#pragma once

#include <vector>

#include "checker/project_model.hpp"

namespace rung::check {

// Appends the findings for every declaration of `source` (tree coordinates).
void check_declarations(const ProjectModel& model, SourceId source, std::vector<Diagnostic>& out);

}  // namespace rung::check
