// `rung parse FILE... [--tree] [--format human|json]`: syntax diagnostics (and trees) of files and
// folders. Returns the process exit code: 0 clean, 1 errors found, 2 usage or I/O error.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include "cli/terminal.hpp"

namespace rung::cli {

enum class OutputFormat { Human, Json };

struct ParseCommandOptions {
  std::vector<std::string> paths;
  bool tree = false;
  OutputFormat format = OutputFormat::Human;
  ColorChoice color = ColorChoice::Auto;
  bool quiet = false;    // no closing summary line
  unsigned threads = 0;  // 0: one per core
};

int run_parse_command(const ParseCommandOptions& options, std::FILE* out, std::FILE* err);

}  // namespace rung::cli
