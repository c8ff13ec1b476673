#include <fmt/format.h>

#include <array>
#include <vector>

#include "checker/project/config_sections.hpp"
#include "checker/symbols/names.hpp"
#include "parser/diagnostic_codes.hpp"

namespace rung::project {
namespace {

constexpr std::array<std::string_view, 6> kRuleLevels{"off", "on", "error", "warning", "info", "hint"};

// A lint rule's code or name is a row "L..." of the diagnostic registry: the registry is filled
// at compile time, so rung.toml is checked the same way whichever rules are built in.
bool is_lint_code(const DiagnosticCodeInfo& info) {
  return !info.code.empty() && info.code[0] == 'L';
}

bool is_rule_key(std::string_view key) {
  for (const DiagnosticCodeInfo& info : all_diagnostic_codes()) {
    if (is_lint_code(info) && (check::names_equal(info.code, key) || check::names_equal(info.title, key))) return true;
  }
  return false;
}

// The text after "known keys: " in the P002 help.
std::string rule_key_help(std::string_view key) {
  std::vector<std::string_view> candidates;
  for (const DiagnosticCodeInfo& info : all_diagnostic_codes()) {
    if (!is_lint_code(info)) continue;
    candidates.push_back(info.code);
    candidates.push_back(info.title);
  }
  std::string help = "rule codes (L030) or names (case-without-else), see 'rung lint --list-rules'";
  std::string_view near = check::closest_name(key, candidates);
  if (!near.empty()) help += fmt::format("; did you mean '{}'?", near);
  return help;
}

void read_rules(const toml::table& table, LintSettings& settings, ConfigReport& report) {
  for (auto&& [key, value] : table) {
    const std::string name(key.str());
    if (!is_rule_key(name)) {
      report.unknown_key(key, "[lint.rules]", rule_key_help(name));
      continue;
    }
    std::optional<std::string> level = value.is_string() ? value.value<std::string>() : std::nullopt;
    bool known_level = false;
    for (std::string_view candidate : kRuleLevels) known_level = known_level || (level && *level == candidate);
    if (!known_level) {
      report.bad_value(
          value, fmt::format("rule '{}' must be \"off\", \"on\", \"error\", \"warning\", \"info\" or \"hint\"", name),
          fmt::format("{} = \"off\"", name));
      continue;
    }
    settings.rules[name] = *level;
    settings.key_offsets["rules." + name] = report.offset_of(key.source().begin);
  }
}

// [lint.naming] and [lint.thresholds] keys belong to the rules that read them (checker/lint/);
// any key is accepted here, only the kind of value is checked.
void read_naming(const toml::table& table, LintSettings& settings, ConfigReport& report) {
  for (auto&& [key, value] : table) {
    const std::string name(key.str());
    if (!value.is_string()) {
      report.bad_value(value, fmt::format("naming pattern '{}' must be a string", name),
                       fmt::format("{} = \"b\"", name));
      continue;
    }
    settings.naming[name] = *value.value<std::string>();
    settings.key_offsets["naming." + name] = report.offset_of(key.source().begin);
  }
}

void read_thresholds(const toml::table& table, LintSettings& settings, ConfigReport& report) {
  for (auto&& [key, value] : table) {
    const std::string name(key.str());
    std::optional<int64_t> number = value.is_integer() ? value.value<int64_t>() : std::nullopt;
    if (!number || *number < 0) {
      report.bad_value(value, fmt::format("threshold '{}' must be a whole number, 0 or more", name),
                       fmt::format("{} = 4", name));
      continue;
    }
    settings.thresholds[name] = *number;
    settings.key_offsets["thresholds." + name] = report.offset_of(key.source().begin);
  }
}

}  // namespace

void read_lint_section(const toml::node& node, LintSettings& settings, ConfigReport& report) {
  const toml::table* table = node.as_table();
  if (!table) return report.bad_value(node, "[lint] must be a table");
  for (auto&& [key, value] : *table) {
    std::string_view k = key.str();
    const toml::table* sub = value.as_table();
    if (k == "baseline") {
      if (value.is_string()) {
        settings.baseline = *value.value<std::string>();
        settings.key_offsets["baseline"] = report.offset_of(key.source().begin);
      } else {
        report.bad_value(value, "'baseline' must be a file name relative to rung.toml",
                         "baseline = \"lint-baseline.json\"");
      }
    } else if (k == "rules" || k == "naming" || k == "thresholds") {
      if (!sub) {
        report.bad_value(value, fmt::format("[lint.{}] must be a table", k));
      } else if (k == "rules") {
        read_rules(*sub, settings, report);
      } else if (k == "naming") {
        read_naming(*sub, settings, report);
      } else {
        read_thresholds(*sub, settings, report);
      }
    } else {
      report.unknown_key(key, "[lint]", "baseline, rules, naming, thresholds");
    }
  }
}

}  // namespace rung::project
