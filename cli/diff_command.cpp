#include "cli/diff_command.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <string_view>

#include "cli/diff_report.hpp"
#include "vcs/git_repository.hpp"
#include "vcs/semantic_diff.hpp"

namespace rung::cli {

int take_arguments_after_dashes(int argc, char** argv, const std::string& name, std::vector<std::string>* paths) {
  int command = 1;  // the subcommand is the first argument that is not an option
  while (command < argc && argv[command][0] == '-') ++command;
  if (command >= argc || argv[command] != name) return argc;
  for (int i = command + 1; i < argc; ++i) {
    if (std::string_view(argv[i]) == "--") {
      for (int k = i + 1; k < argc; ++k) paths->emplace_back(argv[k]);
      return i;
    }
  }
  return argc;
}

int run_diff_command(const DiffCommandOptions& options, std::FILE* out, std::FILE* err) {
  vcs::DiffSpec spec;
  spec.cached = options.cached;
  spec.paths = options.paths;
  // An argument naming an existing file or folder is a path, as git decides; the others are
  // revisions (libgit2 says below whether they are).
  for (const std::string& a : options.arguments) {
    std::error_code ec;
    const std::filesystem::path p = std::filesystem::path(options.folder.empty() ? "." : options.folder) / a;
    if (a.find("..") == std::string::npos && std::filesystem::exists(p, ec)) {
      spec.paths.push_back(a);
    } else {
      spec.revisions.push_back(a);
    }
  }
  const vcs::ChangedFiles changed = vcs::changed_plc_files(options.folder, spec);
  if (!changed.error.empty()) {
    fmt::print(err, "rung diff: {}\n", changed.error);
    return 2;
  }
  vcs::DiffOptions diff_options;
  diff_options.comments = options.comments;
  const vcs::DiffReport report = vcs::semantic_diff(changed.files, diff_options);
  for (const vcs::FileError& e : report.errors) fmt::print(err, "rung diff: warning: {}: {}\n", e.path, e.message);
  const bool color = options.format == "human" && use_color(options.color, out);
  std::string text;
  if (options.format == "json") {
    text = render_json(report);
  } else if (options.stat) {
    text = render_stat(report, color);
  } else {
    text = render_human(report, color);
  }
  std::fwrite(text.data(), 1, text.size(), out);
  if (options.exit_code && !report.changes.empty()) return 1;
  return 0;
}

}  // namespace rung::cli
