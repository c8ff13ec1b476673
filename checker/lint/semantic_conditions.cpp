// L039 constant-condition: an IF, ELSIF, WHILE or UNTIL condition (or a part of one) whose value
// cannot change at run time, and a CASE selector that is a constant. Such code is a typo (x = x
// for x = y), a leftover (IF FALSE THEN) or a misunderstanding of a type (usiCount >= 0 with an
// unsigned counter, byValue < 256 with a BYTE).
//
// Reported:
//   - conditions made of literals only: IF FALSE, IF 1 = 1, WHILE FALSE, ELSIF TRUE;
//   - tautologies and contradictions in a condition: x = x, x <> x, a AND NOT a, a OR NOT a,
//     a XOR a, b AND FALSE, b OR TRUE;
//   - comparisons a variable's type decides: unsigned >= 0, unsigned < 0, BYTE <= 255, SINT > 127
//     (subrange types are left out: without range checks a subrange variable can hold more).
// Not reported:
//   - conditions on CONSTANT variables (IF cDebug THEN, IF cVariant = 2 THEN): switching code with
//     a named constant is a deliberate way to configure a program;
//   - WHILE TRUE and REPEAT ... UNTIL FALSE (endless loops, L042), and REPEAT ... UNTIL TRUE, the
//     known "block to leave with EXIT" idiom.
#include <fmt/format.h>

#include "checker/constant/const_eval.hpp"
#include "checker/lint/flow_support.hpp"
#include "checker/lint/semantic_rules.hpp"
#include "checker/lint/semantic_support.hpp"

namespace rung::lint::semantic {
namespace {

using check::ConstValue;
using check::Symbol;

constexpr int kMaxDepth = 100;

struct Verdict {
  bool value = false;
  std::string why;
};

std::string_view bool_text(bool value) {
  return value ? "TRUE" : "FALSE";
}

bool is_logical(std::string_view op) {
  return op == "AND" || op == "&" || op == "OR" || op == "XOR" || op == "AND_THEN" || op == "OR_ELSE";
}

bool is_comparison(std::string_view op) {
  return op == "=" || op == "<>" || op == "<" || op == "<=" || op == ">" || op == ">=";
}

bool is_bool_literal(SyntaxNode node, std::string_view value) {
  node = without_parentheses(node);
  return node && node.kind() == "boolean_literal" && check::names_equal(node.text(), value);
}

// `a < b` read from the other side: `b > a`.
std::string mirrored(std::string_view op) {
  if (op == "<") return ">";
  if (op == "<=") return ">=";
  if (op == ">") return "<";
  if (op == ">=") return "<=";
  return std::string(op);
}

// `x op c` for every x in lower..upper: the same answer for all, or nullopt.
std::optional<bool> over_range(std::string_view op, __int128 lower, __int128 upper, __int128 c) {
  if (op == ">=") return lower >= c ? std::optional(true) : upper < c ? std::optional(false) : std::nullopt;
  if (op == ">") return lower > c ? std::optional(true) : upper <= c ? std::optional(false) : std::nullopt;
  if (op == "<=") return upper <= c ? std::optional(true) : lower > c ? std::optional(false) : std::nullopt;
  if (op == "<") return upper < c ? std::optional(true) : lower >= c ? std::optional(false) : std::nullopt;
  if (op == "=") return c < lower || c > upper ? std::optional(false) : std::nullopt;
  if (op == "<>") return c < lower || c > upper ? std::optional(true) : std::nullopt;
  return std::nullopt;
}

class ConditionCheck {
 public:
  ConditionCheck(LintContext& context, const Symbol& pou)
      : context_(context), nodes_(context.nodes()), typer_(context.model(), pou) {}

