#include "cli/project_loading.hpp"

#include <fmt/format.h>

#include "cli/diagnostic_printer.hpp"
#include "parser/file_walk.hpp"

namespace rung::cli {
namespace fs = std::filesystem;

namespace {

// Whether `file` is `root` or lies below it.
bool is_within(const fs::path& file, const fs::path& root) {
  const fs::path relative = file.lexically_relative(root);
  return !relative.empty() && *relative.begin() != "..";
}

}  // namespace

ConfigLoad load_config_reporting(const fs::path& start, const Style& style, std::FILE* err) {
  ConfigLoad out;
  out.root = project::find_project_root(start);
  out.loaded = project::load_project_config(out.root ? *out.root : start);
  if (out.loaded.diagnostics.empty()) return out;
  const Document config_document =
      Document::from_bytes((out.loaded.config.root / "rung.toml").string(), out.loaded.text);
  for (const Diagnostic& diagnostic : out.loaded.diagnostics) {
    fmt::print(err, "{}", render_human(config_document, diagnostic, style));
    out.has_errors |= diagnostic.severity == Severity::Error;
  }
  return out;
}

bool LoadedProject::in_scope(const std::string& file) const {
  const fs::path path = fs::absolute(file).lexically_normal();
  for (const fs::path& scope : scopes) {
    if (path == scope || is_within(path, scope)) return true;
  }
  return false;
}

std::optional<LoadedProject> load_project(const ProjectLoadOptions& options, const Style& style, std::FILE* err) {
  std::vector<fs::path> inputs;
  for (const auto& path : options.paths) inputs.push_back(path);
  if (inputs.empty()) inputs.emplace_back(".");
  for (const auto& input : inputs) {
    std::error_code error;
    if (!fs::exists(input, error)) {
      fmt::print(err, "error: {}: no such file or folder\n", input.string());
      return std::nullopt;
    }
  }
  LoadedProject project;
  const fs::path first = fs::absolute(inputs.front()).lexically_normal();
  project.config = load_config_reporting(fs::is_directory(first) ? first : first.parent_path(), style, err);
  project::ProjectConfig& config = project.config.loaded.config;
  if (options.profile) config.profile = *options.profile;

  check::LoadOptions load_options;
  load_options.threads = options.threads;
  if (project.config.root) {
    project.workspace = check::Workspace::load(config, load_options);
  } else {
    WalkResult walk = collect_source_files(inputs);
    project.workspace = check::Workspace::load_files(walk.files, config, load_options);
    for (const auto& error : walk.errors) project.workspace->load_errors.push_back(error);
  }
  for (const auto& error : project.workspace->load_errors) fmt::print(err, "error: {}\n", error);
  for (const auto& input : inputs) project.scopes.push_back(fs::absolute(input).lexically_normal());
  return project;
}

// Freeing the syntax trees of a large project node by node took 5% of a whole check (like
// compilers, which leave their ASTs to the operating system). Sanitizer builds free it: leak
// checks stay useful.
void keep_until_exit(std::unique_ptr<check::Workspace> workspace) {
#if defined(__SANITIZE_ADDRESS__)
  workspace.reset();
#else
  static_cast<void>(workspace.release());
#endif
}

}  // namespace rung::cli
