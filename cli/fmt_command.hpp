// `rung fmt [PATH...]`: lays out source files with the project's [format] settings, in place, or
// says which files would change (--check), or prints the changes (--diff), or formats stdin.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include "cli/terminal.hpp"

namespace rung::cli {

struct FmtCommandOptions {
  std::vector<std::string> paths;  // files or folders; default: the project of the current folder
  bool check = false;              // write nothing; list the files that would change
  bool diff = false;               // write nothing; print unified diffs
  bool stdin_mode = false;         // format standard input to standard output
  std::string stdin_filename;      // with stdin_mode: the file kind and the project (rung.toml)
  ColorChoice color = ColorChoice::Auto;
  bool quiet = false;
  unsigned threads = 0;
};

// Exit code: 0 done (or nothing to change), 1 a file would change (--check, --diff) or could not
// be formatted (syntax errors, the safety check), 2 a missing path, an I/O error or a broken
// rung.toml.
int run_fmt_command(const FmtCommandOptions& options, std::FILE* in, std::FILE* out, std::FILE* err);

}  // namespace rung::cli