  void run() {
    static const TSFieldId kCondition = NodeList::field_id("condition");
    static const TSFieldId kValue = NodeList::field_id("value");
    walk_bodies(nodes_, typer_.pou(), [&](uint32_t i) {
      const std::string_view kind = nodes_.kind(i);
      if (kind == "if_statement") condition(nodes_.node(nodes_.child_by_field(i, kCondition)), "IF");
      if (kind == "elsif_clause") condition(nodes_.node(nodes_.child_by_field(i, kCondition)), "ELSIF");
      if (kind == "while_statement") {
        const SyntaxNode test = nodes_.node(nodes_.child_by_field(i, kCondition));
        if (!(test && test.kind() == "boolean_literal" && check::names_equal(test.text(), "TRUE"))) {
          condition(test, "WHILE");
        }
      }
      if (kind == "repeat_statement") {
        const SyntaxNode test = nodes_.node(nodes_.child_by_field(i, kCondition));
        if (!(test && test.kind() == "boolean_literal")) condition(test, "UNTIL");
      }
      if (kind == "case_statement") selector(nodes_.node(nodes_.child_by_field(i, kValue)));
      return true;
    });
  }

 private:
  void condition(SyntaxNode test, std::string_view keyword) {
    if (!test || test.has_error()) return;
    auto value = context_.model().constant_value(test, &typer_.pou());
    if (value && value->kind == ConstValue::Kind::Bool) {
      if (!contains_name(test)) whole_condition(test, keyword, value->integer != 0);
      return;  // a CONSTANT flag (IF cDebug THEN): meant
    }
    parts(test, 0);
  }

  void whole_condition(SyntaxNode test, std::string_view keyword, bool value) {
    std::string help;
    if (keyword == "WHILE") {
      help = "the loop never runs: remove it (or switch it off with a named CONSTANT if that is meant)";
    } else if (keyword == "UNTIL") {
      help = "the loop body runs exactly once: write its statements without the loop";
    } else if (value) {
      help = keyword == "IF" ? "the condition tests nothing: keep the statements and remove the IF (and its other "
                               "branches, which never run)"
                             : "the branches after it never run: remove the condition or the branches";
    } else {
      help = "the branch never runs: remove it (or switch it off with a named CONSTANT if that is meant)";
    }
    context_.report(
        "L039",
        fmt::format("the {} condition '{}' is always {}", keyword, flow::in_message(test.text()), bool_text(value)),
        test.range(), std::move(help));
  }

  void selector(SyntaxNode value) {
    if (!value || value.has_error() || contains_name(value)) return;
    auto constant = context_.model().constant_value(value, &typer_.pou());
    if (!constant || !constant->is_integer()) return;
    context_.report("L039",
                    fmt::format("the CASE selector is the constant {}", check::int128_to_string(constant->integer)),
                    value.range(), "only the branch of that value can ever run: keep it and remove the CASE");
  }

  // The parts of a condition joined by AND/OR/XOR/NOT: each may be constant on its own.
  void parts(SyntaxNode node, int depth) {
    node = without_parentheses(node);
    if (!node || depth > kMaxDepth) return;
    const std::string_view kind = node.kind();
    if (kind == "unary_expression") {
      if (ast::operator_of(node) == "NOT") parts(node.child_by_field("operand"), depth + 1);
      return;
    }
    if (kind != "binary_expression") return;
    const std::string op = ast::operator_of(node);
    std::optional<Verdict> verdict;
    if (is_logical(op)) verdict = logical(node, op);
    if (is_comparison(op)) verdict = comparison(node, op);
    if (verdict) {
      context_.report(
          "L039",
          fmt::format("'{}' is always {}: {}", flow::in_message(node.text()), bool_text(verdict->value), verdict->why),
          node.range(), "a condition that cannot change is a mistake or dead code: check its operands");
      return;
    }
    if (is_logical(op)) {
      parts(node.child_by_field("left"), depth + 1);
      parts(node.child_by_field("right"), depth + 1);
    }
  }

  bool is_bool(SyntaxNode operand) {
    auto info = typer_.type_of(operand);
    return info && check::arithmetic_type(info->type)->kind == check::TypeKind::Bool;
  }

  // Two operands that are the same code and read the same value twice (no call in between).
  bool same_value(SyntaxNode a, SyntaxNode b) const {
    return flow::same_tokens(nodes_, without_parentheses(a), without_parentheses(b)) && !flow::contains_call(nodes_, a);
  }

