// Find references: every place in the project where a name refers to a given symbol — in
// bodies, declarations' types, initial values, EXTENDS / IMPLEMENTS, configurations, named
// arguments and qualified names (GVL.x, E.v, E#v).
#pragma once

#include <vector>

#include "checker/check.hpp"
#include "checker/query/location.hpp"

namespace rung::check::query {

// Searches the project files (and the stub libraries too when `symbol` is declared in one). Each
// identifier spelled like the symbol's name (case-insensitively) is resolved exactly as
// symbol_at would resolve it there, so a local that hides a global is no reference of the
// global. Sorted by path and offset; `include_declaration` adds the declaring name itself.
std::vector<Location> find_references(const Workspace& workspace, const Symbol* symbol, bool include_declaration);

// The same in one file only (document highlight), sorted by offset.
std::vector<Location> find_references_in(const Workspace& workspace, const Symbol* symbol, SourceId source,
                                         bool include_declaration);

}  // namespace rung::check::query
