#include "checker/lint/rule_groups.hpp"
#include "checker/lint/structure_rules.hpp"

namespace rung::lint {

void add_structure_rules(std::vector<Rule>& rules) {
  rules.push_back({"L010", "direct-address-in-code", true, false, structure::check_direct_address});
  rules.push_back({"L020", "nesting-too-deep", true, false, structure::check_nesting});
  rules.push_back({"L021", "cyclomatic-complexity", true, false, structure::check_complexity});
  rules.push_back({"L022", "pou-too-long", true, false, structure::check_pou_length});
  rules.push_back({"L023", "too-many-parameters", true, false, structure::check_parameter_count});
  rules.push_back({"L024", "multiple-statements-per-line", true, true, structure::check_statements_per_line});
  rules.push_back({"L050", "magic-number", true, false, structure::check_magic_number});
}

}  // namespace rung::lint
