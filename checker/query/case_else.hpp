// "Add ELSE to CASE": the fix of lint rule L030 (case-without-else), also offered on any CASE
// without ELSE under the cursor. The ELSE goes right before END_CASE, indented like the CASE's
// labels, with a comment line where the branch's statements go (an ELSE that says nothing about
// why it is empty would be L032's next finding).
#pragma once

#include <optional>

#include "checker/lint/lint_rule.hpp"
#include "checker/project/format_settings.hpp"
#include "parser/document.hpp"

namespace rung::check::query {

// The CASE statement (without syntax errors) innermost around `tree_offset`; null if none.
SyntaxNode case_statement_at(const Document& document, uint32_t tree_offset);

// The edit (FILE coordinates) that adds an ELSE branch to `case_statement`; nullopt when it has
// one already, or the place cannot be edited in the file.
std::optional<lint::TextEdit> add_case_else(const Document& document, SyntaxNode case_statement,
                                            const project::FormatSettings& settings);

}  // namespace rung::check::query
