#include "checker/check.hpp"

#include <algorithm>
#include <cstdlib>

#include "checker/conditional_sources.hpp"
#include "checker/semantic/body_checker.hpp"
#include "checker/semantic/declaration_checker.hpp"
#include "checker/semantic/pragma_checker.hpp"
#include "checker/semantic/recursion_checker.hpp"
#include "parser/file_walk.hpp"
#include "parser/parallel_for.hpp"
#include "parser/parallel_load.hpp"

#ifndef RUNG_LIBRARY_DIR
#define RUNG_LIBRARY_DIR "library"
#endif

namespace rung::check {
namespace fs = std::filesystem;

fs::path standard_library_dir() {
  if (const char* overridden = std::getenv("RUNG_LIBRARY_DIR"); overridden && *overridden) return overridden;
  return RUNG_LIBRARY_DIR;
}

std::vector<fs::path> default_library_folders(project::Profile profile) {
  const fs::path root = standard_library_dir();
  std::vector<fs::path> folders{root / "iec"};
  if (profile == project::Profile::Codesys || profile == project::Profile::Twincat) {
    for (const char* name : {"Operators", "Standard", "Standard64", "Util", "__SYSTEM"}) {
      folders.push_back(root / "codesys" / name);
    }
  }
  if (profile == project::Profile::Openpcs) folders.push_back(root / "openpcs" / "System");
  return folders;
}

namespace {

std::vector<fs::path> st_files_below(const fs::path& folder) {
  std::error_code error;
  if (!fs::is_directory(folder, error)) return {};
  return collect_source_files({folder}).files;
}

void apply_overrides(std::vector<Diagnostic>& diagnostics, const project::ProjectConfig& config) {
  if (config.severity_overrides.empty()) return;
  std::vector<Diagnostic> kept;
  for (auto& diagnostic : diagnostics) {
    auto found = config.severity_overrides.find(diagnostic.code);
    if (found == config.severity_overrides.end()) {
      kept.push_back(std::move(diagnostic));
    } else if (found->second) {
      diagnostic.severity = *found->second;
      kept.push_back(std::move(diagnostic));
    }
  }
  diagnostics = std::move(kept);
}

// Every POU and member of a file, so each body is checked once.
// Loads `files` on `threads` threads and adds them to `model` in order. Each file's symbols are
// collected on the thread that parsed it: the ids the model will give are known in advance.
void add_files(ProjectModel& model, const std::vector<fs::path>& files, unsigned threads,
               const std::string& library_name, std::vector<std::string>* load_errors) {
  const SourceId first_id = static_cast<SourceId>(model.source_count());
  std::vector<FileSymbols> symbols(files.size());  // one slot per file: workers never share one
  auto collect = [&](LoadedDocument& loaded) {
    symbols[loaded.index] = collect_file_symbols(static_cast<SourceId>(first_id + loaded.index), *loaded.document,
                                                 !library_name.empty(), "");
  };
  load_documents_in_order(
      files, threads,
      [&](LoadedDocument& loaded) {
        if (!loaded.document) {
          if (load_errors) load_errors->push_back(loaded.path.string() + ": " + loaded.error);
          return;
        }
        // An unreadable file earlier in the list shifts the ids of the files after it.
        FileSymbols& collected = symbols[loaded.index];
        renumber(collected, static_cast<SourceId>(model.source_count()));
        model.add_source(std::move(loaded.document), library_name, std::move(collected));
      },
      collect);
}

}  // namespace

void Workspace::add_library_folder(const fs::path& folder, unsigned threads) {
  add_files(*model_, st_files_below(folder), threads, folder.filename().string(), nullptr);
}

void Workspace::add_libraries(const LoadOptions& options, unsigned threads) {
  if (options.standard_libraries) {
    for (const fs::path& folder : default_library_folders(config_.profile)) add_library_folder(folder, threads);
  }
  for (const fs::path& folder : config_.libraries) add_library_folder(folder, threads);
  model_->link();
}

std::unique_ptr<Workspace> Workspace::load_files(const std::vector<fs::path>& files,
                                                 const project::ProjectConfig& config, const LoadOptions& options) {
  std::unique_ptr<Workspace> workspace(new Workspace());
  workspace->config_ = config;
  workspace->model_ = std::make_unique<ProjectModel>(make_profile(config));
  workspace->model_->set_threads(options.threads);
  add_files(*workspace->model_, files, options.threads, "", &workspace->load_errors);
  workspace->add_libraries(options, options.threads);
  compile_conditionally(*workspace->model_);  // blanks inactive {IF} branches, links again
  return workspace;
}

std::unique_ptr<Workspace> Workspace::load(const project::ProjectConfig& config, const LoadOptions& options) {
  std::vector<std::string> errors;
  std::vector<fs::path> files = project::project_source_files(config, &errors);
  auto workspace = load_files(files, config, options);
  for (auto& error : errors) workspace->load_errors.push_back(std::move(error));
  return workspace;
}

std::unique_ptr<Workspace> Workspace::from_texts(const std::vector<std::pair<std::string, std::string>>& files,
                                                 const project::ProjectConfig& config, const LoadOptions& options) {
  std::unique_ptr<Workspace> workspace(new Workspace());
  workspace->config_ = config;
  workspace->model_ = std::make_unique<ProjectModel>(make_profile(config));
  for (const auto& [path, text] : files) {
    workspace->model_->add_source(std::make_unique<Document>(Document::from_bytes(path, text)));
  }
  workspace->add_libraries(options, 1);
  compile_conditionally(*workspace->model_);
  return workspace;
}

FileDiagnostics Workspace::check_source(SourceId id) const {
  const Source& source = model_->source(id);
  FileDiagnostics result;
  result.source = id;
  result.path = source.document->path();
  std::vector<Diagnostic> semantic = source.symbols.diagnostics;
  semantic.insert(semantic.end(), source.link_diagnostics.begin(), source.link_diagnostics.end());
  for (const Symbol* pou : pous_of(source.symbols)) BodyChecker(*model_, *pou, semantic).check();
  check_declarations(*model_, id, semantic);
  check_recursion(*model_, id, semantic);
  check_pragmas(*model_, id, semantic);
  // Semantic findings are in tree coordinates; syntax diagnostics already in file coordinates.
  const Document& document = *source.document;
  for (Diagnostic& diagnostic : semantic) {
    diagnostic.range = {document.file_offset_of(diagnostic.range.begin),
                        document.file_end_offset_of(diagnostic.range.end)};
    for (auto& label : diagnostic.labels) {
      label.range = {document.file_offset_of(label.range.begin), document.file_end_offset_of(label.range.end)};
    }
  }
  result.diagnostics = document.diagnostics();
  result.diagnostics.insert(result.diagnostics.end(), std::make_move_iterator(semantic.begin()),
                            std::make_move_iterator(semantic.end()));
  apply_overrides(result.diagnostics, config_);
  sort_diagnostics(result.diagnostics);
  return result;
}

std::vector<FileDiagnostics> Workspace::check_all(unsigned threads) const {
  std::vector<SourceId> ids;
  for (SourceId id = 0; id < model_->source_count(); ++id) {
    if (!model_->source(id).library) ids.push_back(id);
  }
  std::vector<FileDiagnostics> results(ids.size());
  parallel_for(ids.size(), threads, [&](size_t i) { results[i] = check_source(ids[i]); });
  std::sort(results.begin(), results.end(),
            [](const FileDiagnostics& a, const FileDiagnostics& b) { return a.path < b.path; });
  return results;
}

SourceId Workspace::add_file(std::string path, std::string_view bytes) {
  const SourceId id = model_->add_source(std::make_unique<Document>(Document::from_bytes(std::move(path), bytes)));
  model_->link();
  compile_conditionally(*model_);
  return id;
}

std::vector<SourceId> Workspace::update(SourceId id, std::string_view text) {
  const std::string path = model_->source(id).document->path();
  auto document = std::make_unique<Document>(Document::from_bytes(path, text));
  // A body edit re-links only this file, a declaration edit the files that name what changed
  // (incremental_link.cpp); the rest links the project.
  ProjectModel::SourceUpdate change = model_->update_source(id, std::move(document));
  if (change.link_all) model_->link();
  const std::vector<SourceId> rewritten = compile_conditionally(*model_);
  const bool others_rewritten =
      std::any_of(rewritten.begin(), rewritten.end(), [&](SourceId other) { return other != id; });
  if (!change.link_all && !others_rewritten) return std::move(change.affected);
  std::vector<SourceId> all;
  for (SourceId other = 0; other < model_->source_count(); ++other) {
    if (!model_->source(other).library) all.push_back(other);
  }
  return all;
}

}  // namespace rung::check
