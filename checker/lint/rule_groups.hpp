// The groups of lint rules, one file each (rules_<group>.cpp). rule_registry.cpp collects them.
#pragma once

#include <vector>

#include "checker/lint/lint_rule.hpp"

namespace rung::lint {

void add_naming_rules(std::vector<Rule>& rules);      // L001-L006 names; L060-L062 comments
void add_structure_rules(std::vector<Rule>& rules);   // L010 addresses; L020-L024 size and nesting; L050
void add_flow_rules(std::vector<Rule>& rules);        // L030-L038, L042 statements and conditions
void add_usage_rules(std::vector<Rule>& rules);       // L070-L079 unused, unread, unwritten
void add_semantic_rules(std::vector<Rule>& rules);    // L011, L012, L039-L041, L051-L053 typed rules

}  // namespace rung::lint
