// Readers of the rung.toml sections that live in their own files ([format], [lint]). The main
// reader (project_config.cpp) hands each its table and a way to report mistakes.
#pragma once

#include <toml++/toml.h>

#include <string>
#include <string_view>

#include "checker/project/format_settings.hpp"
#include "checker/project/lint_settings.hpp"

namespace rung::project {

// Mistakes in rung.toml become P002 (unknown key, a warning) and P003 (bad value, an error).
class ConfigReport {
 public:
  virtual ~ConfigReport() = default;
  virtual void unknown_key(const toml::key& key, std::string_view where, std::string_view known) = 0;
  virtual void bad_value(const toml::node& node, std::string message, std::string help = {}) = 0;
  // The byte offset in rung.toml of a TOML position.
  virtual uint32_t offset_of(const toml::source_position& position) const = 0;
};

void read_format_section(const toml::node& node, FormatSettings& settings, ConfigReport& report);
void read_lint_section(const toml::node& node, LintSettings& settings, ConfigReport& report);

}  // namespace rung::project
