// Boolean code that can be written simpler: L036 double-negation, L037 compare-with-bool-literal,
// L038 if-to-assignment. Each fix keeps the meaning: operands that are not primary are put in
// parentheses where the new operator binds tighter than the old one.
#include <string>

#include "checker/lint/flow_rules.hpp"
#include "checker/lint/flow_support.hpp"
#include "checker/query/position.hpp"
#include "checker/semantic/body_checker.hpp"
#include "checker/symbols/names.hpp"
#include "checker/types/type.hpp"
#include "parser/ast.hpp"

namespace rung::lint::flow {
namespace {

// `expression` without the parentheses around it.
SyntaxNode without_parentheses(SyntaxNode expression) {
  while (expression && expression.kind() == "parenthesized_expression") {
    SyntaxNode inner;
    for (SyntaxNode child : expression.named_children()) {
      if (!child.is_extra()) inner = child;
    }
    if (!inner) break;
    expression = inner;
  }
  return expression;
}

bool is_not(SyntaxNode expression) {
  return expression && expression.kind() == "unary_expression" && ast::operator_of(expression) == "NOT";
}

// TRUE / FALSE written as a plain literal, or nullopt.
std::optional<bool> bool_literal(SyntaxNode expression) {
  if (!expression || expression.kind() != "boolean_literal") return std::nullopt;
  return check::names_equal(expression.text(), "TRUE");
}

Fix replace(SyntaxNode node, std::string replacement, std::string description) {
  return Fix{std::move(description), {TextEdit{node.range(), std::move(replacement)}}};
}

// The only statement of a branch body when it is `target := TRUE/FALSE;`, with the literal.
struct BoolAssignment {
  SyntaxNode target;
  bool value = false;
};
std::optional<BoolAssignment> single_bool_assignment(SyntaxNode body) {
  if (!body) return std::nullopt;
  SyntaxNode only;
  for (SyntaxNode statement : body.named_children()) {
    if (statement.is_extra()) continue;
    if (only) return std::nullopt;
    only = statement;
  }
  if (!only || only.kind() != "assignment_statement") return std::nullopt;
  const SyntaxNode op = only.child_by_field("operator");
  const std::optional<bool> value = bool_literal(only.child_by_field("right"));
  if (!op || op.text() != ":=" || !value) return std::nullopt;
  return BoolAssignment{only.child_by_field("left"), *value};
}

}  // namespace

void check_double_negation(LintContext& context) {
  uint32_t covered_end = 0;  // NOT NOT NOT x: the pair found first covers the inner NOT
  const NodeList& nodes = context.nodes();
  for_each_of_kind(nodes, 0, "unary_expression", [&](uint32_t i) {
    if (!check::names_equal(operator_text(nodes, i), "NOT")) return;  // is_not() without building the node
    const SyntaxNode outer = nodes.node(i);
    if (outer.begin() < covered_end || is_broken(outer)) return;
    const SyntaxNode inner = without_parentheses(outer.child_by_field("operand"));
    if (!is_not(inner)) return;
    const SyntaxNode operand = inner.child_by_field("operand");
    if (!operand) return;
    covered_end = inner.end();
    std::optional<Fix> fix;
    // A NOT's operand is unary or primary (NOT binds tighter than every binary operator), so it
    // can stand where the outer NOT stood without parentheses.
    if (!contains_comment(nodes, outer)) fix = replace(outer, std::string(operand.text()), "remove the two NOTs");
    context.report("L036", "'" + in_message(outer.text()) + "' is just '" + in_message(operand.text()) + "'",
                   outer.range(), "two negations cancel out: write the operand alone", std::move(fix));
  });
}

void check_compare_with_bool_literal(LintContext& context) {
  const NodeList& nodes = context.nodes();
  for_each_of_kind(nodes, 0, "binary_expression", [&](uint32_t i) {
    const std::string_view op = operator_text(nodes, i);
    if (op != "=" && op != "<>") return;
    const SyntaxNode comparison = nodes.node(i);
    if (is_broken(comparison)) return;
    const SyntaxNode left = comparison.child_by_field("left");
    const SyntaxNode right = comparison.child_by_field("right");
    std::optional<bool> literal = bool_literal(right);
    SyntaxNode other = left;
    if (!literal) {
      literal = bool_literal(left);
      other = right;
    }
    // TRUE = FALSE is a constant condition (L039), not a comparison with a BOOL.
    if (!literal || !other || bool_literal(other)) return;
    const check::Symbol* scope = check::query::scope_at(context.model(), context.source_id(), comparison.begin());
    if (!scope) return;
    std::vector<Diagnostic> ignored;
    const check::Type* type = check::BodyChecker(context.model(), *scope, ignored).type_of(other).type;
    type = type ? check::arithmetic_type(type) : nullptr;
    if (!type || type->kind != check::TypeKind::Bool) return;
    // x = TRUE and x <> FALSE are x; x = FALSE and x <> TRUE are NOT x.
    const bool keeps = (*literal) == (op == "=");
    const std::string operand(other.text());
    // The comparison binds less tightly than its operands, so `other` can take its place as it
    // is; after NOT it needs parentheses unless it is primary.
    const std::string replacement = keeps ? operand : "NOT " + operand_text(other);
    std::optional<Fix> fix;
    if (!contains_comment(nodes, comparison)) fix = replace(comparison, replacement, "compare without the literal");
    context.report("L037", "comparing the BOOL " + in_message(operand) + " with " + (*literal ? "TRUE" : "FALSE"),
                   comparison.range(), "write " + in_message(replacement) + ": it says the same, shorter",
                   std::move(fix));
  });
}

void check_if_to_assignment(LintContext& context) {
  const NodeList& nodes = context.nodes();
  for_each_of_kind(nodes, 0, "if_statement", [&](uint32_t i) {
    const uint32_t else_index = nodes.first_child_of_kind(i, "else_clause");
    if (else_index == NodeList::kNone || nodes.first_child_of_kind(i, "elsif_clause") != NodeList::kNone) return;
    const SyntaxNode statement = nodes.node(i);
    if (is_broken(statement)) return;
    const SyntaxNode else_clause = nodes.node(else_index);
    const SyntaxNode condition = statement.child_by_field("condition");
    if (!else_clause || !condition) return;
    const std::optional<BoolAssignment> then_part = single_bool_assignment(statement.child_by_field("body"));
    const std::optional<BoolAssignment> else_part = single_bool_assignment(else_clause.child_by_field("body"));
    if (!then_part || !else_part || then_part->value == else_part->value) return;
    if (!same_tokens(nodes, then_part->target, else_part->target)) return;
    const std::string target(then_part->target.text());
    const std::string value = then_part->value ? std::string(condition.text()) : "NOT " + operand_text(condition);
    const std::string replacement = target + " := " + value + ";";
    // A comment inside would be lost by the rewrite: then only the finding, no fix.
    std::optional<Fix> fix;
    if (!contains_comment(nodes, statement)) fix = replace(statement, replacement, "assign the condition");
    context.report("L038",
                   "this IF only assigns " + (then_part->value ? std::string("") : "NOT ") + "its condition to " +
                       in_message(target),
                   {statement.begin(), condition.end()}, "write " + in_message(replacement), std::move(fix));
  });
}

}  // namespace rung::lint::flow
