// `rung git setup [--global]`: makes git show PLC sources through `rung textconv` and merge them
// with `rung merge-file` (docs/git.md has the exact lines and how to undo them).
#pragma once

#include <cstdio>
#include <string>

namespace rung::cli {

// Exit code: 0 done (or nothing to do), 2 not in a repository, a file or config not writable.
int run_git_setup_command(bool global, std::FILE* out, std::FILE* err);

// How git should start this rung: "rung" when that name on PATH is this executable, else the
// executable's absolute path.
std::string rung_command_for_git();

}  // namespace rung::cli
