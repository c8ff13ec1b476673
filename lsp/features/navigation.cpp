// Navigation: go to definition, declaration, type definition and implementation, find references,
// document highlight; rename is in navigation_rename.cpp. Every answer comes from checker/query
// (definition, targets, implementations, references, highlights); this file gives it the LSP
// shape. Positions are FILE offsets throughout, so TwinCAT and .EXP containers answer in their
// own lines.
#include "checker/query/definition.hpp"
#include "checker/query/highlights.hpp"
#include "checker/query/implementations.hpp"
#include "checker/query/references.hpp"
#include "checker/query/targets.hpp"
#include "lsp/features/features.hpp"
#include "lsp/features/navigation_rename.hpp"
#include "lsp/json_util.hpp"
#include "lsp/session.hpp"

namespace rung::lsp {
namespace {

namespace query = check::query;

// LSP DocumentHighlightKind.
constexpr int kHighlightText = 1;
constexpr int kHighlightRead = 2;
constexpr int kHighlightWrite = 3;

// A handler of a request at params.textDocument + params.position: `answer` gets the document
// and the FILE offset. A file deleted on disk (the model keeps it empty until the editor lets go
// of it) answers null.
template <typename Answer>
RequestHandler at_cursor(Answer answer) {
  return [answer](Session& session, const Json& params) -> Json {
    const DocumentRef document = session.document(params);
    if (document.project->removed.contains(document.source)) return nullptr;
    return answer(session, document, session.offset_of(document, json_at(params, {"position"})), params);
  };
}

Json location_or_null(const Session& session, const Project& project, const std::optional<query::Location>& location) {
  return location ? session.location_of(project, *location) : Json(nullptr);
}

Json definition(const Session& session, const DocumentRef& document, uint32_t offset, const Json& /*params*/) {
  return location_or_null(session, *document.project,
                          query::definition_at(document.workspace(), document.source, offset));
}

Json declaration(const Session& session, const DocumentRef& document, uint32_t offset, const Json& /*params*/) {
  return location_or_null(session, *document.project,
                          query::declaration_at(document.workspace(), document.source, offset));
}

Json type_definition(const Session& session, const DocumentRef& document, uint32_t offset, const Json& /*params*/) {
  const check::Symbol* type = query::type_definition_at(document.workspace(), document.source, offset);
  if (!type) return nullptr;
  return session.location_of(*document.project, query::declaration_location(document.model(), *type));
}

Json implementation(const Session& session, const DocumentRef& document, uint32_t offset, const Json& /*params*/) {
  const check::Symbol* symbol = query::symbol_at(document.workspace(), document.source, offset);
  if (!symbol) return nullptr;
  Json locations = Json::array();
  for (const check::Symbol* found : query::implementations_of(document.model(), *symbol)) {
    locations.push_back(session.location_of(*document.project, query::declaration_location(document.model(), *found)));
  }
  return locations;
}

Json references(const Session& session, const DocumentRef& document, uint32_t offset, const Json& params) {
  const check::Symbol* symbol = query::symbol_at(document.workspace(), document.source, offset);
  if (!symbol) return nullptr;
  const bool include_declaration = json_at(params, {"context", "includeDeclaration"}) == Json(true);
  Json locations = Json::array();
  for (const query::Location& location : query::find_references(document.workspace(), symbol, include_declaration)) {
    if (!document.project->removed.contains(location.source)) {
      locations.push_back(session.location_of(*document.project, location));
    }
  }
  return locations;
}

Json document_highlight(const Session& session, const DocumentRef& document, uint32_t offset, const Json& /*params*/) {
  const check::Symbol* symbol = query::symbol_at(document.workspace(), document.source, offset);
  if (!symbol) return nullptr;
  Json highlights = Json::array();
  for (const query::Highlight& highlight : query::highlights_in(document.workspace(), symbol, document.source)) {
    const int kind = highlight.access == query::Access::Write  ? kHighlightWrite
                     : highlight.access == query::Access::Read ? kHighlightRead
                                                               : kHighlightText;
    highlights.push_back({{"range", session.range_of(document, highlight.location.range)}, {"kind", kind}});
  }
  return highlights;
}

}  // namespace

void register_navigation(Router& router) {
  router.on_request("textDocument/definition", at_cursor(definition));
  router.on_request("textDocument/declaration", at_cursor(declaration));
  router.on_request("textDocument/typeDefinition", at_cursor(type_definition));
  router.on_request("textDocument/implementation", at_cursor(implementation));
  router.on_request("textDocument/references", at_cursor(references));
  router.on_request("textDocument/documentHighlight", at_cursor(document_highlight));
  router.on_request("textDocument/prepareRename", prepare_rename);
  router.on_request("textDocument/rename", rename);
  Json& capabilities = router.capabilities();
  capabilities["definitionProvider"] = true;
  capabilities["declarationProvider"] = true;
  capabilities["typeDefinitionProvider"] = true;
  capabilities["implementationProvider"] = true;
  capabilities["referencesProvider"] = true;
  capabilities["documentHighlightProvider"] = true;
  capabilities["renameProvider"] = Json{{"prepareProvider", true}};
}

}  // namespace rung::lsp
