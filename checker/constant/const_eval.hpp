// Constant evaluation of expressions: literals, arithmetic, comparisons, logic and names the
// caller can resolve (CONSTANT variables, enum values). Used for array bounds, STRING(n),
// CASE labels, subrange limits and the checks that need a value (division by zero, overflow).
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "checker/constant/const_value.hpp"
#include "parser/syntax_tree.hpp"

namespace rung::check {

struct ConstEvalProblem {
  enum class Kind { None, DivisionByZero } kind = Kind::None;
  SyntaxNode where;
};

class ConstEvaluator {
 public:
  // Resolves an identifier / qualified name / member expression to its constant value, if any.
  using NameResolver = std::function<std::optional<ConstValue>(SyntaxNode name)>;
  explicit ConstEvaluator(NameResolver resolver) : resolver_(std::move(resolver)) {}

  std::optional<ConstValue> evaluate(SyntaxNode expression);
  // The first problem met by the last evaluate() (a constant division by zero).
  const ConstEvalProblem& problem() const { return problem_; }

 private:
  std::optional<ConstValue> evaluate_at(SyntaxNode expression, int depth);
  std::optional<ConstValue> binary(SyntaxNode expression, int depth);
  std::optional<ConstValue> unary(SyntaxNode expression, int depth);
  std::optional<ConstValue> call(SyntaxNode expression, int depth);

  NameResolver resolver_;
  ConstEvalProblem problem_;
};

// A literal node's value (integer, real, bool, string, duration, typed literals); no names.
std::optional<ConstValue> literal_value(SyntaxNode literal);

}  // namespace rung::check
