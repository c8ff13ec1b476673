// `rung git setup`: the .gitattributes lines and git config entries that make git show PLC
// sources through `rung textconv` and merge them with `rung merge-file`. docs/git.md lists them.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace rung::vcs {

// The .gitattributes lines (in order, without line ends).
std::vector<std::string> git_attribute_lines();

// The git config entries (name, value) for a rung started as `rung_command`.
std::vector<std::pair<std::string, std::string>> git_config_entries(const std::string& rung_command);

struct SetupResult {
  std::string attributes_file;                              // the file the lines went to
  std::vector<std::string> added_lines;                     // lines that were not there yet
  std::vector<std::pair<std::string, std::string>> config;  // entries set
  std::string error;
};

// Appends the missing attribute lines to `<repository>/.gitattributes` (global: the user's
// attributes file, core.attributesFile or ~/.config/git/attributes) and sets the config entries
// in the repository's .git/config (global: ~/.gitconfig). Running it again changes nothing.
SetupResult setup_git(const std::string& folder, bool global, const std::string& rung_command);

}  // namespace rung::vcs
