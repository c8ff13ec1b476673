// Runs ST text through check, compile and the VM, for the runner's tests.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "checker/check.hpp"
#include "runner/compile/compile.hpp"
#include "runner/engine.hpp"

namespace rung::run::testing {

struct RunOptions {
  uint64_t cycles = 1;
  project::Profile profile = project::Profile::Codesys;
  uint64_t tick_ns = 0;
  std::string program;
};

// Members in this order: the engine and the compiled project point into the workspace.
struct Run {
  std::unique_ptr<check::Workspace> workspace;
  std::vector<std::string> check_errors;    // "line:col: [code] message"
  std::vector<std::string> compile_errors;  // "line:col: message"
  CompiledProject project;
  std::unique_ptr<Engine> engine;

  // Runs more cycles; false after a run-time error.
  bool cycles(uint64_t count);
  // The value of a variable path as IEC text (TRUE, 42, 'abc', T#1s) or "<error: ...>".
  std::string text(std::string_view path) const;
  // Sets a variable from literal text (as --set does); fails the test when it cannot.
  void set(std::string_view path, std::string_view value);
  // The run-time error message, or "" when the run is clean.
  std::string error() const;
  // The error with its place and call stack (describe_error), or "".
  std::string described_error() const;
};

// Loads `source` as one file (main.st), checks, compiles and runs options.cycles cycles.
std::unique_ptr<Run> run_text(std::string_view source, const RunOptions& options = {});
std::unique_ptr<Run> run_files(const std::vector<std::pair<std::string, std::string>>& files,
                               const RunOptions& options = {});

// Sets `input` to each of `values` in turn, runs one cycle after each, and returns the texts of
// `output` after those cycles, joined by commas ("FALSE,TRUE,..."), for block tests cycle by cycle.
std::string sequence(Run& run, std::string_view input, const std::vector<std::string>& values, std::string_view output);
// Runs `count` cycles and returns the texts of `outputs` after each, "a/b" per cycle, joined by
// commas.
std::string trace(Run& run, uint64_t count, const std::vector<std::string>& outputs);

// The lines of a list, one per line (for failure messages).
std::string joined(const std::vector<std::string>& lines);

}  // namespace rung::run::testing

// The program checked, compiled and ran without an error.
#define ASSERT_CLEAN(outcome)                                                                          \
  do {                                                                                                 \
    ASSERT_TRUE((outcome)->check_errors.empty()) << ::rung::run::testing::joined((outcome)->check_errors); \
    ASSERT_TRUE((outcome)->compile_errors.empty())                                                     \
        << ::rung::run::testing::joined((outcome)->compile_errors);                                    \
    ASSERT_EQ((outcome)->error(), "") << (outcome)->described_error();                                 \
  } while (0)
