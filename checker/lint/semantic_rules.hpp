// The semantic lint rules (rules_semantic.cpp registers them): rules that need what expressions
// are (their types, constant values, the declarations they name) and, for L011/L012, the whole
// project. One file per rule or pair of related rules.
#pragma once

#include "checker/lint/lint_rule.hpp"

namespace rung::lint::semantic {

void check_output_writes(LintContext& context);         // L011 semantic_outputs.cpp
void check_task_writes(LintContext& context);           // L012 semantic_tasks.cpp
void check_constant_conditions(LintContext& context);   // L039 semantic_conditions.cpp
void check_float_equality(LintContext& context);        // L040 semantic_float_equality.cpp
void check_enum_case(LintContext& context);             // L041 semantic_enum_case.cpp
void check_pointer_arithmetic(LintContext& context);    // L051 semantic_pointers.cpp
void check_loop_variable_after(LintContext& context);   // L052 semantic_loop_counter.cpp
void check_implicit_conversions(LintContext& context);  // L053 semantic_conversions.cpp

}  // namespace rung::lint::semantic
