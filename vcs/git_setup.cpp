#include "vcs/git_setup.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "vcs/git_repository.hpp"

namespace rung::vcs {
namespace {

namespace fs = std::filesystem;

constexpr const char* kComment = "# rung: PLC sources as ST text in diffs, merged on the syntax tree (rung git setup)";

fs::path global_attributes_file() {
  const char* xdg = std::getenv("XDG_CONFIG_HOME");
  if (xdg != nullptr && *xdg != '\0') return fs::path(xdg) / "git" / "attributes";
  const char* home = std::getenv("HOME");
  return fs::path(home != nullptr ? home : ".") / ".config" / "git" / "attributes";
}

}  // namespace

std::vector<std::string> git_attribute_lines() {
  std::vector<std::string> lines{kComment};
  for (const char* pattern : {"*.TcPOU", "*.TcDUT", "*.TcGVL", "*.TcIO", "*.TcITF", "*.EXP", "*.exp", "*.st"}) {
    lines.push_back(fmt::format("{} diff=rung merge=rung", pattern));
  }
  return lines;
}

std::vector<std::pair<std::string, std::string>> git_config_entries(const std::string& rung_command) {
  return {
      {"diff.rung.textconv", rung_command + " textconv"},
      {"merge.rung.name", "rung: three-way merge of PLC sources on the syntax tree"},
      {"merge.rung.driver", rung_command + " merge-file %O %A %B %P"},
  };
}

SetupResult setup_git(const std::string& folder, bool global, const std::string& rung_command) {
  SetupResult result;
  fs::path attributes;
  if (global) {
    attributes = global_attributes_file();
  } else {
    const std::string root = repository_root(folder, &result.error);
    if (root.empty()) return result;
    attributes = fs::path(root) / ".gitattributes";
  }
  result.attributes_file = attributes.string();
  std::string existing;
  {
    std::ifstream in(attributes, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    existing = s.str();
  }
  std::vector<std::string> present;
  std::istringstream lines(existing);
  for (std::string line; std::getline(lines, line);) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    present.push_back(line);
  }
  std::string append;
  for (const std::string& line : git_attribute_lines()) {
    if (std::find(present.begin(), present.end(), line) != present.end()) continue;
    result.added_lines.push_back(line);
    append += line + "\n";
  }
  if (!append.empty()) {
    std::error_code ec;
    fs::create_directories(attributes.parent_path(), ec);
    std::ofstream out(attributes, std::ios::binary | std::ios::app);
    if (!existing.empty() && existing.back() != '\n') out << '\n';
    out << append;
    if (!out) {
      result.error = fmt::format("cannot write {}", attributes.string());
      return result;
    }
  }
  for (const auto& [name, value] : git_config_entries(rung_command)) {
    if (!set_git_config(folder, global, name, value, &result.error)) return result;
    result.config.emplace_back(name, value);
  }
  return result;
}

}  // namespace rung::vcs
