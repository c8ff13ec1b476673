// Typing an expression the user is still writing. Completion after `a.b[i].` and signature help
// inside `obj.M(` need the type of the text before the '.' or '(' while the statement around it
// does not parse yet; error recovery may have torn that text apart in the file's tree.
#pragma once

#include "checker/project_model.hpp"
#include "checker/semantic/body_checker.hpp"

namespace rung::check::query {

// The checker's typing (BodyChecker::type_of) of the expression written at `range` (tree
// coordinates of `source`), read in `scope`: the node of the file's tree that spans exactly that
// range when there is one, else the text parsed again on its own. Unknown type when it is no
// expression.
ExprInfo type_written_expression(const ProjectModel& model, SourceId source, const Symbol& scope, TextRange range);

}  // namespace rung::check::query
