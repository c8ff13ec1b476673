#include "checker/project/config_sections.hpp"

namespace rung::project {

// Filled in by the [lint] work (issue 4): every key is unknown until then.
void read_lint_section(const toml::node& node, LintSettings& settings, ConfigReport& report) {
  static_cast<void>(settings);
  const toml::table* table = node.as_table();
  if (!table) return report.bad_value(node, "[lint] must be a table");
  for (auto&& [key, value] : *table) report.unknown_key(key, "[lint]", "");
}

}  // namespace rung::project
