// From a position an editor sends (a file and a byte offset in FILE coordinates) to what the
// semantic model knows there: the offset in the parsed text, the name token under the cursor and
// the innermost scope (POU, method, action, property accessor, global list, data type,
// configuration) whose names are visible at that point.
#pragma once

#include <optional>

#include "checker/check.hpp"

namespace rung::check::query {

struct QueryPoint {
  SourceId source = kNoSource;
  uint32_t tree_offset = 0;
  SyntaxNode node;                // the innermost named node at the offset
  SyntaxNode name;                // the identifier under (or right before) the cursor; null if none
  const Symbol* scope = nullptr;  // null outside every declaration
};

// Nullopt where the file has no parsed text (XML markup of a container, an unparsed file) or the
// source does not exist.
std::optional<QueryPoint> query_point(const ProjectModel& model, SourceId source, uint32_t file_offset);
std::optional<QueryPoint> query_point(const Workspace& workspace, SourceId source, uint32_t file_offset);

// The identifier (or IL operator name) at `tree_offset`, or the one ending there: an editor's
// cursor right after a name still means that name. Null otherwise.
SyntaxNode name_at(SyntaxNode root, uint32_t tree_offset);

// The innermost declaration around `tree_offset` whose names are in scope there.
const Symbol* scope_at(const ProjectModel& model, SourceId source, uint32_t tree_offset);

}  // namespace rung::check::query
