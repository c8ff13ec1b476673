// Code lens with reference counts. Counting is a project-wide search per declaration, so the
// lenses of a file come without their command and each is counted when the editor shows it
// (codeLens/resolve): a long file with hundreds of methods opens without waiting for all of them.
#include "lsp/features/hierarchy_lens.hpp"

#include "checker/query/outline.hpp"
#include "checker/query/references.hpp"
#include "lsp/features/hierarchy_items.hpp"
#include "lsp/json_util.hpp"
#include "lsp/session.hpp"

namespace rung::lsp {
namespace {

// The client-side command that lists the references (arguments: uri, position, locations, as
// VS Code's editor.action.showReferences takes them); see docs/lsp.md for Neovim.
constexpr const char* kShowReferences = "rung.showReferences";

bool has_lens(const check::Symbol& symbol) {
  if (symbol.name.empty()) return false;  // a file's statements without a POU
  switch (symbol.kind) {
    case check::SymbolKind::Program:
    case check::SymbolKind::Function:
    case check::SymbolKind::FunctionBlock:
    case check::SymbolKind::Class:
    case check::SymbolKind::Interface:
    case check::SymbolKind::Property:
    case check::SymbolKind::Action:
    case check::SymbolKind::DataType: return true;
    case check::SymbolKind::Method:  // not a property's GET or SET
      return !symbol.owner || symbol.owner->kind != check::SymbolKind::Property;
    default: return false;
  }
}

void add_lenses(const Session& session, const DocumentRef& document, const check::Symbol& symbol, Json& lenses) {
  if (has_lens(symbol)) {
    const TextRange name = check::query::name_range_in_file(document.model(), symbol);
    lenses.push_back(
        {{"range", session.range_of(document, name)},
         {"data", {{"uri", document.uri}, {"at", symbol.name_range.begin}, {"name", qualified_name(symbol)}}}});
  }
  if (symbol.kind == check::SymbolKind::GlobalList) return;  // variables only
  for (const check::Symbol* member : symbol.ordered) {
    if (member->kind != check::SymbolKind::Variable && member->kind != check::SymbolKind::EnumValue) {
      add_lenses(session, document, *member, lenses);
    }
  }
}

Json code_lenses(Session& session, const Json& params) {
  const DocumentRef document = session.document(params);
  Json lenses = Json::array();
  if (document.project->removed.contains(document.source)) return lenses;
  for (const check::Symbol* top : document.model().source(document.source).symbols.top_level) {
    add_lenses(session, document, *top, lenses);
  }
  return lenses;
}

std::string count_title(size_t count) {
  return std::to_string(count) + (count == 1 ? " reference" : " references");
}

Json resolve_lens(Session& session, const Json& lens) {
  if (!lens.is_object() || !lens.contains("range"))
    throw RpcError{ErrorCode::InvalidParams, "params must be a CodeLens"};
  Json resolved = lens;
  const Json& data = json_at(lens, {"data"});
  const Json& at = json_at(data, {"at"});
  const std::optional<DocumentRef> document = session.find_document(json_string(data, "uri"));
  const check::Symbol* symbol =
      document && at.is_number_unsigned()
          ? find_declaration(document->model(), document->source, at.get<uint32_t>(), json_string(data, "name"))
          : nullptr;
  // A declaration that is gone (the file changed or was deleted) has no references any more.
  Json locations = Json::array();
  Json position = json_at(lens, {"range", "start"});
  if (symbol) {
    for (const check::query::Location& location : check::query::find_references(document->workspace(), symbol, false)) {
      locations.push_back(session.location_of(*document->project, location));
    }
    position = session.position_of(*document, check::query::name_range_in_file(document->model(), *symbol).begin);
  }
  resolved["command"] = {{"title", count_title(locations.size())},
                         {"command", kShowReferences},
                         {"arguments", {json_string(data, "uri"), position, locations}}};
  return resolved;
}

}  // namespace

void register_code_lens(Router& router) {
  router.capabilities()["codeLensProvider"] = {{"resolveProvider", true}};
  router.on_request("textDocument/codeLens", code_lenses);
  router.on_request("codeLens/resolve", resolve_lens);
}

}  // namespace rung::lsp
