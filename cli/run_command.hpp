// `rung run [PATH]`: checks a project, compiles it for the runner and runs its programs for a
// number of cycles on the virtual clock; prints the variables afterwards (table or JSON).
#pragma once

#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "checker/project/project_config.hpp"
#include "cli/terminal.hpp"

namespace CLI {
class App;
}

namespace rung::cli {

enum class RunFormat { Human, Json };

struct RunCommandOptions {
  std::vector<std::string> paths;
  std::string program;
  std::string configuration;
  std::optional<uint64_t> cycles;  // default 1
  std::string until;               // a BOOL variable, or VAR=VALUE
  std::string for_time;            // a duration: run until the clock reaches it
  std::string tick;                // a duration; default: the task interval, else 10 ms
  std::vector<std::string> set;    // VAR=VALUE before the first cycle
  std::vector<std::string> watch;  // variables printed after every cycle
  std::string trace;               // CSV file, one row per cycle
  uint64_t max_cycles = 1'000'000;  // bound of --until
  uint64_t loop_limit = 100'000'000;  // backward jumps per program call (the watchdog)
  bool dump_ir = false;  // print the compiled instructions and stop
  RunFormat format = RunFormat::Human;
  std::optional<project::Profile> profile;
  ColorChoice color = ColorChoice::Auto;
};

// Registers `run` on `app`; `options` and `format_text` receive the parsed values.
CLI::App* add_run_subcommand(CLI::App& app, RunCommandOptions& options, std::string& format_text,
                             std::string& profile_text);
int run_run_command(const RunCommandOptions& options, std::FILE* out, std::FILE* err);

}  // namespace rung::cli
