// The checks of the flow rule group (statements and conditions), registered by rules_flow.cpp.
#pragma once

#include "checker/lint/lint_rule.hpp"

namespace rung::lint::flow {

// flow_branches.cpp
void check_case_without_else(LintContext& context);    // L030
void check_empty_branch(LintContext& context);         // L032
void check_duplicate_condition(LintContext& context);  // L033
void check_identical_branches(LintContext& context);   // L034

// flow_statements.cpp
void check_empty_statement(LintContext& context);  // L031
void check_self_assignment(LintContext& context);  // L035
void check_endless_loop(LintContext& context);     // L042

// flow_simplify.cpp
void check_double_negation(LintContext& context);            // L036
void check_compare_with_bool_literal(LintContext& context);  // L037
void check_if_to_assignment(LintContext& context);           // L038

}  // namespace rung::lint::flow
