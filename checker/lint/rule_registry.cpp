#include <algorithm>

#include "checker/lint/rule_groups.hpp"
#include "checker/symbols/names.hpp"

namespace rung::lint {
namespace {

std::vector<Rule> build_registry() {
  std::vector<Rule> rules;
  add_naming_rules(rules);
  add_structure_rules(rules);
  add_flow_rules(rules);
  add_usage_rules(rules);
  add_semantic_rules(rules);
  std::sort(rules.begin(), rules.end(), [](const Rule& a, const Rule& b) { return a.code < b.code; });
  return rules;
}

}  // namespace

std::span<const Rule> all_rules() {
  static const std::vector<Rule> rules = build_registry();
  return rules;
}

const Rule* find_rule(std::string_view code_or_name) {
  for (const Rule& rule : all_rules()) {
    if (check::names_equal(rule.code, code_or_name) || check::names_equal(rule.name, code_or_name)) return &rule;
  }
  return nullptr;
}

}  // namespace rung::lint
