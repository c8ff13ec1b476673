#include "checker/lint/rule_groups.hpp"

namespace rung::lint {

void add_structure_rules(std::vector<Rule>& rules) { static_cast<void>(rules); }

}  // namespace rung::lint
