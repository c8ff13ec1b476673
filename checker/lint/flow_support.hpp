// Helpers shared by the flow lint rules (statements and conditions, rules_flow.cpp): comparing
// code by its tokens, finding what a piece of code contains, and edits that remove code cleanly.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "checker/lint/lint_rule.hpp"
#include "parser/syntax_tree.hpp"

namespace rung::lint::flow {

// The questions below look at every node below the one asked about: they walk the file's node
// list (`nodes`, LintContext::nodes(); the nodes asked about are nodes of its tree).

// Whether `a` and `b` are the same code: the same tokens in the same order, comments, pragmas and
// whitespace ignored, names and keywords compared case-insensitively (string literals exactly).
bool same_tokens(const NodeList& nodes, SyntaxNode a, SyntaxNode b);
// The same for nodes `a` and `b` of `nodes` by index.
bool same_tokens(const NodeList& nodes, uint32_t a, uint32_t b);

// Whether `node` contains a call (a function, method or FB call: it may have side effects).
bool contains_call(const NodeList& nodes, SyntaxNode node);
// Whether a comment lies inside `node` (a fix that rewrites `node` would lose it).
bool contains_comment(const NodeList& nodes, SyntaxNode node);
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
std::vector<Branch> branches_of(const NodeList& nodes, SyntaxNode node);
// Whether `body` (a statement list, or null) has no statement but ';'.
bool is_empty_body(const NodeList& nodes, SyntaxNode body);
// Whether a comment or a pragma lies inside `span` somewhere below `scope`: a comment makes an
// empty branch deliberate, and a pragma may hold code (Beremiz {{ C code }}).
bool has_comment_in(const NodeList& nodes, SyntaxNode scope, TextRange span);

// The range to delete to remove `range` of `text` cleanly: the whole line (with its line break)
// when nothing else is on it; else the range with the blanks before it (or, at the start of a
// line, the blanks after it), so no stray spaces are left.
TextRange removal_range(std::string_view text, TextRange range);

// visit(i) for every node of `kind` at or below node `from` of `nodes`, in text order (comments
// and pragmas not entered).
template <typename Visit>
void for_each_of_kind(const NodeList& nodes, uint32_t from, std::string_view kind, Visit&& visit) {
  nodes.walk(from, [&](uint32_t i) {
    if (nodes.is_extra(i)) return false;
    if (nodes.kind(i) == kind) visit(i);
    return nodes.has_children(i);
  });
}

// visit(node) for every node of `kind` in the file of `context`, in text order.
template <typename Visit>
void for_each_of_kind(const LintContext& context, std::string_view kind, Visit&& visit) {
  const NodeList& nodes = context.nodes();
  for_each_of_kind(nodes, 0, kind, [&](uint32_t i) { visit(nodes.node(i)); });
}

}  // namespace rung::lint::flow
