// The semantic group: rules that need expression types and constant values (BodyChecker), and the
// project-wide ones that follow writes across POUs and tasks. The rules live in semantic_*.cpp.
#include "checker/lint/rule_groups.hpp"
#include "checker/lint/semantic_rules.hpp"

namespace rung::lint {

void add_semantic_rules(std::vector<Rule>& rules) {
  rules.push_back({"L011", "output-written-in-several-places", true, false, semantic::check_output_writes});
  rules.push_back({"L012", "global-written-by-several-tasks", true, false, semantic::check_task_writes});
  rules.push_back({"L039", "constant-condition", true, false, semantic::check_constant_conditions});
  rules.push_back({"L040", "float-equality", true, false, semantic::check_float_equality});
  rules.push_back({"L041", "enum-case-incomplete", true, false, semantic::check_enum_case});
  rules.push_back({"L051", "pointer-arithmetic", true, false, semantic::check_pointer_arithmetic});
  rules.push_back({"L052", "loop-variable-after-loop", true, false, semantic::check_loop_variable_after});
  // Off by default: every widening (INT to DINT, INT to REAL) is legal and usually meant; projects
  // that want each type change written out switch it on.
  rules.push_back({"L053", "implicit-conversion", false, false, semantic::check_implicit_conversions});
}

}  // namespace rung::lint
