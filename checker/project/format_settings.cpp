#include <fmt/format.h>

#include "checker/project/config_sections.hpp"

namespace rung::project {

// Filled in by the [format] work (issue 4): every key is unknown until then.
bool apply_format_preset(std::string_view preset, FormatSettings& settings) {
  if (preset != "codesys") return false;
  settings = FormatSettings{};
  return true;
}

void read_format_section(const toml::node& node, FormatSettings& settings, ConfigReport& report) {
  static_cast<void>(settings);
  const toml::table* table = node.as_table();
  if (!table) return report.bad_value(node, "[format] must be a table");
  for (auto&& [key, value] : *table) report.unknown_key(key, "[format]", "");
}

}  // namespace rung::project
