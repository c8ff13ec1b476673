// Which tokens the formatter may write in another letter case, and how: keywords (IF, END_VAR,
// AND, TRUE, the IL operators LD/ST/JMPC...) and, when the settings say so, the elementary type
// names in type positions (BOOL, INT, TIME, INT#5). Identifiers keep their spelling. The safety
// check uses the same classes to compare those tokens without case.
#pragma once

#include <string>
#include <string_view>

#include "checker/project/format_settings.hpp"
#include "formatter/syntax_kinds.hpp"

namespace rung::format {

enum class CaseClass : uint8_t { None, Keyword, ElementaryType };

// Where a leaf stands: its parent's kind, whether it is the parent's first child, and whether it
// is the parent's only child (a type_name of one identifier, not Lib.INT).
struct LeafPlace {
  NodeKind parent = NodeKind::Other;
  bool first_child = false;
  bool only_child = false;
};

CaseClass case_class(const SymbolInfo& leaf, LeafPlace place, std::string_view text);

// Appends `text` in the case the settings ask for `cls` (unchanged for CaseClass::None).
void append_in_case(std::string& out, std::string_view text, CaseClass cls, const project::FormatSettings& settings);

// ASCII case-insensitive equality (keywords and type names are ASCII).
bool equal_ignoring_case(std::string_view a, std::string_view b);

}  // namespace rung::format
