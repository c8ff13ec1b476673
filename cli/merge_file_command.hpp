// `rung merge-file BASE OURS THEIRS [PATH]`: git's merge driver (%O %A %B %P). Merges the three
// versions on the syntax tree and writes the result over OURS.
#pragma once

#include <cstdio>
#include <string>

namespace rung::cli {

struct MergeFileOptions {
  std::string base;
  std::string ours;
  std::string theirs;
  std::string path;  // the file's name in the repository (its kind); default: OURS
};

// Exit code: 0 merged cleanly, 1 conflicts (written with markers), 2 a file cannot be read or
// written, or the versions cannot be merged at all (OURS is then left as it was).
int run_merge_file_command(const MergeFileOptions& options, std::FILE* out, std::FILE* err);

}  // namespace rung::cli
