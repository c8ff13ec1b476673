// Checks Instruction List bodies. IL computes in one register, the current result (CR): LD sets
// it, operators combine it with their operand, ST copies it out. The checker follows the CR's type
// through the instructions of a body in order, the way a compiler does (IEC 61131-3 2nd ed.
// 3.2; OpenPCS manual, which names the rules S5009/S5010/S5024/S5027), and reuses BodyChecker
// for everything an operand is (names, types, calls, conversions).
//
// The CR is undefined at the start of a body, after a label (a jump may arrive with any value),
// after JMP, CAL and RET; using it there is E801. ST, S and R leave it unchanged (OpenPCS:
// "multiple ST may follow one another").
#pragma once

#include <string>
#include <unordered_set>
#include <vector>

#include "checker/semantic/body_checker.hpp"

namespace rung::check {

class IlChecker {
 public:
  IlChecker(BodyChecker& body, const ProjectModel& model, const Symbol& pou);

  // Checks one il_body. A transition's code ends with its condition in the CR, which must be BOOL.
  void check(SyntaxNode il_body, bool transition = false);
  // The value of an il_expression, `(a ADD b)` as a CAL argument (OpenPCS S5034).
  ExprInfo value_of(SyntaxNode il_expression);

 private:
  struct CurrentResult {
    bool defined = false;
    ExprInfo info;
  };

  void collect_labels(SyntaxNode node);
  // The instructions and labels directly below `parent`; `depth` counts open parentheses.
  void check_sequence(SyntaxNode parent, int depth, bool load_may_open);
  void check_instruction(SyntaxNode instruction, int depth, bool first_in_parentheses);
  void check_deferred(SyntaxNode instruction, SyntaxNode op_node, int depth);
  void check_function_call(SyntaxNode instruction, SyntaxNode op_node, const std::vector<SyntaxNode>& operands);
  void check_cal(SyntaxNode operand);
  bool check_fb_input(SyntaxNode op_node, const std::vector<SyntaxNode>& operands);
  void check_jump_label(SyntaxNode label);

  // Combines the CR with an operand by an operator that keeps the CR (ADD, AND, GT ...).
  void apply(std::string_view op_name, const ExprInfo& operand, SyntaxNode operand_node, TextRange range);
  // The value an operand stands for (a type name or namespace is not a value: E004).
  ExprInfo operand_value(SyntaxNode operand);
  // Reports E801 when the CR is undefined; afterwards it counts as defined (of unknown type), so
  // that one missing LD gives one diagnostic.
  void require_result(SyntaxNode op_node);
  // Reports E103 when the CR is not BOOL (conditional JMP/CAL/RET, S, R).
  void require_bool_result(SyntaxNode op_node);
  bool expect_operands(SyntaxNode op_node, const std::vector<SyntaxNode>& operands, size_t count);
  void undefine() { current_ = CurrentResult{.info = ExprInfo{.type = model_.types().unknown()}}; }

  BodyChecker& body_;
  const ProjectModel& model_;
  const Symbol& pou_;
  CurrentResult current_;
  std::unordered_set<std::string> labels_;  // upper-case
  SyntaxNode left_by_;                      // the JMP or RET just before, while nothing else came
  bool misplaced_in_parentheses_ = false;   // E802 reported inside the open parentheses
};

}  // namespace rung::check
