#include "checker/project/project_config.hpp"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <set>
#include <sstream>

#include "checker/project/config_sections.hpp"
#include "parser/diagnostic_codes.hpp"
#include "parser/file_walk.hpp"
#include "parser/keywords.hpp"
#include "parser/source/line_index.hpp"

namespace rung::project {
namespace {

using keywords::upper;

// Collects diagnostics with positions taken from toml++'s 1-based line/column.
class ConfigReader final : public ConfigReport {
 public:
  ConfigReader(LoadedConfig& out) : out_(out), lines_(out.text) {}

  void read() {
    toml::table table;
    try {
      table = toml::parse(out_.text, out_.config.config_file ? out_.config.config_file->string() : "rung.toml");
    } catch (const toml::parse_error& e) {
      add(codes::kConfigSyntax, Severity::Error, e.source().begin, std::string(e.description()),
          "fix the TOML syntax; see docs/rung-toml.md");
      return;
    }
    for (auto&& [key, node] : table) {
      std::string_view k = key.str();
      if (k == "project") {
        read_project(node);
      } else if (k == "defines") {
        read_defines(node);
      } else if (k == "diagnostics") {
        read_diagnostics(node);
      } else if (k == "target") {
        read_target(node);
      } else if (k == "format") {
        read_format_section(node, out_.config.format, *this);
      } else if (k == "lint") {
        read_lint_section(node, out_.config.lint, *this);
      } else {
        unknown(key, "top-level table", "project, defines, diagnostics, target, format, lint");
      }
    }
  }

 private:
  uint32_t offset_of(const toml::source_position& p) const override {
    if (!p) return 0;
    return lines_.offset_of_char(p.line - 1, p.column - 1);
  }

  void add(std::string_view code, Severity severity, const toml::source_position& at, std::string message,
           std::string help = {}) {
    Diagnostic d;
    d.code = std::string(code);
    d.severity = severity;
    uint32_t o = offset_of(at);
    d.range = {o, o};
    d.message = std::move(message);
    d.help = std::move(help);
    out_.diagnostics.push_back(std::move(d));
  }

  void unknown_key(const toml::key& key, std::string_view where, std::string_view known) override {
    unknown(key, where, known);
  }
  void unknown(const toml::key& key, std::string_view where, std::string_view known) {
    add(codes::kConfigUnknownKey, Severity::Warning, key.source().begin,
        fmt::format("unknown key '{}' in {}", key.str(), where), fmt::format("known keys: {}", known));
  }

  void bad_value(const toml::node& node, std::string message, std::string help = {}) override {
    add(codes::kConfigBadValue, Severity::Error, node.source().begin, std::move(message), std::move(help));
  }

  std::vector<std::string> string_list(const toml::node& node, std::string_view key) {
    std::vector<std::string> out;
    if (const toml::array* array = node.as_array()) {
      for (const toml::node& item : *array) {
        if (auto s = item.value<std::string>()) {
          out.push_back(*s);
        } else {
          bad_value(item, fmt::format("'{}' must list strings", key));
        }
      }
    } else if (auto s = node.value<std::string>()) {
      out.push_back(*s);
    } else {
      bad_value(node, fmt::format("'{}' must be a list of strings", key), fmt::format("{} = [\"src\"]", key));
    }
    return out;
  }

  void read_project(const toml::node& node) {
    const toml::table* t = node.as_table();
    if (!t) return bad_value(node, "[project] must be a table");
    ProjectConfig& c = out_.config;
    for (auto&& [key, value] : *t) {
      std::string_view k = key.str();
      if (k == "name") {
        if (auto s = value.value<std::string>())
          c.name = *s;
        else
          bad_value(value, "'name' must be a string");
      } else if (k == "profile") {
        auto s = value.value<std::string>();
        auto p = s ? parse_profile(*s) : std::nullopt;
        if (p)
          c.profile = *p;
        else
          bad_value(value, "'profile' must be \"codesys\", \"iec\" or \"twincat\"", "profile = \"codesys\"");
      } else if (k == "sources") {
        c.sources = string_list(value, k);
      } else if (k == "exclude") {
        c.exclude = string_list(value, k);
      } else if (k == "libraries") {
        for (const std::string& lib : string_list(value, k)) c.libraries.push_back(c.root / lib);
      } else {
        unknown(key, "[project]", "name, profile, sources, exclude, libraries");
      }
    }
  }

