#include "cli/merge_file_command.hpp"

#include <fmt/format.h>

#include <optional>

#include "cli/atomic_write.hpp"
#include "vcs/git_repository.hpp"
#include "vcs/merge.hpp"

namespace rung::cli {

int run_merge_file_command(const MergeFileOptions& options, std::FILE* out, std::FILE* err) {
  const std::string name = options.path.empty() ? options.ours : options.path;
  std::optional<std::string> texts[3];
  const std::string* paths[3] = {&options.base, &options.ours, &options.theirs};
  for (int i = 0; i < 3; ++i) {
    texts[i] = vcs::read_file_bytes(*paths[i]);
    if (!texts[i]) {
      fmt::print(err, "rung merge-file: {}: cannot open file\n", *paths[i]);
      return 2;
    }
  }
  const vcs::MergeResult result = vcs::merge_file(name, *texts[0], *texts[1], *texts[2]);
  for (const std::string& note : result.notes) fmt::print(err, "rung merge-file: {}: {}\n", name, note);
  if (!result.error.empty()) {
    fmt::print(err, "rung merge-file: {}: {}; left our version as it is\n", name, result.error);
    return 2;
  }
  std::string error;
  if (!replace_file_atomically(options.ours, result.text, &error)) {
    fmt::print(err, "rung merge-file: {}\n", error);
    return 2;
  }
  if (result.conflicts > 0) {
    fmt::print(out, "rung merge-file: {}: {} conflict{}\n", name, result.conflicts, result.conflicts == 1 ? "" : "s");
    return 1;
  }
  return 0;
}

}  // namespace rung::cli
