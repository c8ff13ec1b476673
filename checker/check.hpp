// The checker's front door: load a project (its files and the stub libraries its profile and
// rung.toml name), link it, and check every POU. The CLI (`rung check`), the language server and
// the tests all go through here.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "checker/project/project_config.hpp"
#include "checker/project_model.hpp"

namespace rung::check {

// Where rung's own stub libraries live (library/ of the source tree or of an install); the
// environment variable RUNG_LIBRARY_DIR overrides it.
std::filesystem::path standard_library_dir();
// The stub library folders a profile loads by default, e.g. iec and codesys/* for CODESYS.
std::vector<std::filesystem::path> default_library_folders(project::Profile profile);

struct FileDiagnostics {
  SourceId source = kNoSource;
  std::string path;
  std::vector<Diagnostic> diagnostics;  // ranges in FILE coordinates (container offsets mapped)
};

struct LoadOptions {
  unsigned threads = 0;  // 0: one per core
  bool standard_libraries = true;
};

class Workspace {
 public:
  // Loads the project described by `config` (files from project_source_files).
  static std::unique_ptr<Workspace> load(const project::ProjectConfig& config, const LoadOptions& options = {});
  // Loads the given files only (plus libraries): for single files and tests.
  static std::unique_ptr<Workspace> load_files(const std::vector<std::filesystem::path>& files,
                                               const project::ProjectConfig& config, const LoadOptions& options = {});
  // From in-memory texts: (path, text) pairs. For tests and the language server.
  static std::unique_ptr<Workspace> from_texts(const std::vector<std::pair<std::string, std::string>>& files,
                                               const project::ProjectConfig& config, const LoadOptions& options = {});

  ProjectModel& model() { return *model_; }
  const ProjectModel& model() const { return *model_; }

  // Diagnostics of every project file (libraries are checked once, silently), sorted by file
  // and position. Severity overrides of rung.toml applied.
  std::vector<FileDiagnostics> check_all(unsigned threads = 0) const;
  // Diagnostics of one file.
  FileDiagnostics check_source(SourceId id) const;
  // An editor changed a file: re-parse it and re-check what depends on it. Returns the ids of
  // the files whose diagnostics may have changed.
  std::vector<SourceId> update(SourceId id, std::string_view text);
  // A file the project did not have (created on disk, or opened in an editor): parsed, added and
  // the project linked again. Every project file's diagnostics may change.
  SourceId add_file(std::string path, std::string_view bytes);

  const project::ProjectConfig& config() const { return config_; }

  std::vector<std::string> load_errors;  // files that could not be read

 private:
  Workspace() = default;
  void add_library_folder(const std::filesystem::path& folder, unsigned threads);
  // The profile's standard stubs and rung.toml's libraries, then link().
  void add_libraries(const LoadOptions& options, unsigned threads);
  std::unique_ptr<ProjectModel> model_;
  project::ProjectConfig config_;
};

}  // namespace rung::check
