// Symbols: the outline of a file (textDocument/documentSymbol) and the search over every
// project's declarations (workspace/symbol). The answers come from checker/query (outline,
// symbol_search); this file gives them the LSP shape.
#include <set>

#include "checker/query/outline.hpp"
#include "checker/query/symbol_search.hpp"
#include "lsp/features/features.hpp"
#include "lsp/features/symbols_kinds.hpp"
#include "lsp/json_util.hpp"
#include "lsp/session.hpp"

namespace rung::lsp {
namespace {

using check::query::OutlineItem;
using check::query::OutlineKind;

constexpr size_t kMaxWorkspaceSymbols = 500;

Json document_symbol(const Session& session, const DocumentRef& document, const OutlineItem& item) {
  Json symbol{{"name", item.name},
              {"kind", lsp_symbol_kind(item.kind)},
              {"range", session.range_of(document, item.range)},
              {"selectionRange", session.range_of(document, item.selection)}};
  if (!item.detail.empty()) symbol["detail"] = item.detail;
  if (!item.children.empty()) {
    Json children = Json::array();
    for (const OutlineItem& child : item.children) children.push_back(document_symbol(session, document, child));
    symbol["children"] = std::move(children);
  }
  return symbol;
}

// SymbolInformation for clients without hierarchical symbols: every item with the name of the
// one it belongs to; VAR blocks are left out (their variables belong to the POU).
void flat_symbols(const Session& session, const DocumentRef& document, const std::vector<OutlineItem>& items,
                  const std::string& container, Json& out) {
  for (const OutlineItem& item : items) {
    if (item.kind == OutlineKind::VarBlock) {
      flat_symbols(session, document, item.children, container, out);
      continue;
    }
    Json symbol{{"name", item.name},
                {"kind", lsp_symbol_kind(item.kind)},
                {"location", {{"uri", document.uri}, {"range", session.range_of(document, item.range)}}}};
    if (!container.empty()) symbol["containerName"] = container;
    out.push_back(std::move(symbol));
    flat_symbols(session, document, item.children, item.name, out);
  }
}

Json document_symbols(Session& session, const Json& params) {
  const DocumentRef document = session.document(params);
  Json result = Json::array();
  if (document.project->removed.contains(document.source)) return result;
  const std::vector<OutlineItem> outline = check::query::document_outline(document.model(), document.source);
  const Json& hierarchical =
      json_at(session.client_capabilities(), {"textDocument", "documentSymbol", "hierarchicalDocumentSymbolSupport"});
  if (hierarchical.is_boolean() && hierarchical.get<bool>()) {
    for (const OutlineItem& item : outline) result.push_back(document_symbol(session, document, item));
  } else {
    flat_symbols(session, document, outline, {}, result);
  }
  return result;
}

struct FoundSymbol {
  const Project* project = nullptr;
  check::query::SymbolMatch match;
};

Json workspace_symbols(Session& session, const Json& params) {
  const std::string query = json_string(params, "query");
  std::vector<FoundSymbol> found;
  for (const auto& project : session.projects()) {
    check::query::SymbolSearch search{.limit = kMaxWorkspaceSymbols,
                                      .skip = [&](check::SourceId id) { return project->removed.contains(id); },
                                      .cancelled = [&] { return session.cancelled(); }};
    for (auto& match : check::query::search_symbols(project->model(), query, search)) {
      found.push_back({project.get(), std::move(match)});
    }
  }
  if (session.cancelled()) return nullptr;  // the server answers RequestCancelled
  std::stable_sort(found.begin(), found.end(), [](const FoundSymbol& a, const FoundSymbol& b) {
    return check::query::better_match(a.match, b.match);
  });
  Json result = Json::array();
  // Every project loads the stub libraries: one entry per declaration.
  std::set<std::pair<std::string, uint32_t>> seen;
  for (const FoundSymbol& entry : found) {
    if (result.size() >= kMaxWorkspaceSymbols) break;
    const check::Symbol& symbol = *entry.match.symbol;
    const std::string uri = session.uri_of(*entry.project, symbol.source);
    const TextRange name = check::query::name_range_in_file(entry.project->model(), symbol);
    if (!seen.emplace(uri, name.begin).second) continue;
    Json information{{"name", entry.match.name},
                     {"kind", lsp_symbol_kind(check::query::outline_kind_of(symbol))},
                     {"location", {{"uri", uri}, {"range", session.range_in(*entry.project, symbol.source, name)}}}};
    if (!entry.match.container.empty()) information["containerName"] = entry.match.container;
    result.push_back(std::move(information));
  }
  return result;
}

}  // namespace

void register_symbols(Router& router) {
  router.capabilities()["documentSymbolProvider"] = true;
  router.on_request("textDocument/documentSymbol", document_symbols);
  router.capabilities()["workspaceSymbolProvider"] = true;
  router.on_request("workspace/symbol", workspace_symbols);
}

}  // namespace rung::lsp