  std::optional<Verdict> logical(SyntaxNode node, std::string_view op) {
    const SyntaxNode left = node.child_by_field("left");
    const SyntaxNode right = node.child_by_field("right");
    if (!left || !right) return std::nullopt;
    // Only on BOOL operands is the pattern a constant (AND and OR of WORDs work bit by bit). The
    // pattern is read first: typing the operands is the expensive part.
    std::optional<Verdict> verdict = logical_pattern(left, right, op);
    if (!verdict || !is_bool(left) || !is_bool(right)) return std::nullopt;
    return verdict;
  }

  // What `left op right` always is by its shape alone, if anything.
  std::optional<Verdict> logical_pattern(SyntaxNode left, SyntaxNode right, std::string_view op) {
    const bool is_and = op == "AND" || op == "&" || op == "AND_THEN";
    const bool is_or = op == "OR" || op == "OR_ELSE";
    auto negation_of = [&](SyntaxNode maybe_not, SyntaxNode other) {
      const SyntaxNode inner = without_parentheses(maybe_not);
      return inner.kind() == "unary_expression" && ast::operator_of(inner) == "NOT" &&
             same_value(inner.child_by_field("operand"), other);
    };
    if (negation_of(right, left) || negation_of(left, right)) {
      if (is_and) return Verdict{false, "a value AND its negation"};
      if (is_or) return Verdict{true, "a value OR its negation"};
      return Verdict{true, "a value XOR its negation"};
    }
    if (op == "XOR" && same_value(left, right)) return Verdict{false, "both operands are the same"};
    if (is_and && (is_bool_literal(left, "FALSE") || is_bool_literal(right, "FALSE"))) {
      return Verdict{false, "anything AND FALSE is FALSE"};
    }
    if (is_or && (is_bool_literal(left, "TRUE") || is_bool_literal(right, "TRUE"))) {
      return Verdict{true, "anything OR TRUE is TRUE"};
    }
    return std::nullopt;
  }

  std::optional<Verdict> comparison(SyntaxNode node, std::string_view op) {
    const SyntaxNode left = node.child_by_field("left");
    const SyntaxNode right = node.child_by_field("right");
    if (!left || !right) return std::nullopt;
    if (contains_name(left) && same_value(left, right)) {
      const bool value = op == "=" || op == "<=" || op == ">=";
      return Verdict{value, "both sides are the same"};
    }
    if (auto verdict = by_type_range(left, right, op)) return verdict;
    return by_type_range(right, left, mirrored(op));
  }

  // `variable op literal` decided by the variable's type alone.
  std::optional<Verdict> by_type_range(SyntaxNode variable, SyntaxNode constant, std::string_view op) {
    if (!is_variable_access(variable) || contains_name(constant)) return std::nullopt;
    auto info = typer_.type_of(variable);
    auto literal = typer_.type_of(constant);
    if (!info || !literal || !literal->value || !literal->value->is_integer()) return std::nullopt;
    const check::Type* type = check::underlying(info->type);
    if (type->kind == check::TypeKind::Reference && type->element) type = check::underlying(type->element);
    if (type->kind != check::TypeKind::SignedInt && type->kind != check::TypeKind::UnsignedInt &&
        type->kind != check::TypeKind::Bit) {
      return std::nullopt;  // subranges (not enforced without range checks), enums, BOOL, REAL ...
    }
    auto range = check::integer_range(type);
    if (!range) return std::nullopt;
    auto value = over_range(op, range->lower, range->upper, literal->value->integer);
    if (!value) return std::nullopt;
    return Verdict{*value, fmt::format("{} is {} ({}..{})", flow::in_message(variable.text()), info->type->name,
                                       check::int128_to_string(range->lower), check::int128_to_string(range->upper))};
  }

  LintContext& context_;
  const NodeList& nodes_;
  ExpressionTyper typer_;
};

}  // namespace

void check_constant_conditions(LintContext& context) {
  for (const Symbol* pou : context.pous()) ConditionCheck(context, *pou).run();
}

}  // namespace rung::lint::semantic
