#include "checker/lint/flow_support.hpp"

#include <vector>

#include "checker/symbols/names.hpp"
#include "parser/ast.hpp"

namespace rung::lint::flow {
namespace {

// The tokens of `node` in text order, without comments and pragmas.
std::vector<SyntaxNode> tokens_of(SyntaxNode node) {
  std::vector<SyntaxNode> tokens;
  walk_preorder(node, [&](SyntaxNode n) {
    if (n.is_extra()) return false;
    if (n.child_count() == 0) tokens.push_back(n);
    return true;
  });
  return tokens;
}

bool is_string_token(SyntaxNode token) {
  return token.kind().find("string") != std::string_view::npos;
}

bool is_blank(char c) {
  return c == ' ' || c == '\t';
}

}  // namespace

bool same_tokens(SyntaxNode a, SyntaxNode b) {
  if (!a || !b) return false;
  const std::vector<SyntaxNode> left = tokens_of(a);
  const std::vector<SyntaxNode> right = tokens_of(b);
  if (left.size() != right.size()) return false;
  for (size_t i = 0; i < left.size(); ++i) {
    if (left[i].kind() != right[i].kind()) return false;
    // 'Abc' and 'ABC' are different values; every other token of ST is case-insensitive.
    const bool equal = is_string_token(left[i]) ? left[i].text() == right[i].text()
                                                : check::names_equal(left[i].text(), right[i].text());
    if (!equal) return false;
  }
  return true;
}

bool contains_call(SyntaxNode node) {
  bool found = false;
  walk_preorder(node, [&](SyntaxNode n) {
    if (found || n.is_extra()) return false;
    if (n.kind() == "call_expression") found = true;
    return !found;
  });
  return found;
}

bool contains_comment(SyntaxNode node) {
  bool found = false;
  walk_preorder(node, [&](SyntaxNode n) {
    if (found) return false;
    if (n.is_extra()) {
      found = n.kind() == "comment";
      return false;
    }
    return true;
  });
  return found;
}

bool is_primary(SyntaxNode expression) {
  switch (ast::expression_kind(expression)) {
    case ast::ExpressionKind::Identifier:
    case ast::ExpressionKind::Literal:
    case ast::ExpressionKind::Parenthesized:
    case ast::ExpressionKind::Call:
    case ast::ExpressionKind::Member:
    case ast::ExpressionKind::Index:
    case ast::ExpressionKind::Dereference:
    case ast::ExpressionKind::DirectAddress: return true;
    default: return false;
  }
}

std::string operand_text(SyntaxNode expression) {
  if (is_primary(expression)) return std::string(expression.text());
  return "(" + std::string(expression.text()) + ")";
}

std::string in_message(std::string_view code) {
  constexpr size_t kLongest = 60;
  std::string out;
  for (char c : code) {
    const bool blank = c == ' ' || c == '\t' || c == '\r' || c == '\n';
    if (blank && (out.empty() || out.back() == ' ')) continue;
    out.push_back(blank ? ' ' : c);
  }
  while (!out.empty() && out.back() == ' ') out.pop_back();
  if (out.size() > kLongest) {
    size_t cut = kLongest - 3;
    while (cut > 0 && (static_cast<unsigned char>(out[cut]) & 0xC0) == 0x80) --cut;  // not inside a UTF-8 character
    out = out.substr(0, cut) + "...";
  }
  return out;
}

std::vector<Branch> branches_of(SyntaxNode node) {
  std::vector<Branch> branches;
  const bool is_if = node.kind() == "if_statement";
  for (SyntaxNode child : node.named_children()) {
    const std::string_view kind = child.kind();
    if (is_if && kind == "statement_list") {
      // The THEN branch: its head is IF ... THEN, which ends where the condition ends.
      continue;
    }
    if (kind == "elsif_clause" || kind == "else_clause" || kind == "case_element") {
      Branch branch;
      branch.kind = kind == "elsif_clause"  ? Branch::Kind::Elsif
                    : kind == "else_clause" ? Branch::Kind::Else
                                            : Branch::Kind::Case;
      branch.condition = child.child_by_field("condition");
      branch.body = child.child_by_field("body");
      uint32_t head_end = child.begin() + (kind == "else_clause" ? 4 : 0);
      if (branch.condition) head_end = branch.condition.end();
      if (kind == "case_element") {
        for (SyntaxNode label : child.children_by_field("label")) head_end = label.end();
      }
      branch.head = {child.begin(), head_end};
      branch.span = {child.begin(), child.end()};
      branches.push_back(branch);
    }
  }
  if (is_if) {
    Branch then_branch;
    then_branch.condition = node.child_by_field("condition");
    then_branch.body = node.child_by_field("body");
    then_branch.head = {node.begin(), then_branch.condition ? then_branch.condition.end() : node.begin() + 2};
    then_branch.span = {then_branch.head.end, node.end()};
    branches.insert(branches.begin(), then_branch);
  }
  // A branch reaches to the next one: comments between them belong to it.
  for (size_t i = 0; i + 1 < branches.size(); ++i) branches[i].span.end = branches[i + 1].span.begin;
  if (!branches.empty()) branches.back().span.end = node.end();
  return branches;
}

bool is_empty_body(SyntaxNode body) {
  if (!body) return true;
  for (SyntaxNode statement : body.named_children()) {
    if (!statement.is_extra() && statement.kind() != "empty_statement") return false;
  }
  return true;
}

bool has_comment_in(SyntaxNode scope, TextRange span) {
  bool found = false;
  walk_preorder(scope, [&](SyntaxNode node) {
    if (found || node.end() <= span.begin || node.begin() >= span.end) return false;
    if (node.is_extra()) {
      found = node.kind() == "comment" || node.kind() == "pragma";
      return false;
    }
    return true;
  });
  return found;
}

TextRange removal_range(std::string_view text, TextRange range) {
  uint32_t before = range.begin;
  while (before > 0 && is_blank(text[before - 1])) --before;
  uint32_t after = range.end;
  while (after < text.size() && is_blank(text[after])) ++after;
  const bool starts_line = before == 0 || text[before - 1] == '\n';
  const bool ends_line = after == text.size() || text[after] == '\n' || text[after] == '\r';
  if (starts_line && ends_line) {
    // Alone on its line: the line goes, with its line break ("\r\n" or "\n").
    if (after < text.size() && text[after] == '\r') ++after;
    if (after < text.size() && text[after] == '\n') ++after;
    return {before, after};
  }
  if (starts_line) return {range.begin, after};  // keep the indentation of what follows
  return {before, range.end};
}

}  // namespace rung::lint::flow
