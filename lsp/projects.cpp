#include "lsp/projects.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>

#include "parser/file_walk.hpp"

namespace rung::lsp {
namespace fs = std::filesystem;

namespace {

std::optional<std::string> read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

bool is_inside(const fs::path& root, const fs::path& path) {
  const fs::path relative = path.lexically_relative(root);
  return !relative.empty() && *relative.begin() != "..";
}

void note(std::vector<Affected>& affected, Project& project, std::vector<check::SourceId> sources) {
  for (Affected& entry : affected) {
    if (entry.project == &project) {
      entry.sources.insert(entry.sources.end(), sources.begin(), sources.end());
      std::sort(entry.sources.begin(), entry.sources.end());
      entry.sources.erase(std::unique(entry.sources.begin(), entry.sources.end()), entry.sources.end());
      return;
    }
  }
  affected.push_back({&project, std::move(sources)});
}

}  // namespace

std::string ProjectSet::key_of(const fs::path& path) {
  std::error_code error;
  fs::path absolute = path.is_absolute() ? path : fs::absolute(path, error);
  return absolute.lexically_normal().string();
}

void ProjectSet::index_paths(Project& project) {
  project.by_path.clear();
  const check::ProjectModel& model = project.workspace->model();
  for (check::SourceId id = 0; id < model.source_count(); ++id) {
    if (model.source(id).library) continue;
    const std::string& path = model.source(id).document->path();
    project.by_path[project.loose ? path : key_of(path)] = id;
  }
}

lint::FileFindings Project::lint(check::SourceId source) const {
  lint::AnalysisCache cache(lint_index.get());
  return lint::lint_source(*workspace, source, settings().lint, &cache);
}

std::unique_ptr<Project> ProjectSet::load_project(const fs::path& root, const LoadProgress& progress) {
  auto project = std::make_unique<Project>();
  project->root = root;
  project->config = project::load_project_config(root);
  if (progress) progress("loading " + root.filename().string());
  project->workspace = check::Workspace::load(project->config.config, options_);
  index_paths(*project);
  return project;
}

Project& ProjectSet::add_folder(const fs::path& folder, const LoadProgress& progress) {
  const fs::path wanted = fs::path(key_of(folder));
  // A folder below a rung.toml belongs to that project (the root is where rung.toml is).
  const fs::path root = project::find_project_root(wanted).value_or(wanted);
  for (auto& project : projects_) {
    if (!project->loose && (project->root == root || is_inside(project->root, wanted))) return *project;
  }
  projects_.push_back(load_project(root, progress));
  return *projects_.back();
}

void ProjectSet::remove_folder(const fs::path& folder) {
  const fs::path wanted = fs::path(key_of(folder));
  const fs::path root = project::find_project_root(wanted).value_or(wanted);
  std::erase_if(projects_, [&](const std::unique_ptr<Project>& project) { return !project->loose && project->root == root; });
}

std::optional<FileRef> ProjectSet::find(std::string_view key) const {
  for (const auto& project : projects_) {
    const auto found = project->by_path.find(key);
    if (found != project->by_path.end() && !project->removed.contains(found->second)) {
      return FileRef{project.get(), found->second};
    }
  }
  return std::nullopt;
}

Project* ProjectSet::project_for(const fs::path& path) const {
  Project* best = nullptr;
  for (const auto& project : projects_) {
    if (project->loose || !is_inside(project->root, path)) continue;
    if (!best || project->root.string().size() > best->root.string().size()) best = project.get();
  }
  return best;
}

bool ProjectSet::belongs_to(const Project& project, const fs::path& path) const {
  const std::string relative = path.lexically_relative(project.root).generic_string();
  const auto& settings = project.settings();
  const bool excluded = std::any_of(settings.exclude.begin(), settings.exclude.end(),
                                    [&](const std::string& pattern) { return project::glob_match(pattern, relative); });
  if (excluded) return false;
  return std::any_of(settings.sources.begin(), settings.sources.end(), [&](const std::string& source) {
    const fs::path base = (project.root / source).lexically_normal();
    return base == path || is_inside(base, path);
  });
}

check::SourceId ProjectSet::add_or_revive(Project& project, const std::string& key, std::string_view bytes,
                                          std::vector<Affected>& affected) {
  // A file deleted earlier keeps its slot in the model: it comes back there.
  if (const auto removed = project.by_path.find(key); removed != project.by_path.end()) {
    project.removed.erase(removed->second);
    change({&project, removed->second}, std::string(bytes), affected);
    return removed->second;
  }
  const check::SourceId id = project.workspace->add_file(key, bytes);
  project.by_path[key] = id;
  ++project.generation;
  all_files(project, affected);
  return id;
}

void ProjectSet::all_files(Project& project, std::vector<Affected>& affected) {
  std::vector<check::SourceId> ids;
  for (const auto& [key, id] : project.by_path) {
    if (!project.removed.contains(id)) ids.push_back(id);
  }
  note(affected, project, std::move(ids));
}

FileRef ProjectSet::open(const std::string& key, const std::string& text, std::vector<Affected>& affected) {
  if (auto found = find(key)) {
    if (found->project->model().source(found->source).document->file_text() != text) {
      change(*found, text, affected);
    } else {
      note(affected, *found->project, {found->source});
    }
    return *found;
  }
  const fs::path path(key);
  const bool is_file = path.is_absolute();
  if (Project* owner = is_file ? project_for(path) : nullptr; owner && belongs_to(*owner, path)) {
    // A new file of the project (not yet on disk, or created before the watcher told us).
    return {owner, add_or_revive(*owner, key, text, affected)};
  }
  auto loose = std::make_unique<Project>();
  loose->loose = true;
  loose->root = is_file ? path.parent_path() : fs::path();
  const fs::path config_root = is_file ? project::find_project_root(path.parent_path()).value_or(path.parent_path())
                                       : fs::current_path();
  loose->config = project::load_project_config(config_root);
  loose->workspace = check::Workspace::from_texts({{key, text}}, loose->settings(), options_);
  index_paths(*loose);
  projects_.push_back(std::move(loose));
  Project& project = *projects_.back();
  all_files(project, affected);
  return {&project, project.by_path.begin()->second};
}

void ProjectSet::change(FileRef file, std::string_view text, std::vector<Affected>& affected) {
  std::vector<check::SourceId> ids = file.project->workspace->update(file.source, text);
  ++file.project->generation;
  std::erase_if(ids, [&](check::SourceId id) { return file.project->model().source(id).library; });
  note(affected, *file.project, std::move(ids));
}

void ProjectSet::close(const std::string& key, std::vector<Affected>& affected) {
  const auto found = find(key);
  if (!found) return;
  if (found->project->loose) {
    // The editor's diagnostics for it are cleared by the caller.
    std::erase_if(projects_, [&](const std::unique_ptr<Project>& project) { return project.get() == found->project; });
    return;
  }
  const auto bytes = read_bytes(key);
  if (!bytes) {  // never saved: the file leaves the project
    disk_deleted(key, affected);
    return;
  }
  if (*bytes != found->project->model().source(found->source).document->file_text()) {
    change(*found, *bytes, affected);
  }
}

void ProjectSet::disk_changed(const fs::path& path, bool is_open, std::vector<Affected>& affected) {
  if (is_open) return;
  const std::string key = key_of(path);
  const auto bytes = read_bytes(key);
  if (!bytes) return;
  if (auto found = find(key)) {
    if (!found->project->loose) change(*found, *bytes, affected);
    return;
  }
  // A file created on disk: it joins the project whose sources cover it, if rung reads its kind.
  Project* owner = project_for(key);
  if (!owner || !belongs_to(*owner, key)) return;
  if (source_kind_of(key) == SourceKind::None) return;
  add_or_revive(*owner, key, *bytes, affected);
}

void ProjectSet::disk_deleted(const fs::path& path, std::vector<Affected>& affected) {
  const std::string key = key_of(path);
  const auto found = find(key);
  if (!found || found->project->loose) return;
  change(*found, std::string(), affected);
  found->project->removed.insert(found->source);
}

Project& ProjectSet::reload(Project& project, const LoadProgress& progress) {
  for (auto& slot : projects_) {
    if (slot.get() == &project) {
      slot = load_project(project.root, progress);
      return *slot;
    }
  }
  return project;
}

}  // namespace rung::lsp
