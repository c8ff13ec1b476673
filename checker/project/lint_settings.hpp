// rung.toml [lint]: which lint rules run, how severe they are, naming patterns and thresholds.
// Plain data filled by checker/project/lint_settings.cpp; the linter (checker/lint/) resolves
// rule names and codes and reports settings it does not know.
#pragma once

#include <cstdint>
#include <map>
#include <string>

namespace rung::project {

struct LintSettings {
  // [lint.rules]: a rule's code or name (e.g. "L030" or "case-without-else") -> "off", "on" (the
  // rule's default severity), "error", "warning", "info" or "hint". Keys are kept as written.
  std::map<std::string, std::string> rules;
  // [lint.naming]: naming patterns, e.g. BOOL = "b", FUNCTION_BLOCK = "FB_", global = "g_".
  std::map<std::string, std::string> naming;
  // [lint.thresholds]: e.g. max_nesting = 4, max_cyclomatic_complexity = 15.
  std::map<std::string, int64_t> thresholds;
  // [lint] baseline = "lint-baseline.json": findings listed there are not reported (relative to
  // the project root). Empty: no baseline.
  std::string baseline;
  // Byte offsets in rung.toml of each key above (for messages about unknown rules or patterns).
  std::map<std::string, uint32_t> key_offsets;
};

}  // namespace rung::project
