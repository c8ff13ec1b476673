// The state of one language server session and the API every feature handler uses: find the
// document a request names, convert LSP positions (line + UTF-16 column in the file the editor
// shows) to rung's byte offsets and back, send notifications. Everything here runs on the
// server's single worker thread, so handlers read the projects without locks.
#pragma once

#include <atomic>
#include <chrono>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "checker/query/location.hpp"
#include "lsp/json_rpc.hpp"
#include "lsp/projects.hpp"

namespace rung::lsp {

// A file a request is about, as features see it.
struct DocumentRef {
  Project* project = nullptr;
  check::SourceId source = check::kNoSource;
  std::string uri;

  const check::Workspace& workspace() const { return *project->workspace; }
  const check::ProjectModel& model() const { return project->workspace->model(); }
  const Document& document() const { return *model().source(source).document; }
  const project::ProjectConfig& settings() const { return project->settings(); }
};

// An editor's open buffer.
struct OpenDocument {
  std::string uri;
  std::string key;  // ProjectSet key
  int64_t version = 0;
  std::string language_id;
};

using Sink = std::function<void(const Json& message)>;

class Session {
 public:
  explicit Session(Sink sink, check::LoadOptions load_options = {});

  // ---- For feature handlers ------------------------------------------------------------------
  // The document `params.textDocument.uri` names; RpcError(InvalidParams) if it is unknown.
  DocumentRef document(const Json& params);
  std::optional<DocumentRef> find_document(std::string_view uri);
  // params.position as a byte offset of the FILE text; RpcError(InvalidParams) if malformed.
  // Positions past a line's end or the last line clamp, as the protocol asks.
  uint32_t offset_of(const DocumentRef& document, const Json& position) const;
  Json position_of(const DocumentRef& document, uint32_t file_offset) const;
  Json range_of(const DocumentRef& document, TextRange file_range) const;
  // The same for any file of a project (a definition in another file, a library stub).
  Json range_in(const Project& project, check::SourceId source, TextRange file_range) const;
  std::string uri_of(const Project& project, check::SourceId source) const;
  // LSP Location {uri, range} of a query answer found in `project`.
  Json location_of(const Project& project, const check::query::Location& location) const;
  // Every loaded project (loose ones too).
  const std::vector<std::unique_ptr<Project>>& projects() const { return projects_.projects(); }
  // The open buffer of `uri`, if the editor has it open.
  const OpenDocument* open_document(std::string_view uri) const;

  // The client's ClientCapabilities from initialize.
  const Json& client_capabilities() const { return client_capabilities_; }
  // True once the client cancelled the request being answered: stop and return anything.
  bool cancelled() const { return current_cancel_ && current_cancel_->load(); }
  void notify(std::string_view method, Json params) const;
  // window/logMessage (type 1 error .. 4 log).
  void log(int type, std::string_view message) const;

  // ---- For the server ------------------------------------------------------------------------
  // Notifications and lifecycle requests the session answers itself (documents, workspace,
  // initialize); false when `method` is none of them.
  bool handle_lifecycle(std::string_view method, const Json& params, Json* result);
  // One step of background work (diagnostics of changed files); false when there is none.
  bool background_step();
  bool shutdown_requested() const { return shutdown_requested_; }
  bool initialized() const { return initialize_done_; }
  void set_current_cancel(const std::atomic<bool>* flag) { current_cancel_ = flag; }
  void set_capabilities(const Json& server_capabilities) { server_capabilities_ = server_capabilities; }
  // Diagnostics of one file (checker and linter), LSP Diagnostic objects; for push and pull.
  Json diagnostics_of(const DocumentRef& document) const;

 private:
  Json initialize(const Json& params);
  void initialized_notification();
  void did_open(const Json& params);
  void did_change(const Json& params);
  void did_close(const Json& params);
  void did_save(const Json& params);
  void did_change_watched_files(const Json& params);
  void did_change_workspace_folders(const Json& params);
  void index_folders(const std::vector<std::filesystem::path>& folders);
  void mark_dirty(const std::vector<Affected>& affected);
  void publish(const DocumentRef& document);
  // rung.toml findings (P001-P003) on the rung.toml itself.
  void publish_config_diagnostics(const Project& project);
  void publish_config_text(const std::string& uri, const std::filesystem::path& folder, const std::string& text);
  void reload_project_at(const std::filesystem::path& folder);
  // Forgets due work of a project about to be dropped or reloaded.
  void drop_project(const Project* project);
  void clear_published(const Project& project);
  std::string key_of_uri(std::string_view uri) const;
  std::optional<Json> position_from_offset(const Document& document, uint32_t file_offset) const;

  Sink sink_;
  ProjectSet projects_;
  Json client_capabilities_ = Json::object();
  Json server_capabilities_ = Json::object();
  std::vector<std::filesystem::path> pending_folders_;  // from initialize, indexed on initialized
  std::map<std::string, OpenDocument, std::less<>> open_;  // by URI
  // Files whose diagnostics are due: open ones first, then the rest of the project.
  std::set<std::pair<Project*, check::SourceId>> dirty_open_;
  std::set<std::pair<Project*, check::SourceId>> dirty_background_;
  std::set<std::string> published_;  // URIs with non-empty diagnostics on the client
  const std::atomic<bool>* current_cancel_ = nullptr;
  bool initialize_done_ = false;
  bool shutdown_requested_ = false;
  bool push_diagnostics_ = true;
  bool work_done_progress_ = false;
  int progress_tokens_ = 0;
};

}  // namespace rung::lsp
