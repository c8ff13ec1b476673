// Rename: whether the name under the cursor may be renamed, and the edits that rename it in every
// file of the project (containers included), or why not.
//
// Refused: keywords, literals, comments, XML markup, names the compilers know (SIZEOF), labels,
// tasks and steps, undeclared names, names declared in the stub libraries (TON, LIMIT: renaming
// them would break every program that uses them), and names not written in the code (a plain
// file's global variable list is named after its file). A new name must be an IEC 61131-3
// identifier that is no keyword and not visible already where the symbol is declared or used.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "checker/check.hpp"
#include "checker/query/location.hpp"

namespace rung::check::query {

struct RenameTarget {
  const Symbol* symbol = nullptr;  // what would be renamed (a VAR_EXTERNAL stands for its global)
  Location name;                   // the name under the cursor, FILE coordinates
  std::string placeholder;         // that name as written there
  std::string refusal;             // non-empty (and symbol null): why it cannot be renamed
};

RenameTarget rename_target(const Workspace& workspace, SourceId source, uint32_t file_offset);

struct TextEdit {
  Location location;  // FILE coordinates
  std::string new_text;
};

struct RenamePlan {
  std::vector<TextEdit> edits;  // by path, then offset; none overlap
  std::string refusal;          // non-empty: nothing may be changed, and why
};

// Renames `symbol` and, for a method or property, the members it implements or overrides and
// those that implement or override it (query::member_family), everywhere they are named.
RenamePlan plan_rename(const Workspace& workspace, const Symbol& symbol, std::string_view new_name);

// Why `name` cannot be a declared name ("" when it can): not an identifier, two '_' in a row, a
// keyword.
std::string identifier_problem(std::string_view name);

}  // namespace rung::check::query
