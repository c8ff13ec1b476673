#include "checker/lint/naming_rules.hpp"
#include "checker/lint/rule_groups.hpp"

namespace rung::lint {

void add_naming_rules(std::vector<Rule>& rules) {
  // Naming conventions differ between companies: the prefix rules only run when a project asks.
  rules.push_back({"L001", "variable-prefix", false, false, naming::check_variable_prefix});
  rules.push_back({"L002", "scope-prefix", false, false, naming::check_scope_prefix});
  rules.push_back({"L003", "pou-prefix", false, false, naming::check_pou_prefix});
  rules.push_back({"L004", "type-prefix", false, false, naming::check_type_prefix});
  rules.push_back({"L005", "name-too-short", false, false, naming::check_name_too_short});
  rules.push_back({"L006", "name-case-mismatch", true, true, naming::check_name_case});
  rules.push_back({"L060", "missing-pou-comment", true, false, naming::check_pou_comment});
  rules.push_back({"L061", "todo-comment", false, false, naming::check_todo_comment});
  rules.push_back({"L062", "commented-out-code", true, false, naming::check_commented_code});
}

}  // namespace rung::lint
