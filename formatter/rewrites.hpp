// The token changes `rung fmt` may make besides whitespace and letter case, each one a no-op for
// the program: the ';' after END_IF/END_CASE/END_FOR/END_WHILE/END_REPEAT (an empty statement)
// added or removed, and ELSE IF c THEN .. END_IF END_IF merged into ELSIF c THEN .. END_IF where
// the inner IF is the whole ELSE branch. The formatter plans them on the input's tree; the safety
// check validates each one on that tree again before it accepts the changed token stream.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "checker/project/format_settings.hpp"
#include "parser/syntax_tree.hpp"

namespace rung::format {

struct Rewrite {
  enum class Kind {
    AddSemicolon,     // `at`: the END_ keyword after which a ';' is added
    RemoveSemicolon,  // `at`: the ';' that goes
    MergeElseIf,      // `at`: the ELSE whose IF becomes ELSIF (and whose inner END_IF goes)
  };
  Kind kind;
  uint32_t at;
};

// The rewrites the settings ask for, in text order.
std::vector<Rewrite> plan_rewrites(const SyntaxTree& tree, std::string_view text,
                                   const project::FormatSettings& settings);

// The text with the rewrites applied (whitespace around them kept; an END_IF line that only
// held the removed END_IF goes with it).
std::string apply_rewrites(const SyntaxTree& tree, std::string_view text, const std::vector<Rewrite>& rewrites);

// For MergeElseIf at an ELSE: the nodes involved, or null nodes when the merge is not one that
// keeps the program's meaning and its comments (the check and the planner both use this).
struct ElseIfMerge {
  SyntaxNode else_keyword;
  SyntaxNode if_keyword;     // the inner IF, which becomes ELSIF
  SyntaxNode end_if;         // the inner END_IF, which goes
  SyntaxNode end_semicolon;  // the inner IF's ';' after END_IF, which goes too (may be null)
  bool valid() const { return !else_keyword.is_null(); }
};
ElseIfMerge else_if_merge_at(const SyntaxTree& tree, std::string_view text, uint32_t else_offset);

// Whether a leaf is END_IF, END_CASE, END_FOR, END_WHILE or END_REPEAT of a statement.
bool is_statement_end_keyword(SyntaxNode leaf);

}  // namespace rung::format
