// `rung check [PATH...]`: the semantic checker over a project (syntax and semantic diagnostics).
#pragma once

#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "checker/project/project_config.hpp"
#include "cli/terminal.hpp"

namespace rung::cli {

enum class CheckFormat { Human, Json, Sarif };

struct CheckCommandOptions {
  std::vector<std::string> paths;  // files or folders; default: the current folder
  CheckFormat format = CheckFormat::Human;
  std::optional<project::Profile> profile;  // --profile overrides rung.toml
  ColorChoice color = ColorChoice::Auto;
  bool quiet = false;
  unsigned threads = 0;
};

int run_check_command(const CheckCommandOptions& options, std::FILE* out, std::FILE* err);

}  // namespace rung::cli
