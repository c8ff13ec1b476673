// The flow rule group: statements that do nothing, branches and conditions that repeat or can be
// simpler, loops that never end. The checks live in flow_*.cpp (see flow_rules.hpp).
#include "checker/lint/flow_rules.hpp"
#include "checker/lint/rule_groups.hpp"

namespace rung::lint {

void add_flow_rules(std::vector<Rule>& rules) {
  // code, name (the registry's title), enabled by default, has a fix, check
  rules.push_back({"L030", "case-without-else", true, false, flow::check_case_without_else});
  rules.push_back({"L031", "empty-statement", true, true, flow::check_empty_statement});
  rules.push_back({"L032", "empty-branch", true, false, flow::check_empty_branch});
  rules.push_back({"L033", "duplicate-condition", true, false, flow::check_duplicate_condition});
  rules.push_back({"L034", "identical-branches", true, false, flow::check_identical_branches});
  rules.push_back({"L035", "self-assignment", true, true, flow::check_self_assignment});
  rules.push_back({"L036", "double-negation", true, true, flow::check_double_negation});
  rules.push_back({"L037", "compare-with-bool-literal", true, true, flow::check_compare_with_bool_literal});
  rules.push_back({"L038", "if-to-assignment", true, true, flow::check_if_to_assignment});
  rules.push_back({"L042", "endless-loop", true, false, flow::check_endless_loop});
}

}  // namespace rung::lint
