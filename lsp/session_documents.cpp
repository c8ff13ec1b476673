// Session: the lifecycle (initialize, shutdown), open documents and the workspace: what the
// editor and the file system tell the server, turned into project updates and due diagnostics.
#include <algorithm>

#include "lsp/json_util.hpp"
#include "lsp/session.hpp"
#include "lsp/text_sync.hpp"
#include "lsp/uri.hpp"
#include "parser/file_walk.hpp"

#ifndef RUNG_VERSION
#define RUNG_VERSION "dev"
#endif

namespace rung::lsp {
namespace fs = std::filesystem;

namespace {

bool is_rung_toml(const fs::path& path) { return path.filename() == "rung.toml"; }

// Languages rung reads, by the ids editors send (the extension decides for files it knows).
bool is_plc_language(std::string_view language_id) {
  return language_id == "iec61131" || language_id == "st" || language_id == "structured-text" ||
         language_id == "structuredtext" || language_id == "iecst" || language_id == "il";
}

}  // namespace

bool Session::handle_lifecycle(std::string_view method, const Json& params, Json* result) {
  if (method == "initialize") {
    *result = initialize(params);
  } else if (method == "initialized") {
    initialized_notification();
  } else if (method == "shutdown") {
    shutdown_requested_ = true;
    *result = nullptr;
  } else if (method == "textDocument/didOpen") {
    did_open(params);
  } else if (method == "textDocument/didChange") {
    did_change(params);
  } else if (method == "textDocument/didClose") {
    did_close(params);
  } else if (method == "textDocument/didSave") {
    did_save(params);
  } else if (method == "workspace/didChangeWatchedFiles") {
    did_change_watched_files(params);
  } else if (method == "workspace/didChangeWorkspaceFolders") {
    did_change_workspace_folders(params);
  } else if (method == "workspace/didChangeConfiguration" || method == "$/setTrace" || method == "window/workDoneProgress/cancel") {
    // Settings live in rung.toml; tracing and progress cancellation need no answer.
  } else {
    return false;
  }
  return true;
}

Json Session::initialize(const Json& params) {
  if (initialize_done_) throw RpcError{ErrorCode::InvalidRequest, "initialize was sent twice"};
  initialize_done_ = true;
  client_capabilities_ = params.is_object() ? params.value("capabilities", Json::object()) : Json::object();
  if (!client_capabilities_.is_object()) client_capabilities_ = Json::object();
  // A client that pulls diagnostics gets no pushed ones (it would show every finding twice).
  push_diagnostics_ = json_at(client_capabilities_, {"textDocument", "diagnostic"}).is_null();
  work_done_progress_ = json_at(client_capabilities_, {"window", "workDoneProgress"}) == true;

  const Json& folders = json_at(params, {"workspaceFolders"});
  if (folders.is_array()) {
    for (const Json& folder : folders) {
      if (auto path = path_of_uri(json_string(folder, "uri"))) pending_folders_.push_back(*path);
    }
  } else if (auto root = path_of_uri(json_string(params, "rootUri"))) {
    pending_folders_.push_back(*root);
  } else if (const std::string root_path = json_string(params, "rootPath"); !root_path.empty()) {
    pending_folders_.emplace_back(root_path);
  }

  Json capabilities = server_capabilities_;
  capabilities["positionEncoding"] = "utf-16";
  capabilities["textDocumentSync"] = Json{{"openClose", true}, {"change", 2}, {"save", Json{{"includeText", false}}}};
  capabilities["workspace"] = Json{{"workspaceFolders", Json{{"supported", true}, {"changeNotifications", true}}}};
  if (!push_diagnostics_) {
    capabilities["diagnosticProvider"] = Json{{"identifier", "rung"}, {"interFileDependencies", true}, {"workspaceDiagnostics", false}};
  }
  return Json{{"capabilities", capabilities}, {"serverInfo", Json{{"name", "rung"}, {"version", RUNG_VERSION}}}};
}

void Session::initialized_notification() {
  if (json_at(client_capabilities_, {"workspace", "didChangeWatchedFiles", "dynamicRegistration"}) == true) {
    Json watchers = Json::array();
    for (const char* glob : {"**/*.{st,ST,iecst,il,IL,sfc,gvl,pou,exp,EXP,xml}", "**/*.{TcPOU,TcDUT,TcGVL,TcIO,TcITF}",
                             "**/rung.toml"}) {
      watchers.push_back(Json{{"globPattern", glob}});
    }
    sink_(make_request("rung-watch", "client/registerCapability",
                       Json{{"registrations", Json::array({Json{{"id", "rung-watched-files"},
                                                               {"method", "workspace/didChangeWatchedFiles"},
                                                               {"registerOptions", Json{{"watchers", watchers}}}}})}}));
  }
  std::vector<fs::path> folders;
  folders.swap(pending_folders_);
  index_folders(folders);
}

void Session::index_folders(const std::vector<fs::path>& folders) {
  if (folders.empty()) return;
  std::string token;
  if (work_done_progress_) {
    token = "rung-index-" + std::to_string(++progress_tokens_);
    sink_(make_request(token, "window/workDoneProgress/create", Json{{"token", token}}));
    notify("$/progress", Json{{"token", token}, {"value", Json{{"kind", "begin"}, {"title", "rung: indexing"}, {"percentage", 0}}}});
  }
  size_t done = 0;
  for (const fs::path& folder : folders) {
    const auto progress = [&](std::string_view message) {
      if (token.empty()) return;
      const auto percentage = static_cast<unsigned>(100 * done / folders.size());
      notify("$/progress", Json{{"token", token}, {"value", Json{{"kind", "report"}, {"message", std::string(message)}, {"percentage", percentage}}}});
    };
    Project& project = projects_.add_folder(folder, progress);
    ++done;
    std::vector<Affected> affected;
    std::vector<check::SourceId> all;
    for (const auto& [key, id] : project.by_path) all.push_back(id);
    affected.push_back({&project, std::move(all)});
    mark_dirty(affected);
    for (const std::string& error : project.workspace->load_errors) log(2, "rung: " + error);
    publish_config_diagnostics(project);
  }
  if (!token.empty()) {
    size_t files = 0;
    for (const auto& project : projects()) files += project->by_path.size();
    notify("$/progress", Json{{"token", token}, {"value", Json{{"kind", "end"}, {"message", std::to_string(files) + " files indexed"}}}});
  }
}

void Session::did_open(const Json& params) {
  const Json& item = json_at(params, {"textDocument"});
  const std::string uri = json_string(item, "uri");
  const Json& text = json_at(item, {"text"});
  if (uri.empty() || !text.is_string()) throw RpcError{ErrorCode::InvalidParams, "didOpen without textDocument.uri/text"};
  const std::string key = key_of_uri(uri);
  const std::string language = json_string(item, "languageId");
  if (is_rung_toml(fs::path(key))) {
    publish_config_text(uri, fs::path(key).parent_path(), text.get<std::string>());
    return;
  }
  // Only files rung reads; anything else an editor sends (a Markdown file) is not parsed as ST.
  if (source_kind_of(fs::path(key)) == SourceKind::None && !is_plc_language(language)) return;
  OpenDocument& open = open_[uri];
  open.uri = uri;
  open.key = key;
  open.version = json_at(item, {"version"}).is_number_integer() ? item["version"].get<int64_t>() : 0;
  open.language_id = language;
  std::vector<Affected> affected;
  projects_.open(key, text.get<std::string>(), affected);
  mark_dirty(affected);
}

void Session::did_change(const Json& params) {
  const std::string uri = json_string(json_at(params, {"textDocument"}), "uri");
  if (is_rung_toml(fs::path(key_of_uri(uri)))) {
    const Json& changes = json_at(params, {"contentChanges"});
    if (changes.is_array() && !changes.empty() && !changes.back().contains("range")) {
      publish_config_text(uri, fs::path(key_of_uri(uri)).parent_path(), json_string(changes.back(), "text"));
    }
    return;
  }
  const auto open = open_.find(uri);
  if (open == open_.end()) {
    log(2, "rung: didChange for a document that is not open: " + uri);
    return;
  }
  const Json& version = json_at(params, {"textDocument", "version"});
  if (version.is_number_integer()) {
    // An older version than the one applied arrives late: applying it would corrupt the text.
    if (version.get<int64_t>() <= open->second.version) {
      log(3, "rung: dropped stale change of " + uri + " (version " + version.dump() + ")");
      return;
    }
    open->second.version = version.get<int64_t>();
  }
  const auto file = projects_.find(open->second.key);
  if (!file) return;
  std::string text(file->project->model().source(file->source).document->file_text());
  const Json& changes = json_at(params, {"contentChanges"});
  if (!changes.is_array()) throw RpcError{ErrorCode::InvalidParams, "didChange without contentChanges"};
  for (const Json& change : changes) {
    if (auto error = apply_content_change(text, change)) {
      log(1, "rung: " + uri + ": " + *error + "; change ignored");
      return;
    }
  }
  std::vector<Affected> affected;
  projects_.change(*file, text, affected);
  mark_dirty(affected);
}

void Session::did_close(const Json& params) {
  const std::string uri = json_string(json_at(params, {"textDocument"}), "uri");
  const auto open = open_.find(uri);
  if (open == open_.end()) return;
  const std::string key = open->second.key;
  open_.erase(open);
  const auto file = projects_.find(key);
  const bool loose = file && file->project->loose;
  if (loose) drop_project(file->project);
  std::vector<Affected> affected;
  projects_.close(key, affected);
  mark_dirty(affected);
  if (loose && published_.erase(uri)) notify("textDocument/publishDiagnostics", Json{{"uri", uri}, {"diagnostics", Json::array()}});
}

void Session::did_save(const Json& params) {
  const std::string uri = json_string(json_at(params, {"textDocument"}), "uri");
  const auto path = path_of_uri(uri);
  if (path && is_rung_toml(*path)) reload_project_at(path->parent_path());
}

void Session::did_change_watched_files(const Json& params) {
  const Json& changes = json_at(params, {"changes"});
  if (!changes.is_array()) return;
  std::vector<Affected> affected;
  for (const Json& change : changes) {
    const std::string uri = json_string(change, "uri");
    const auto path = path_of_uri(uri);
    if (!path) continue;
    if (is_rung_toml(*path)) {
      reload_project_at(path->parent_path());
      continue;
    }
    const int type = change.is_object() && change.value("type", Json()).is_number_integer() ? change["type"].get<int>() : 0;
    const bool is_open = open_.contains(uri);
    if (type == 3) {
      if (is_open) continue;
      projects_.disk_deleted(*path, affected);
      if (published_.erase(uri)) notify("textDocument/publishDiagnostics", Json{{"uri", uri}, {"diagnostics", Json::array()}});
    } else if (type == 1 || type == 2) {
      projects_.disk_changed(*path, is_open, affected);
    }
  }
  mark_dirty(affected);
}

void Session::did_change_workspace_folders(const Json& params) {
  const Json& removed = json_at(params, {"event", "removed"});
  if (removed.is_array()) {
    for (const Json& folder : removed) {
      const auto path = path_of_uri(json_string(folder, "uri"));
      if (!path) continue;
      if (Project* project = projects_.project_for(*path); project && !project->loose) {
        clear_published(*project);
        drop_project(project);
      }
      projects_.remove_folder(*path);
    }
  }
  const Json& added = json_at(params, {"event", "added"});
  std::vector<fs::path> folders;
  if (added.is_array()) {
    for (const Json& folder : added) {
      if (auto path = path_of_uri(json_string(folder, "uri"))) folders.push_back(*path);
    }
  }
  index_folders(folders);
}

void Session::reload_project_at(const fs::path& folder) {
  const std::string root = ProjectSet::key_of(folder);
  for (const auto& project : projects()) {
    if (project->loose || project->root.string() != root) continue;
    // The editor's unsaved buffers win over the disk: keep their texts across the reload.
    std::vector<std::pair<std::string, std::string>> buffers;
    for (const auto& [uri, open] : open_) {
      if (const auto file = projects_.find(open.key); file && file->project == project.get()) {
        buffers.emplace_back(open.key, std::string(file->project->model().source(file->source).document->file_text()));
      }
    }
    drop_project(project.get());
    Project& reloaded = projects_.reload(*project);
    std::vector<Affected> affected;
    for (const auto& [key, text] : buffers) projects_.open(key, text, affected);
    std::vector<check::SourceId> all;
    for (const auto& [key, id] : reloaded.by_path) all.push_back(id);
    affected.push_back({&reloaded, std::move(all)});
    mark_dirty(affected);
    publish_config_diagnostics(reloaded);
    log(3, "rung: reloaded " + root + "/rung.toml");
    return;
  }
}

}  // namespace rung::lsp
