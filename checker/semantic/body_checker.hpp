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

// One argument of a call: `name := value`, `name => value`, or a value by position. IL passes
// the current result as an argument that has no syntax node of its own: `typed` holds its type
// and `value` the instruction it stands for (for the messages).
struct CallArgument {
  SyntaxNode node;   // the whole argument
  SyntaxNode name;   // the formal parameter; null for a positional argument
  SyntaxNode value;  // the actual value, or the variable an output goes to
  bool output = false;
  std::optional<ExprInfo> typed;
};

// The arguments of an argument_list node (OpenPCS outputs after '|' included).
std::vector<CallArgument> call_arguments(SyntaxNode argument_list);

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
  void check_one_generic_type(const Symbol* callee, const std::vector<ExprInfo>& arguments,
                              const std::vector<SyntaxNode>& where);
  const Type* bind_generic_result(const Symbol* callee, const std::vector<ExprInfo>& arguments);

  // statement_checker.cpp
  void check_body(SyntaxNode body);  // a statement list, IL body or SFC network
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

  // Pieces of expressions and statements for bodies that are not ST (the IL checker).
  // The result of `op operand` / `left op right` for typed operands (E104 when undefined);
  // `shown` is the operator as written, for messages (IL: ADD for '+').
  ExprInfo unary_result(std::string_view op, const ExprInfo& operand, TextRange range);
  ExprInfo binary_result(std::string_view op, const ExprInfo& left, const ExprInfo& right, SyntaxNode right_node,
                         TextRange range, std::string_view shown = {});
  // Whether `target` may be written (E401/E402/E403 when not, reported at `where`).
  bool check_assignment_target(const ExprInfo& target, SyntaxNode where);
  // A call of `callee` with these arguments; `call` is where the call is written.
  ExprInfo check_arguments(const Symbol* callee, bool instance_call, const std::vector<CallArgument>& arguments,
                           SyntaxNode call, int depth);

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
