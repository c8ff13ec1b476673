// Checks of declared names against each other beyond one scope (the collector reports a name
// declared twice in one scope): POUs and types of one file with the same name, a variable named
// like a POU or type, a local with the name of a global (per profile), a variable that redeclares
// an inherited one, an enumerator defined by two enumerations of one POU.
#pragma once

#include <vector>

#include "checker/project_model.hpp"

namespace rung::check {

// Appends the findings for the declarations of `source` (tree coordinates).
void check_names(const ProjectModel& model, SourceId source, std::vector<Diagnostic>& out);

}  // namespace rung::check
