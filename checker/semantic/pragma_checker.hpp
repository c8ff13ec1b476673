// Pragmas that speak to the user: message pragmas ({warning 'text'} E602, {error 'text'} E603,
// {info 'text'} and {text 'text'} E605), pragmas rung cannot interpret (E604) and malformed
// conditional compilation (E606). Code in inactive {IF} branches is blanked before the file is
// read for checking (checker/conditional_sources.hpp), so its messages are not reported.
#pragma once

#include <vector>

#include "checker/project_model.hpp"

namespace rung::check {

// Appends the findings for the pragmas of `source` (tree coordinates).
void check_pragmas(const ProjectModel& model, SourceId source, std::vector<Diagnostic>& out);

}  // namespace rung::check
