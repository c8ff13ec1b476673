// Go to definition: the declaration a name under the cursor refers to, in context (a local or
// global variable, a POU or type in a declaration, a member after '.', an enum value E.v or E#v,
// a named argument's parameter, GVL.x, Lib.F, THIS^.x and SUPER^.x).
#pragma once

#include <optional>

#include "checker/check.hpp"
#include "checker/query/location.hpp"

namespace rung::check::query {

// The symbol the name at `file_offset` (FILE coordinates of `source`) refers to; nullptr where
// there is no name, or it refers to nothing rung knows (a builtin, an undeclared name).
const Symbol* symbol_at(const Workspace& workspace, SourceId source, uint32_t file_offset);

// Where that symbol is declared.
std::optional<Location> definition_at(const Workspace& workspace, SourceId source, uint32_t file_offset);

Location declaration_location(const Workspace& workspace, const Symbol& symbol);

}  // namespace rung::check::query
