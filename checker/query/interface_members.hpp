// "Implement missing interface members": the fix of E204. A FUNCTION_BLOCK that IMPLEMENTS an
// interface must have each of the interface's methods and properties (its base interfaces'
// too, inherited ones count: the rule of the declaration checker). The skeletons are the
// interface's own declarations, copied with their signatures, VAR blocks and comments (the doc
// comment above each member too), and inserted before END_FUNCTION_BLOCK (or after the block's
// last member when the file writes members after the block, the CODESYS object shape).
#pragma once

#include <optional>
#include <vector>

#include "checker/check.hpp"
#include "checker/lint/lint_rule.hpp"
#include "checker/project/format_settings.hpp"

namespace rung::check::query {

struct MissingMembers {
  const Symbol* interface = nullptr;    // as named in IMPLEMENTS
  std::vector<const Symbol*> members;   // its methods and properties the block lacks, in order
};

// Per interface `block` implements: the members it lacks (interfaces with none left out).
std::vector<MissingMembers> missing_interface_members(const ProjectModel& model, const Symbol& block);

// The edit (FILE coordinates of the block's file) inserting `members` into `block`; nullopt when
// the place cannot be edited (a TwinCAT .TcPOU keeps each method in an XML element of its own).
std::optional<lint::TextEdit> implement_members(const Workspace& workspace, const Symbol& block,
                                                const std::vector<const Symbol*>& members,
                                                const project::FormatSettings& settings);

}  // namespace rung::check::query