  void read_defines(const toml::node& node) {
    const toml::table* t = node.as_table();
    if (!t) return bad_value(node, "[defines] must be a table");
    for (auto&& [key, value] : *t) {
      // Ask the node for its own kind: value<bool>() would also convert numbers.
      if (value.is_boolean()) {
        if (*value.value<bool>()) out_.config.defines[std::string(key.str())] = "";
      } else if (value.is_string()) {
        out_.config.defines[std::string(key.str())] = *value.value<std::string>();
      } else if (value.is_integer()) {
        out_.config.defines[std::string(key.str())] = std::to_string(*value.value<int64_t>());
      } else {
        bad_value(value, fmt::format("define '{}' must be true/false, a number or a string", key.str()));
      }
    }
  }

  void read_diagnostics(const toml::node& node) {
    const toml::table* t = node.as_table();
    if (!t) return bad_value(node, "[diagnostics] must be a table");
    for (auto&& [key, value] : *t) {
      std::string code = upper(key.str());
      auto s = value.value<std::string>();
      std::optional<std::optional<Severity>> level;
      if (s == "error")
        level = Severity::Error;
      else if (s == "warning")
        level = Severity::Warning;
      else if (s == "info")
        level = Severity::Info;
      else if (s == "hint")
        level = Severity::Hint;
      else if (s == "off")
        level = std::optional<Severity>();
      if (!level) {
        bad_value(value,
                  fmt::format("severity of {} must be \"error\", \"warning\", \"info\", \"hint\" or \"off\"", code));
        continue;
      }
      if (!find_diagnostic_code(code)) {
        add(codes::kConfigUnknownKey, Severity::Warning, key.source().begin,
            fmt::format("unknown diagnostic code '{}'", code), "run 'rung explain' for the list of codes");
      }
      out_.config.severity_overrides[code] = *level;
    }
  }

  void read_target(const toml::node& node) {
    const toml::table* t = node.as_table();
    if (!t) return bad_value(node, "[target] must be a table");
    for (auto&& [key, value] : *t) {
      if (key.str() == "max_string_length") {
        auto n = value.value<int64_t>();
        if (n && *n >= 1 && *n <= 65535)
          out_.config.max_string_length = static_cast<uint32_t>(*n);
        else
          bad_value(value, "'max_string_length' must be a number from 1 to 65535");
      } else if (key.str() == "addressing") {
        auto mode = value.value<std::string>();
        if (mode && (*mode == "byte" || *mode == "word" || *mode == "byte-offset"))
          out_.config.addressing = *mode;
        else
          bad_value(value, "'addressing' must be \"byte\", \"word\" or \"byte-offset\"");
      } else {
        unknown(key, "[target]", "max_string_length, addressing");
      }
    }
  }

  LoadedConfig& out_;
  source::LineIndex lines_;
};

}  // namespace

std::string_view profile_name(Profile profile) {
  switch (profile) {
    case Profile::Codesys: return "codesys";
    case Profile::Iec: return "iec";
    case Profile::Twincat: return "twincat";
    case Profile::Openpcs: return "openpcs";
  }
  return "codesys";
}

std::optional<Profile> parse_profile(std::string_view name) {
  std::string n(name);
  for (char& c : n) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (n == "codesys") return Profile::Codesys;
  if (n == "iec") return Profile::Iec;
  if (n == "twincat") return Profile::Twincat;
  if (n == "openpcs") return Profile::Openpcs;
  return std::nullopt;
}

LoadedConfig parse_project_config(std::string text, const std::filesystem::path& folder) {
  LoadedConfig out;
  out.config.root = folder;
  out.config.name = std::filesystem::absolute(folder).lexically_normal().filename().string();
  if (out.config.name.empty()) out.config.name = std::filesystem::absolute(folder).parent_path().filename().string();
  out.text = std::move(text);
  ConfigReader reader(out);
  reader.read();
  sort_diagnostics(out.diagnostics);
  return out;
}

LoadedConfig load_project_config(const std::filesystem::path& folder) {
  std::filesystem::path file = folder / "rung.toml";
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) return parse_project_config("", folder);
  std::ifstream in(file, std::ios::binary);
  std::ostringstream buffer;
  buffer << in.rdbuf();
  LoadedConfig out = parse_project_config(buffer.str(), folder);
  out.config.config_file = file;
  return out;
}

