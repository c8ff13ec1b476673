#include "lsp/features/navigation_rename.hpp"

#include "checker/query/rename.hpp"
#include "lsp/json_util.hpp"

namespace rung::lsp {
namespace {

namespace query = check::query;

// The symbol under the cursor, or RequestFailed with why it cannot be renamed.
query::RenameTarget target_of(Session& session, const DocumentRef& document, const Json& params) {
  if (document.project->removed.contains(document.source)) {
    throw RpcError{ErrorCode::RequestFailed, "the file was deleted"};
  }
  const uint32_t offset = session.offset_of(document, json_at(params, {"position"}));
  query::RenameTarget target = query::rename_target(document.workspace(), document.source, offset);
  if (!target.symbol) throw RpcError{ErrorCode::RequestFailed, "cannot rename here: " + target.refusal};
  return target;
}

// The open buffer's version of `uri` (null for a file only on disk: the client edits it as it is).
Json version_of(const Session& session, const std::string& uri) {
  const OpenDocument* open = session.open_document(uri);
  return open ? Json(open->version) : Json(nullptr);
}

Json workspace_edit(const Session& session, const Project& project, const std::vector<query::TextEdit>& edits,
                    bool document_changes) {
  // The edits come sorted by file, so each file's edits are one run.
  std::vector<std::pair<std::string, Json>> files;
  for (const query::TextEdit& edit : edits) {
    std::string uri = session.uri_of(project, edit.location.source);
    if (files.empty() || files.back().first != uri) files.emplace_back(std::move(uri), Json::array());
    files.back().second.push_back(
        {{"range", session.range_in(project, edit.location.source, edit.location.range)}, {"newText", edit.new_text}});
  }
  if (document_changes) {
    Json changes = Json::array();
    for (auto& [uri, file_edits] : files) {
      changes.push_back(
          {{"textDocument", {{"uri", uri}, {"version", version_of(session, uri)}}}, {"edits", std::move(file_edits)}});
    }
    return Json{{"documentChanges", std::move(changes)}};
  }
  Json changes = Json::object();
  for (auto& [uri, file_edits] : files) changes[uri] = std::move(file_edits);
  return Json{{"changes", std::move(changes)}};
}

}  // namespace

Json prepare_rename(Session& session, const Json& params) {
  const DocumentRef document = session.document(params);
  const query::RenameTarget target = target_of(session, document, params);
  return Json{{"range", session.range_of(document, target.name.range)}, {"placeholder", target.placeholder}};
}

Json rename(Session& session, const Json& params) {
  const DocumentRef document = session.document(params);
  const Json& new_name = json_at(params, {"newName"});
  if (!new_name.is_string()) throw RpcError{ErrorCode::InvalidParams, "params.newName must be a string"};
  const query::RenameTarget target = target_of(session, document, params);
  const query::RenamePlan plan =
      query::plan_rename(document.workspace(), *target.symbol, new_name.get_ref<const std::string&>());
  if (!plan.refusal.empty()) throw RpcError{ErrorCode::RequestFailed, "cannot rename: " + plan.refusal};
  const bool document_changes =
      json_at(session.client_capabilities(), {"workspace", "workspaceEdit", "documentChanges"}) == Json(true);
  return workspace_edit(session, *document.project, plan.edits, document_changes);
}

}  // namespace rung::lsp
