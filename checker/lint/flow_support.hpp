// Helpers shared by the flow lint rules (statements and conditions, rules_flow.cpp): comparing
// code by its tokens, finding what a piece of code contains, and edits that remove code cleanly.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "checker/lint/lint_rule.hpp"
#include "parser/syntax_tree.hpp"

namespace rung::lint::flow {

// Whether `a` and `b` are the same code: the same tokens in the same order, comments, pragmas and
// whitespace ignored, names and keywords compared case-insensitively (string literals exactly).
bool same_tokens(SyntaxNode a, SyntaxNode b);

// Whether `node` contains a call (a function, method or FB call: it may have side effects).
bool contains_call(SyntaxNode node);
// Whether a comment lies inside `node` (a fix that rewrites `node` would lose it).
bool contains_comment(SyntaxNode node);
// Whether an ERROR or missing node lies inside `node` (the parser guessed: do not judge it).
inline bool is_broken(SyntaxNode node) {
  return !node || node.has_error() || node.is_missing();
}

// Whether `expression` binds at least as tightly as a unary operator's operand must (a name, a
// literal, a call, a parenthesized expression ...): text that can stand after NOT unchanged.
bool is_primary(SyntaxNode expression);
// `expression`'s text, in parentheses unless it is primary.
std::string operand_text(SyntaxNode expression);
// Code quoted in a message: on one line, blanks collapsed, long code shortened with "...".
std::string in_message(std::string_view code);

// One branch of an IF or CASE: where it is reported, its statements, and the text span that
// belongs to it (a comment there makes an empty branch deliberate).
struct Branch {
  enum class Kind { Then, Elsif, Else, Case };
  Kind kind = Kind::Then;
  TextRange head;        // "IF c", "ELSIF c", "ELSE", "1, 2" (for messages)
  SyntaxNode condition;  // IF / ELSIF
  SyntaxNode body;       // statement_list, may be null
  TextRange span;        // from the head to the next branch (or the END_ keyword)
};

// The branches of an if_statement or case_statement in text order (empty for other nodes).
std::vector<Branch> branches_of(SyntaxNode node);
// Whether `body` (a statement list, or null) has no statement but ';'.
bool is_empty_body(SyntaxNode body);
// Whether a comment or a pragma lies inside `span` somewhere below `scope`: a comment makes an
// empty branch deliberate, and a pragma may hold code (Beremiz {{ C code }}).
bool has_comment_in(SyntaxNode scope, TextRange span);

// The range to delete to remove `range` of `text` cleanly: the whole line (with its line break)
// when nothing else is on it; else the range with the blanks before it (or, at the start of a
// line, the blanks after it), so no stray spaces are left.
TextRange removal_range(std::string_view text, TextRange range);

// Every node of `kind` in the file, in text order (comments and pragmas not entered).
template <typename Visit>
void for_each_of_kind(SyntaxNode root, std::string_view kind, Visit&& visit) {
  walk_preorder(root, [&](SyntaxNode node) {
    if (node.is_extra()) return false;
    if (node.kind() == kind) visit(node);
    return node.child_count() > 0;
  });
}

}  // namespace rung::lint::flow