std::optional<std::filesystem::path> find_project_root(const std::filesystem::path& start) {
  std::error_code ec;
  std::filesystem::path dir = std::filesystem::absolute(start, ec);
  if (!std::filesystem::is_directory(dir, ec)) dir = dir.parent_path();
  for (; !dir.empty(); dir = dir.parent_path()) {
    if (std::filesystem::is_regular_file(dir / "rung.toml", ec)) return dir;
    if (dir == dir.root_path()) break;
  }
  return std::nullopt;
}

bool glob_match(std::string_view pattern, std::string_view path) {
  // Recursive matcher; patterns and paths are short. '**/' also matches no folder at all.
  if (pattern.empty()) return path.empty();
  if (pattern.substr(0, 2) == "**") {
    std::string_view rest = pattern.substr(2);
    bool folders_only = !rest.empty() && rest[0] == '/';
    if (folders_only) rest.remove_prefix(1);
    for (size_t k = 0; k <= path.size(); ++k) {
      if (folders_only && k > 0 && path[k - 1] != '/') continue;
      if (glob_match(rest, path.substr(k))) return true;
    }
    return false;
  }
  if (pattern[0] == '*') {
    for (size_t k = 0; k <= path.size(); ++k) {
      if (glob_match(pattern.substr(1), path.substr(k))) return true;
      if (k < path.size() && path[k] == '/') break;
    }
    return false;
  }
  if (path.empty()) return false;
  if (pattern[0] == '?' ? path[0] == '/' : pattern[0] != path[0]) return false;
  return glob_match(pattern.substr(1), path.substr(1));
}

std::vector<std::filesystem::path> project_source_files(const ProjectConfig& config, std::vector<std::string>* errors) {
  std::vector<std::filesystem::path> inputs;
  for (const std::string& source : config.sources) inputs.push_back(config.root / source);
  WalkResult walk = collect_source_files(inputs);
  if (errors) errors->insert(errors->end(), walk.errors.begin(), walk.errors.end());
  std::vector<std::filesystem::path> files;
  for (const auto& file : walk.files) {
    std::string relative = file.lexically_relative(config.root).generic_string();
    bool excluded = std::any_of(config.exclude.begin(), config.exclude.end(),
                                [&](const std::string& pattern) { return glob_match(pattern, relative); });
    if (!excluded) files.push_back(file);
  }
  return files;
}

std::string default_config_text(std::string_view project_name) {
  return fmt::format(R"(# rung.toml: settings of this PLC project for rung (reference: docs/rung-toml.md in rung).
# Every setting is optional; the values below are the defaults.

[project]
name = "{}"
# Semantics where vendors disagree: "codesys" (default), "twincat" or "iec".
profile = "codesys"
# Files and folders that belong to the project, relative to this file. Folders are searched for
# .st .il .TcPOU .TcDUT .TcGVL .TcIO .EXP and PLCopen .xml files.
sources = ["."]
# Glob patterns (relative to this file) of files to leave out: * within a folder, ** across folders.
exclude = []
# Folders of declaration-only ST ("stubs") for libraries the project uses, e.g. vendor libraries.
libraries = []

[defines]
# Symbols for conditional compilation: {{IF defined(SIMULATION)}} ... {{END_IF}}
# SIMULATION = true

[diagnostics]
# Severity per diagnostic code: "error", "warning", "info", "hint" or "off".
# S008 = "off"

[target]
# Longest STRING(n) the target PLC allows.
max_string_length = 255
)",
                     project_name);
}

}  // namespace rung::project
