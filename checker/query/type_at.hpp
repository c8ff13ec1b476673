// Hover: the type of the expression under the cursor, as the body checker types it.
#pragma once

#include "checker/check.hpp"

namespace rung::check::query {

// The type of the expression at `file_offset` (FILE coordinates of `source`): a name, obj.member,
// a literal, or the smallest expression around an operator. On a declaration's name, a type name
// or a named argument: the type of the symbol it names. Nullptr where there is no expression
// (keywords, comments, statements as a whole).
const Type* type_at(const Workspace& workspace, SourceId source, uint32_t file_offset);

}  // namespace rung::check::query
