// Pull diagnostics (textDocument/diagnostic, LSP 3.17): the same findings the server pushes to
// clients that do not pull. A result id per project generation lets the client skip unchanged
// reports.
#include "lsp/features/features.hpp"
#include "lsp/session.hpp"

namespace rung::lsp {

void register_diagnostics(Router& router) {
  router.on_request("textDocument/diagnostic", [](Session& session, const Json& params) {
    const DocumentRef document = session.document(params);
    const std::string result_id = std::to_string(document.project->generation) + ":" + std::to_string(document.source);
    if (params.is_object() && params.value("previousResultId", Json()) == result_id) {
      return Json{{"kind", "unchanged"}, {"resultId", result_id}};
    }
    return Json{{"kind", "full"}, {"resultId", result_id}, {"items", session.diagnostics_of(document)}};
  });
}

}  // namespace rung::lsp
