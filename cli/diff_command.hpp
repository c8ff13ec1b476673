// `rung diff [REV [REV]] [--cached] [-- PATH...]`: what changed in the PLC code of a git
// repository, by meaning (objects added, removed, renamed, moved; declarations; bodies), over
// libgit2. See docs/commands/diff.md.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include "cli/terminal.hpp"

namespace rung::cli {

struct DiffCommandOptions {
  // Revisions, and files or folders (an argument naming an existing one is a path, as git
  // decides without "--").
  std::vector<std::string> arguments;
  std::vector<std::string> paths;  // the arguments after "--": always paths
  bool cached = false;
  std::string format = "human";  // human | json
  bool stat = false;
  bool exit_code = false;  // 1 when something changed, as git diff --exit-code
  bool comments = false;   // comment-only changes count
  ColorChoice color = ColorChoice::Auto;
  std::string folder;  // the folder to start from (default: the current one)
};

// CLI11 2.1 gives a subcommand's arguments after "--" to the top level, which rejects them: this
// takes them (and the "--") off the command line when they follow the subcommand `name`, puts
// them in `paths` and returns the new argc.
int take_arguments_after_dashes(int argc, char** argv, const std::string& name, std::vector<std::string>* paths);

// Exit code: 0 (or, with exit_code, 1 when something changed); 2 not a repository, an unknown
// revision, an I/O error.
int run_diff_command(const DiffCommandOptions& options, std::FILE* out, std::FILE* err);

}  // namespace rung::cli
