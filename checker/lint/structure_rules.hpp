// The checks of the structure rule group (addresses, size and nesting, layout, literals),
// registered by rules_structure.cpp.
#pragma once

#include "checker/lint/lint_rule.hpp"

namespace rung::lint::structure {

// structure_addresses.cpp
void check_direct_address(LintContext& context);  // L010

// structure_metrics.cpp
void check_nesting(LintContext& context);          // L020
void check_complexity(LintContext& context);       // L021
void check_pou_length(LintContext& context);       // L022
void check_parameter_count(LintContext& context);  // L023

// structure_layout.cpp
void check_statements_per_line(LintContext& context);  // L024

// structure_numbers.cpp
void check_magic_number(LintContext& context);  // L050

}  // namespace rung::lint::structure
