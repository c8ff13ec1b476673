// The projects a language server session works on. Each workspace folder is one project (its
// rung.toml, or the one above it, says which files belong to it); every project file is indexed
// from disk whether it is open or not. A file the editor opens outside every project gets a small
// project of its own ("loose"), with the settings of the nearest rung.toml above it.
#pragma once

#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "checker/check.hpp"
#include "checker/lint/lint.hpp"
#include "checker/lint/project_index.hpp"

namespace rung::lsp {

struct Project {
  std::filesystem::path root;
  bool loose = false;  // a single file outside every workspace folder
  project::LoadedConfig config;
  std::unique_ptr<check::Workspace> workspace;
  std::map<std::string, check::SourceId, std::less<>> by_path;  // normalized path (or URI) -> file
  std::set<check::SourceId> removed;  // deleted on disk: kept (empty) in the model, hidden from features
  uint64_t generation = 0;            // bumped by every change, for caches of feature results

  // The linter's project-wide index, kept across edits: a keystroke's lint re-reads the edited
  // file instead of the whole project (only the worker thread lints).
  std::unique_ptr<lint::ProjectIndex> lint_index = std::make_unique<lint::ProjectIndex>();

  const project::ProjectConfig& settings() const { return config.config; }
  const check::ProjectModel& model() const { return workspace->model(); }
  // The lint findings of one file, with the project's [lint] settings.
  lint::FileFindings lint(check::SourceId source) const;
};

struct FileRef {
  Project* project = nullptr;
  check::SourceId source = check::kNoSource;
};

// Files whose diagnostics may have changed, per project.
struct Affected {
  Project* project = nullptr;
  std::vector<check::SourceId> sources;
};

// `done` of `total` files loaded, for $/progress.
using LoadProgress = std::function<void(std::string_view message)>;

class ProjectSet {
 public:
  explicit ProjectSet(check::LoadOptions options = {}) : options_(options) {}

  // The key a file is known by: its absolute, normalized path.
  static std::string key_of(const std::filesystem::path& path);

  // A workspace folder: loads its project (files, libraries, link). A folder inside an already
  // loaded project's root is not loaded twice.
  Project& add_folder(const std::filesystem::path& folder, const LoadProgress& progress = {});
  void remove_folder(const std::filesystem::path& folder);

  // The project file at `key`, if any project has it (loose projects included).
  std::optional<FileRef> find(std::string_view key) const;
  // An editor opened `key` with `text`: the file of the project that has it (its text replaced
  // when it differs), or it joins the project whose sources cover it, or it gets a loose project.
  FileRef open(const std::string& key, const std::string& text, std::vector<Affected>& affected);
  // The editor's text changed.
  void change(FileRef file, std::string_view text, std::vector<Affected>& affected);
  // The editor closed the file: a project file goes back to its text on disk; a loose project ends.
  void close(const std::string& key, std::vector<Affected>& affected);

  // workspace/didChangeWatchedFiles. Open files are the editor's business and ignored here.
  void disk_changed(const std::filesystem::path& path, bool is_open, std::vector<Affected>& affected);
  void disk_deleted(const std::filesystem::path& path, std::vector<Affected>& affected);
  // rung.toml of `project` changed (or appeared): the project is loaded again.
  Project& reload(Project& project, const LoadProgress& progress = {});

  const std::vector<std::unique_ptr<Project>>& projects() const { return projects_; }
  // The project whose root holds `path` (deepest root wins), loose projects left out.
  Project* project_for(const std::filesystem::path& path) const;

 private:
  std::unique_ptr<Project> load_project(const std::filesystem::path& root, const LoadProgress& progress);
  static void index_paths(Project& project);
  bool belongs_to(const Project& project, const std::filesystem::path& path) const;
  static void all_files(Project& project, std::vector<Affected>& affected);
  check::SourceId add_or_revive(Project& project, const std::string& key, std::string_view bytes,
                                std::vector<Affected>& affected);

  check::LoadOptions options_;
  std::vector<std::unique_ptr<Project>> projects_;
};

}  // namespace rung::lsp
