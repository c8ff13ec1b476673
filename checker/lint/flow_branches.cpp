// Branches of IF and CASE (and loop bodies): L030 case-without-else, L032 empty-branch,
// L033 duplicate-condition, L034 identical-branches.
#include <fmt/format.h>

#include <string>
#include <vector>

#include "checker/lint/flow_rules.hpp"
#include "checker/lint/flow_support.hpp"
#include "parser/ast.hpp"

namespace rung::lint::flow {
namespace {

std::string_view head_text(std::string_view text, TextRange head) {
  return text.substr(head.begin, head.end - head.begin);
}

// What the branch is called in a message: "the THEN branch of 'IF bRun'", "CASE branch '1, 2'".
std::string branch_name(std::string_view text, const Branch& branch) {
  std::string head = in_message(head_text(text, branch.head));
  switch (branch.kind) {
    case Branch::Kind::Then: return "the THEN branch of '" + head + "'";
    case Branch::Kind::Elsif: return "the branch '" + head + "'";
    case Branch::Kind::Else: return "the ELSE branch";
    case Branch::Kind::Case: return "CASE branch '" + head + "'";
  }
  return head;
}

bool is_else(const Branch& branch) {
  return branch.kind == Branch::Kind::Else;
}

// Whether a CASE branch does enough that two copies of it are worth merging: one assignment or
// jump is a table entry (DAYS_IN_MONTH := 30; nState := 20;) that reads better per label.
bool is_substantial(SyntaxNode body) {
  size_t count = 0;
  SyntaxNode only;
  for (SyntaxNode statement : body.named_children()) {
    if (statement.is_extra() || statement.kind() == "empty_statement") continue;
    ++count;
    only = statement;
  }
  if (count != 1) return count > 1;
  switch (ast::statement_kind(only)) {
    case ast::StatementKind::Assignment:
    case ast::StatementKind::Exit:
    case ast::StatementKind::Continue:
    case ast::StatementKind::Return:
    case ast::StatementKind::Jump: return false;
    default: return true;
  }
}

// Whether the loop's body (the statements it repeats) is empty, with no comment anywhere in it.
void check_loop_body(LintContext& context, SyntaxNode loop) {
  const NodeList& nodes = context.nodes();
  const SyntaxNode body = loop.child_by_field("body");
  if (!is_empty_body(nodes, body) || has_comment_in(nodes, loop, loop.range())) return;
  const std::string keyword = loop.kind() == "for_statement"     ? "FOR"
                              : loop.kind() == "while_statement" ? "WHILE"
                                                                 : "REPEAT";
  context.report("L032", "the " + keyword + " loop has an empty body",
                 {loop.begin(), loop.begin() + static_cast<uint32_t>(keyword.size())},
                 "an empty loop only spends cycle time: remove it, or write the statements it should repeat");
}

}  // namespace

void check_case_without_else(LintContext& context) {
  for_each_of_kind(context, "case_statement", [&](SyntaxNode statement) {
    if (is_broken(statement) || statement.first_child_of_kind("else_clause")) return;
    const SyntaxNode value = statement.child_by_field("value");
    if (!value) return;
    context.report("L030", "CASE on " + in_message(value.text()) + " has no ELSE", {statement.begin(), value.end()},
                   "add ELSE to handle values no label lists (e.g. a corrupted or uninitialised state)");
  });
}

void check_empty_branch(LintContext& context) {
  const std::string_view text = context.text();
  const NodeList& nodes = context.nodes();
  nodes.walk(0, [&](uint32_t i) {
    if (nodes.is_extra(i)) return false;
    const std::string_view kind = nodes.kind(i);
    if (kind == "for_statement" || kind == "while_statement" || kind == "repeat_statement") {
      const SyntaxNode node = nodes.node(i);
      if (!is_broken(node)) check_loop_body(context, node);
      return true;
    }
    if (kind != "if_statement" && kind != "case_statement") return true;
    const SyntaxNode node = nodes.node(i);
    if (is_broken(node)) return true;
    const bool in_case = kind == "case_statement";
    const std::vector<Branch> branches = branches_of(nodes, node);
    for (size_t b = 0; b < branches.size(); ++b) {
      const Branch& branch = branches[b];
      if (!is_empty_body(nodes, branch.body) || has_comment_in(nodes, node, branch.span)) continue;
      context.report("L032", branch_name(text, branch) + " is empty", branch.head,
                     is_else(branch) && !in_case
                         ? "remove the empty ELSE, or write a comment saying why nothing is done here"
                         : "write the statements it should run, or a comment saying why nothing is done here");
    }
    return true;
  });
}

void check_duplicate_condition(LintContext& context) {
  const NodeList& nodes = context.nodes();
  for_each_of_kind(nodes, 0, "if_statement", [&](uint32_t i) {
    // Without ELSIF there is one condition: nothing to repeat.
    if (nodes.first_child_of_kind(i, "elsif_clause") == NodeList::kNone) return;
    const SyntaxNode statement = nodes.node(i);
    if (is_broken(statement)) return;
    std::vector<SyntaxNode> earlier;
    for (const Branch& branch : branches_of(nodes, statement)) {
      if (!branch.condition) continue;
      // f() may answer differently the second time (an edge, a counter): not a repeat.
      if (contains_call(nodes, branch.condition)) continue;
      const SyntaxNode* first = nullptr;
      for (const SyntaxNode& previous : earlier) {
        if (same_tokens(nodes, previous, branch.condition)) {
          first = &previous;
          break;
        }
      }
      if (first) {
        context.report("L033", "ELSIF repeats the condition '" + in_message(first->text()) + "': its branch never runs",
                       branch.condition.range(),
                       "an earlier branch already took every case where it is TRUE; test what was meant here",
                       {DiagnosticLabel{first->range(), "first tested here"}});
      } else {
        earlier.push_back(branch.condition);
      }
    }
  });
}

void check_identical_branches(LintContext& context) {
  const std::string_view text = context.text();
  const NodeList& nodes = context.nodes();
  for_each_of_kind(nodes, 0, "if_statement", [&](uint32_t i) {
    // Only IF c THEN <s> ELSE <s> END_IF: with ELSIF, equal branches may be a deliberate order.
    if (nodes.first_child_of_kind(i, "else_clause") == NodeList::kNone ||
        nodes.first_child_of_kind(i, "elsif_clause") != NodeList::kNone) {
      return;
    }
    const SyntaxNode statement = nodes.node(i);
    if (is_broken(statement)) return;
    const std::vector<Branch> branches = branches_of(nodes, statement);
    if (branches.size() != 2 || !is_else(branches[1])) return;
    if (is_empty_body(nodes, branches[0].body) || !same_tokens(nodes, branches[0].body, branches[1].body)) return;
    context.report("L034",
                   "the THEN and ELSE branches of '" + in_message(head_text(text, branches[0].head)) + "' are the same",
                   branches[0].head,
                   "the condition makes no difference: keep the statements once without the IF, or fix the branch "
                   "that is wrong",
                   {DiagnosticLabel{branches[1].head, "the ELSE branch does the same"}});
  });
  for_each_of_kind(context, "case_statement", [&](SyntaxNode statement) {
    if (is_broken(statement)) return;
    const std::vector<Branch> branches = branches_of(nodes, statement);
    for (size_t i = 1; i < branches.size(); ++i) {
      if (is_empty_body(nodes, branches[i].body) || is_else(branches[i]) || !is_substantial(branches[i].body)) continue;
      for (size_t j = 0; j < i; ++j) {
        if (is_else(branches[j]) || !same_tokens(nodes, branches[j].body, branches[i].body)) continue;
        const std::string first = in_message(head_text(text, branches[j].head));
        const std::string second = in_message(head_text(text, branches[i].head));
        context.report("L034", fmt::format("CASE branch '{}' does the same as branch '{}'", second, first), branches[i].head,
                       fmt::format("merge the labels into one branch ({}, {}) if that is what is meant", first, second),
                       {DiagnosticLabel{branches[j].head, "the same statements here"}});
        break;
      }
    }
  });
}

}  // namespace rung::lint::flow
