// The checks of the naming rule group (names and comments), registered by rules_naming.cpp.
#pragma once

#include <map>
#include <set>
#include <string>
#include <vector>

#include "checker/lint/lint_rule.hpp"

namespace rung::lint::naming {

// The variables whose names the naming rules judge: locals, parameters and globals declared in
// the file (naming_prefix_rules.cpp).
std::vector<const check::Symbol*> named_variables(const LintContext& context);

// Whether a variable is the counter of a FOR loop in the body of the POU that declares it: loop
// counters are short and unprefixed by tradition (naming_names.cpp). Remembers each POU's loops.
class LoopCounters {
 public:
  // `nodes`: the node list of the file whose variables are asked about.
  explicit LoopCounters(const NodeList& nodes) : nodes_(nodes) {}
  bool contains(const check::Symbol& variable);

 private:
  const NodeList& nodes_;
  std::map<const check::Symbol*, std::set<std::string>> by_pou_;
};

// naming_prefix_rules.cpp
void check_variable_prefix(LintContext& context);  // L001
void check_scope_prefix(LintContext& context);     // L002
void check_pou_prefix(LintContext& context);       // L003
void check_type_prefix(LintContext& context);      // L004

// naming_names.cpp
void check_name_too_short(LintContext& context);  // L005
void check_name_case(LintContext& context);       // L006

// naming_comments.cpp
void check_pou_comment(LintContext& context);     // L060
void check_todo_comment(LintContext& context);    // L061
void check_commented_code(LintContext& context);  // L062

}  // namespace rung::lint::naming
