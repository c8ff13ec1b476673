#include "checker/lint/flow_support.hpp"

#include <vector>

#include "checker/symbols/names.hpp"
#include "parser/ast.hpp"

namespace rung::lint::flow {
namespace {

// The first token at or after `i` before `stop` (a leaf that is no comment or pragma, nor inside
// one); `stop` when there is none.
uint32_t next_token(const NodeList& nodes, uint32_t i, uint32_t stop) {
  while (i < stop) {
    if (nodes.is_extra(i)) {
      i = nodes.subtree_end(i);
    } else if (nodes.has_children(i)) {
      ++i;
    } else {
      return i;
    }
  }
  return stop;
}

bool is_string_token(std::string_view kind) {
  return kind.find("string") != std::string_view::npos;
}

bool is_blank(char c) {
  return c == ' ' || c == '\t';
}

}  // namespace

bool same_tokens(const NodeList& nodes, SyntaxNode a, SyntaxNode b) {
  return same_tokens(nodes, nodes.index_of(a), nodes.index_of(b));
}

bool same_tokens(const NodeList& nodes, uint32_t left, uint32_t right) {
  if (left == NodeList::kNone || right == NodeList::kNone) return false;
  const uint32_t left_end = nodes.subtree_end(left);
  const uint32_t right_end = nodes.subtree_end(right);
  uint32_t x = next_token(nodes, left, left_end);
  uint32_t y = next_token(nodes, right, right_end);
  for (; x < left_end && y < right_end;
       x = next_token(nodes, x + 1, left_end), y = next_token(nodes, y + 1, right_end)) {
    const std::string_view kind = nodes.kind(x);
    if (kind != nodes.kind(y)) return false;
    // 'Abc' and 'ABC' are different values; every other token of ST is case-insensitive.
    const bool equal =
        is_string_token(kind) ? nodes.text(x) == nodes.text(y) : check::names_equal(nodes.text(x), nodes.text(y));
    if (!equal) return false;
  }
  return x == left_end && y == right_end;
}

bool contains_call(const NodeList& nodes, SyntaxNode node) {
  bool found = false;
  nodes.walk(nodes.index_of(node), [&](uint32_t i) {
    if (found || nodes.is_extra(i)) return false;
    if (nodes.kind(i) == "call_expression") found = true;
    return !found;
  });
  return found;
}

bool contains_comment(const NodeList& nodes, SyntaxNode node) {
  bool found = false;
  nodes.walk(nodes.index_of(node), [&](uint32_t i) {
    if (found) return false;
    if (nodes.is_extra(i)) {
      found = nodes.kind(i) == "comment";
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

std::vector<Branch> branches_of(const NodeList& nodes, SyntaxNode node) {
  static const TSFieldId kCondition = NodeList::field_id("condition");
  static const TSFieldId kBody = NodeList::field_id("body");
  static const TSFieldId kLabel = NodeList::field_id("label");
  std::vector<Branch> branches;
  const uint32_t statement = nodes.index_of(node);
  if (statement == NodeList::kNone) return branches;
  const bool is_if = nodes.kind(statement) == "if_statement";
  nodes.for_each_child(statement, [&](uint32_t child) {
    if (!nodes.is_named(child)) return;
    // The THEN branch is the if_statement's own statement_list: its head is IF ... THEN.
    const std::string_view kind = nodes.kind(child);
    if (kind != "elsif_clause" && kind != "else_clause" && kind != "case_element") return;
    Branch branch;
    branch.kind = kind == "elsif_clause"  ? Branch::Kind::Elsif
                  : kind == "else_clause" ? Branch::Kind::Else
                                          : Branch::Kind::Case;
    const uint32_t condition = nodes.child_by_field(child, kCondition);
    branch.condition = nodes.node(condition);
    branch.body = nodes.node(nodes.child_by_field(child, kBody));
    uint32_t head_end = nodes.begin(child) + (kind == "else_clause" ? 4 : 0);
    if (condition != NodeList::kNone) head_end = nodes.end(condition);
    if (kind == "case_element") {
      nodes.for_each_child(child, [&](uint32_t label) {
        if (nodes.field(label) == kLabel && kLabel != 0) head_end = nodes.end(label);
      });
    }
    branch.head = {nodes.begin(child), head_end};
    branch.span = nodes.range(child);
    branches.push_back(branch);
  });
  if (is_if) {
    Branch then_branch;
    const uint32_t condition = nodes.child_by_field(statement, kCondition);
    then_branch.condition = nodes.node(condition);
    then_branch.body = nodes.node(nodes.child_by_field(statement, kBody));
    then_branch.head = {nodes.begin(statement),
                        condition != NodeList::kNone ? nodes.end(condition) : nodes.begin(statement) + 2};
    then_branch.span = {then_branch.head.end, nodes.end(statement)};
    branches.insert(branches.begin(), then_branch);
  }
  // A branch reaches to the next one: comments between them belong to it.
  for (size_t i = 0; i + 1 < branches.size(); ++i) branches[i].span.end = branches[i + 1].span.begin;
  if (!branches.empty()) branches.back().span.end = nodes.end(statement);
  return branches;
}

bool is_empty_body(const NodeList& nodes, SyntaxNode body) {
  const uint32_t list = nodes.index_of(body);
  if (list == NodeList::kNone) return true;
  bool empty = true;
  nodes.for_each_child(list, [&](uint32_t statement) {
    if (nodes.is_named(statement) && !nodes.is_extra(statement) && nodes.kind(statement) != "empty_statement") {
      empty = false;
    }
  });
  return empty;
}

bool has_comment_in(const NodeList& nodes, SyntaxNode scope, TextRange span) {
  bool found = false;
  nodes.walk(nodes.index_of(scope), [&](uint32_t i) {
    if (found || nodes.end(i) <= span.begin || nodes.begin(i) >= span.end) return false;
    if (nodes.is_extra(i)) {
      const std::string_view kind = nodes.kind(i);
      found = kind == "comment" || kind == "pragma";
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
