#include "checker/constant/const_eval.hpp"

#include <cmath>

#include "checker/symbols/names.hpp"
#include "parser/ast.hpp"

namespace rung::check {
namespace {

constexpr int kMaxDepth = 200;  // deeper expressions are left unevaluated (no recursion blow-up)

std::optional<ConstValue> compare(const ConstValue& a, const ConstValue& b, std::string_view op) {
  int order = 0;
  if (a.is_number() && b.is_number()) {
    if (a.is_integer() && b.is_integer()) {
      order = a.integer < b.integer ? -1 : (a.integer > b.integer ? 1 : 0);
    } else {
      order = a.as_real() < b.as_real() ? -1 : (a.as_real() > b.as_real() ? 1 : 0);
    }
  } else if (a.kind == b.kind && a.kind != ConstValue::Kind::String && a.kind != ConstValue::Kind::Real) {
    order = a.integer < b.integer ? -1 : (a.integer > b.integer ? 1 : 0);
  } else if (a.kind == ConstValue::Kind::String && b.kind == ConstValue::Kind::String) {
    order = a.text < b.text ? -1 : (a.text > b.text ? 1 : 0);
  } else {
    return std::nullopt;
  }
  if (op == "=") return ConstValue::of_bool(order == 0);
  if (op == "<>") return ConstValue::of_bool(order != 0);
  if (op == "<") return ConstValue::of_bool(order < 0);
  if (op == "<=") return ConstValue::of_bool(order <= 0);
  if (op == ">") return ConstValue::of_bool(order > 0);
  if (op == ">=") return ConstValue::of_bool(order >= 0);
  return std::nullopt;
}

}  // namespace

std::optional<ConstValue> literal_value(SyntaxNode literal) {
  const std::string_view kind = literal.kind();
  const std::string_view text = literal.text();
  if (kind == "integer_literal") {
    if (auto value = parse_integer_literal(text)) return ConstValue::of_integer(*value);
    return std::nullopt;
  }
  if (kind == "real_literal") {
    if (auto value = parse_real_literal(text)) return ConstValue::of_real(*value);
    return std::nullopt;
  }
  if (kind == "boolean_literal") return ConstValue::of_bool(names_equal(text, "TRUE"));
  if (kind == "time_literal") {
    if (auto value = parse_duration_literal(text)) return ConstValue::of_duration(*value);
    return std::nullopt;
  }
  if (kind == "string_literal") {
    if (auto value = parse_string_literal(text)) {
      ConstValue out;
      out.kind = ConstValue::Kind::String;
      out.text = std::move(*value);
      return out;
    }
    return std::nullopt;
  }
  if (kind == "typed_literal") {
    // INT#-5: the value after '#', with its sign. The grammar's `value` field spans the sign and
    // the number, and looking it up finds the sign token; the number is the last named child.
    if (literal.named_child_count() < 2) return std::nullopt;
    SyntaxNode value = literal.named_child(literal.named_child_count() - 1);
    bool negative = false;
    for (uint32_t i = 0; i < literal.child_count(); ++i) {
      if (literal.child(i).kind() == "-") negative = true;
    }
    auto inner = literal_value(value);
    if (inner && negative) {
      if (inner->kind == ConstValue::Kind::Integer) inner->integer = -inner->integer;
      if (inner->kind == ConstValue::Kind::Real) inner->real = -inner->real;
    }
    return inner;
  }
  return std::nullopt;
}

std::optional<ConstValue> ConstEvaluator::evaluate(SyntaxNode expression) {
  problem_ = {};
  return evaluate_at(expression, 0);
}

std::optional<ConstValue> ConstEvaluator::evaluate_at(SyntaxNode expression, int depth) {
  if (!expression || depth > kMaxDepth) return std::nullopt;
  switch (ast::expression_kind(expression)) {
    case ast::ExpressionKind::Literal:
      return literal_value(expression);
    case ast::ExpressionKind::Parenthesized:
      return evaluate_at(expression.named_child(0), depth + 1);
    case ast::ExpressionKind::Binary:
      return binary(expression, depth);
    case ast::ExpressionKind::Unary:
      return unary(expression, depth);
    case ast::ExpressionKind::Identifier:
    case ast::ExpressionKind::Member:
      return resolver_ ? resolver_(expression) : std::nullopt;
    case ast::ExpressionKind::Call:
      return call(expression, depth);
    default:
      return std::nullopt;
  }
}

std::optional<ConstValue> ConstEvaluator::unary(SyntaxNode expression, int depth) {
  auto operand = evaluate_at(expression.child_by_field("operand"), depth + 1);
  if (!operand) return std::nullopt;
  const std::string op = ast::operator_of(expression);
  if (op == "-") {
    if (operand->kind == ConstValue::Kind::Integer || operand->kind == ConstValue::Kind::Duration) {
      operand->integer = -operand->integer;
      return operand;
    }
    if (operand->kind == ConstValue::Kind::Real) return ConstValue::of_real(-operand->real);
    return std::nullopt;
  }
  if (op == "+") return operand->is_number() ? operand : std::nullopt;
  if (op == "NOT") {
    if (operand->kind == ConstValue::Kind::Bool) return ConstValue::of_bool(operand->integer == 0);
    return std::nullopt;  // bitwise NOT needs the operand's width: left to the type checker
  }
  return std::nullopt;
}

std::optional<ConstValue> ConstEvaluator::binary(SyntaxNode expression, int depth) {
  auto left = evaluate_at(expression.child_by_field("left"), depth + 1);
  if (!left) return std::nullopt;
  auto right = evaluate_at(expression.child_by_field("right"), depth + 1);
  if (!right) return std::nullopt;
  const std::string op = ast::operator_of(expression);
  if (op == "=" || op == "<>" || op == "<" || op == "<=" || op == ">" || op == ">=") return compare(*left, *right, op);
  if (op == "AND" || op == "&" || op == "OR" || op == "XOR" || op == "AND_THEN" || op == "OR_ELSE") {
    if (left->kind != right->kind || (left->kind != ConstValue::Kind::Bool && left->kind != ConstValue::Kind::Integer)) {
      return std::nullopt;
    }
    ConstValue out = *left;
    if (op == "OR" || op == "OR_ELSE") {
      out.integer = left->integer | right->integer;
    } else if (op == "XOR") {
      out.integer = left->integer ^ right->integer;
    } else {
      out.integer = left->integer & right->integer;
    }
    return out;
  }
  const bool integers = (left->kind == ConstValue::Kind::Integer || left->kind == ConstValue::Kind::Duration) &&
                        right->kind == ConstValue::Kind::Integer;
  if ((op == "/" || op == "MOD") && right->is_number() && right->as_real() == 0) {
    if (problem_.kind == ConstEvalProblem::Kind::None) problem_ = {ConstEvalProblem::Kind::DivisionByZero, expression};
    return std::nullopt;
  }
  if (integers || (left->kind == ConstValue::Kind::Duration && right->kind == ConstValue::Kind::Duration)) {
    ConstValue out = *left;
    if (right->kind == ConstValue::Kind::Duration && left->kind == ConstValue::Kind::Integer) return std::nullopt;
    const __int128 a = left->integer, b = right->integer;
    if (op == "+") {
      out.integer = a + b;
    } else if (op == "-") {
      out.integer = a - b;
    } else if (op == "*") {
      out.integer = a * b;
    } else if (op == "/") {
      out.integer = a / b;  // truncation toward zero, as IEC integer division
    } else if (op == "MOD") {
      out.integer = a % b;
    } else if (op == "**") {
      return ConstValue::of_real(std::pow(static_cast<double>(a), static_cast<double>(b)));
    } else {
      return std::nullopt;
    }
    return out;
  }
  if (left->is_number() && right->is_number()) {
    const double a = left->as_real(), b = right->as_real();
    if (op == "+") return ConstValue::of_real(a + b);
    if (op == "-") return ConstValue::of_real(a - b);
    if (op == "*") return ConstValue::of_real(a * b);
    if (op == "/") return ConstValue::of_real(a / b);
    if (op == "**") return ConstValue::of_real(std::pow(a, b));
  }
  return std::nullopt;
}

std::optional<ConstValue> ConstEvaluator::call(SyntaxNode expression, int depth) {
  // Conversions of constants keep their value for the purposes rung needs (bounds, labels):
  // INT_TO_DINT(5), TO_UINT(3), DINT#... ; anything else is not constant.
  SyntaxNode function = expression.child_by_field("function");
  SyntaxNode arguments = expression.child_by_field("arguments");
  if (!function || !arguments || function.kind() != "identifier") return std::nullopt;
  const std::string name = upper_name(function.text());
  if (name.find("_TO_") == std::string::npos && !name.starts_with("TO_")) return std::nullopt;
  if (name.find("REAL") != std::string::npos || name.find("STRING") != std::string::npos ||
      name.find("TIME") != std::string::npos || name.find("BOOL") != std::string::npos) {
    return std::nullopt;
  }
  std::vector<SyntaxNode> args = arguments.children_of_kind("argument");
  if (args.size() != 1) return std::nullopt;
  auto value = evaluate_at(args[0].child_by_field("value"), depth + 1);
  if (!value || value->kind != ConstValue::Kind::Integer) return std::nullopt;
  return value;
}

}  // namespace rung::check
