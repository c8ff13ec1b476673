// Checks the bodies (statements and expressions) of one POU against the linked ProjectModel:
// names, types of expressions, assignments, conditions, calls, loops, CASE labels, jumps.
// Split over files by concern: expression_typer.cpp (what an expression is), call_checker.cpp
// (calls and their arguments), statement_checker.cpp (statements).
//
// Tolerance: an expression whose type cannot be known gets the Unknown type, which converts to
// and from everything silently, so one missing declaration gives one diagnostic, not a cascade.
#pragma once

#include <optional>
#include <string>
#include <unordered_set>
#include <vector>

#include "checker/constant/const_value.hpp"
#include "checker/project_model.hpp"
#include "checker/types/conversions.hpp"

namespace rung::check {

// What the checker learned about an expression.
struct ExprInfo {
  const Type* type = nullptr;        // never null after typing
  const Symbol* symbol = nullptr;    // the declaration it names, if any
  std::optional<ConstValue> value;   // its value when it is made of literals only
  bool untyped_literal = false;      // a literal without TYPE#: takes the type its context needs
  bool based_literal = false;        // 16#.., 2#..: a bit pattern (fits same-width signed types)
  bool assignable = false;           // may stand left of :=
  bool names_type = false;           // the expression is a type name (E_Color in E_Color.Red)
  bool names_namespace = false;      // a library namespace or GVL qualifier
  bool read_only_output = false;     // an output of another FB instance
};

class BodyChecker {
 public:
  BodyChecker(const ProjectModel& model, const Symbol& pou, std::vector<Diagnostic>& out);

  // Checks the POU's own body; members (methods, actions) are separate BodyCheckers.
  void check();

  // Types one expression (also for the language server: hover, completion).
  ExprInfo type_of(SyntaxNode expression);

 private:
  // expression_typer.cpp
  ExprInfo type_expression(SyntaxNode expression, int depth);
  ExprInfo type_identifier(SyntaxNode identifier);
  ExprInfo type_member(SyntaxNode expression, int depth);
  ExprInfo type_index(SyntaxNode expression, int depth);
  ExprInfo type_dereference(SyntaxNode expression, int depth);
  ExprInfo type_binary(SyntaxNode expression, int depth);
  ExprInfo type_unary(SyntaxNode expression, int depth);
  ExprInfo type_literal(SyntaxNode literal);
  ExprInfo info_for_symbol(const Symbol* symbol, SyntaxNode where);
  const Type* literal_type(const ConstValue& value, bool based) const;
  void report_undeclared(SyntaxNode name);

  // call_checker.cpp
  ExprInfo type_call(SyntaxNode call, int depth);
  ExprInfo check_call_arguments(SyntaxNode call, const Symbol* callee, bool instance_call, int depth);
  const Type* bind_generic_result(const Symbol* callee, const std::vector<ExprInfo>& arguments);

  // statement_checker.cpp
  void check_statement_list(SyntaxNode list);
  void check_statement(SyntaxNode statement);
  void check_assignment(SyntaxNode statement);
  void check_condition(SyntaxNode condition);
  void check_case(SyntaxNode statement);
  void check_for(SyntaxNode statement);
  void check_unreachable(SyntaxNode list);
  void collect_labels(SyntaxNode list);
  bool inside(const Symbol& pou) const;
  const Symbol* enum_value_for(const Type* target, SyntaxNode value) const;  // `pou` is the checked POU or one of its owners

 public:
  // Shared helpers (also used by declaration checks).
  // Reports when a value of `value` cannot be stored in `target` (E101/E105/E102/E106).
  void check_conversion(const ExprInfo& value, const Type* target, SyntaxNode where);
  void report(std::string_view code, std::string message, TextRange range, std::string help = {},
              std::vector<DiagnosticLabel> labels = {});

 private:
  const ProjectModel& model_;
  const Symbol& pou_;
  std::vector<Diagnostic>& out_;
  TypeArena& types_;
  int loop_depth_ = 0;
  std::vector<const Symbol*> for_variables_;  // FOR variables of the loops we are inside
  std::unordered_set<std::string> labels_;     // upper-case jump labels of the body
  std::unordered_set<std::string> sfc_names_;  // steps and actions of an SFC body (step.x, ...)
};

}  // namespace rung::check
