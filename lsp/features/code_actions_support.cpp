#include "lsp/features/code_actions_support.hpp"

#include <algorithm>

#include "lsp/json_util.hpp"

namespace rung::lsp {

ActionRequest::ActionRequest(Session& session, const DocumentRef& document, TextRange range, const Json& context)
    : session_(session), document_(document), range_(range) {
  if (const Json& diagnostics = json_at(context, {"diagnostics"}); diagnostics.is_array()) {
    client_diagnostics_ = diagnostics;
  }
  if (const Json& only = json_at(context, {"only"}); only.is_array()) {
    for (const Json& kind : only) {
      if (kind.is_string()) only_.push_back(kind.get<std::string>());
    }
  }
  document_changes_ =
      json_at(session.client_capabilities(), {"workspace", "workspaceEdit", "documentChanges"}) == Json(true);
}

bool ActionRequest::wants(std::string_view kind) const {
  if (only_.empty()) return true;
  return std::any_of(only_.begin(), only_.end(), [&](const std::string& wanted) {
    return kind == wanted || (kind.starts_with(wanted) && kind.size() > wanted.size() && kind[wanted.size()] == '.');
  });
}

bool ActionRequest::asks_for(std::string_view kind) const {
  return std::any_of(only_.begin(), only_.end(), [&](const std::string& wanted) {
    return std::string_view(wanted) == kind || std::string_view(wanted).starts_with(std::string(kind) + ".") ||
           kind.starts_with(wanted + ".");
  });
}

bool ActionRequest::touches(TextRange range) const { return range.begin <= range_.end && range_.begin <= range.end; }

Json ActionRequest::workspace_edit(const std::vector<lint::TextEdit>& edits) const {
  std::vector<lint::TextEdit> sorted = edits;
  std::stable_sort(sorted.begin(), sorted.end(),
                   [](const lint::TextEdit& a, const lint::TextEdit& b) { return a.range.begin < b.range.begin; });
  Json text_edits = Json::array();
  for (const lint::TextEdit& edit : sorted) {
    text_edits.push_back({{"range", session_.range_of(document_, edit.range)}, {"newText", edit.replacement}});
  }
  if (document_changes_) {
    const OpenDocument* open = session_.open_document(document_.uri);
    return Json{{"documentChanges",
                 Json::array({{{"textDocument", {{"uri", document_.uri}, {"version", open ? Json(open->version) : Json()}}},
                               {"edits", std::move(text_edits)}}})}};
  }
  return Json{{"changes", {{document_.uri, std::move(text_edits)}}}};
}

void ActionRequest::add(std::string title, std::string_view kind, const std::vector<lint::TextEdit>& edits,
                        std::string_view diagnostic_code, TextRange diagnostic_range, bool preferred) {
  if (edits.empty() || !wants(kind)) return;
  Json action{{"title", std::move(title)}, {"kind", std::string(kind)}};
  if (!diagnostic_code.empty()) {
    const Json range = session_.range_of(document_, diagnostic_range);
    Json fixed = Json::array();
    for (const Json& diagnostic : client_diagnostics_) {
      if (diagnostic.is_object() && diagnostic.value("code", Json()) == Json(std::string(diagnostic_code)) &&
          diagnostic.value("range", Json()) == range) {
        fixed.push_back(diagnostic);
      }
    }
    if (!fixed.empty()) action["diagnostics"] = std::move(fixed);
  }
  if (preferred) action["isPreferred"] = true;
  action["edit"] = workspace_edit(edits);
  actions_.push_back(std::move(action));
}

}  // namespace rung::lsp
