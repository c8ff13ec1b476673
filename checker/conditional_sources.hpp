// Conditional compilation applied to a loaded project: each project file's {IF} conditions are
// evaluated against rung.toml's defines and the project's own declarations (ProjectModel), and the
// file is read again with its inactive branches blanked (project/conditional_compilation.hpp).
//
// Conditions such as defined(variable: x) need the project's symbols, which need the files read
// first. So the files are read as written, linked, and the conditions evaluated; the rewritten
// files are linked again and the conditions evaluated once more, because a name a condition asks
// about may itself sit in a branch that turned out inactive. This repeats until nothing changes,
// at most kMaxConditionalRounds times: a condition about a name declared only in its own branch
// ({IF NOT defined(variable: x)} x : INT; {END_IF}) has no stable answer, and the last round wins.
#pragma once

#include <vector>

#include "checker/project_model.hpp"

namespace rung::check {

inline constexpr int kMaxConditionalRounds = 4;

// Rewrites the project files (not libraries) whose conditional pragmas leave code out, and links
// the model again if any changed. Returns the ids of the files whose text changed.
std::vector<SourceId> compile_conditionally(ProjectModel& model);

}  // namespace rung::check
