// textDocument/codeAction: quick fixes for lint and checker findings, "fix all" source actions,
// and refactorings (ELSE for a CASE, formal <-> informal calls). Every action carries its edit
// (no codeAction/resolve round trip: the edits are small and computed from one check of the
// file). The groups live in code_actions_lint.cpp, code_actions_checker.cpp and
// code_actions_refactor.cpp; the decisions in checker/query and checker/lint.
#include "lsp/features/code_actions_support.hpp"
#include "lsp/features/features.hpp"
#include "lsp/json_util.hpp"

namespace rung::lsp {
namespace {

Json code_action(Session& session, const Json& params) {
  const DocumentRef document = session.document(params);
  const Json& range = json_at(params, {"range"});
  if (!range.is_object()) throw RpcError{ErrorCode::InvalidParams, "params.range is missing"};
  if (document.project->removed.contains(document.source) || !document.document().tree()) return Json::array();
  const uint32_t begin = session.offset_of(document, range.value("start", Json()));
  const uint32_t end = session.offset_of(document, range.value("end", Json()));
  ActionRequest request(session, document, TextRange{std::min(begin, end), std::max(begin, end)},
                        json_at(params, {"context"}));
  add_checker_actions(request);
  if (!session.cancelled()) add_lint_actions(request);
  if (!session.cancelled()) add_refactorings(request);
  return request.take();
}

}  // namespace

void register_code_actions(Router& router) {
  router.on_request("textDocument/codeAction", code_action);
  router.capabilities()["codeActionProvider"] = Json{
      {"codeActionKinds", Json::array({std::string(kQuickFix), std::string(kRefactorRewrite), std::string(kFixAll),
                                       std::string(kFixRule)})},
      {"resolveProvider", false}};
}

}  // namespace rung::lsp
