// Pragmas that speak to the user: message pragmas ({warning 'text'} E602, {error 'text'} E603,
// {info 'text'} and {text 'text'} E605), pragmas rung cannot interpret (E604) and malformed
// conditional compilation (E606). Code in inactive {IF} branches is blanked before the file is
// read for checking (checker/conditional_sources.hpp), so its messages are not reported.
#pragma once

#include <vector>

#include "checker/project_model.hpp"

namespace rung::check {

// Appends the findings for the pragmas of `source` (tree coordinates), and E601 for every
// declaration whose type is marked {attribute 'obsolete'} (fbinst : fb1, EXTENDS fb1).
void check_pragmas(const ProjectModel& model, SourceId source, std::vector<Diagnostic>& out);

// E601 for a use of `obsolete` (a symbol with {attribute 'obsolete' := 'text'}) at `where`.
Diagnostic obsolete_use(const Symbol& obsolete, TextRange where);

}  // namespace rung::check
