// `rung lint [PATH...]`: the lint rules (checker/lint/) over a project: style, naming, structure
// and likely mistakes that are legal code, as configured in rung.toml [lint]. Optionally applies
// the rules' fixes (--fix) and keeps a baseline of accepted findings (--write-baseline).
#pragma once

#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "checker/project/project_config.hpp"
#include "cli/check_command.hpp"
#include "cli/terminal.hpp"

namespace rung::cli {

struct LintCommandOptions {
  std::vector<std::string> paths;  // files or folders; default: the current folder
  CheckFormat format = CheckFormat::Human;
  std::optional<project::Profile> profile;  // overrides rung.toml
  bool fix = false;                         // apply every fix of a reported finding, write the files
  // Write the findings to the baseline file instead of reporting them; "" = the file rung.toml
  // names, else lint-baseline.json in the project folder.
  std::optional<std::string> write_baseline;
  bool no_baseline = false;  // report the findings the baseline lists, too
  bool list_rules = false;   // print the rules and how this project sets them
  ColorChoice color = ColorChoice::Auto;
  bool quiet = false;
  unsigned threads = 0;
};

// Exit code: 0 no finding at error level, 1 findings at error level, 2 a missing path, an I/O
// error, an unreadable baseline or a broken rung.toml.
int run_lint_command(const LintCommandOptions& options, std::FILE* out, std::FILE* err);

}  // namespace rung::cli
