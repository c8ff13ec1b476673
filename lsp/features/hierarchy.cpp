// Call hierarchy (who calls a POU, what it calls) and type hierarchy (EXTENDS, IMPLEMENTS), and
// the reference counts of code lens (hierarchy_lens.cpp). The answers come from checker/query
// (call_hierarchy, type_hierarchy); this file gives them the LSP shape.
#include <algorithm>

#include "checker/query/call_hierarchy.hpp"
#include "checker/query/type_hierarchy.hpp"
#include "lsp/features/features.hpp"
#include "lsp/features/hierarchy_items.hpp"
#include "lsp/features/hierarchy_lens.hpp"
#include "lsp/json_util.hpp"

namespace rung::lsp {
namespace {

using check::query::Call;

// The declaration at params.position that `pick` accepts, as a one-item array; null elsewhere.
template <typename Pick>
Json prepare(Session& session, const Json& params, Pick&& pick) {
  const DocumentRef document = session.document(params);
  if (document.project->removed.contains(document.source)) return nullptr;
  const uint32_t offset = session.offset_of(document, json_at(params, {"position"}));
  const check::Symbol* symbol = pick(document.workspace(), document.source, offset);
  if (!symbol) return nullptr;
  return Json::array({hierarchy_item(session, *document.project, *symbol)});
}

// Calls grouped by the declaration at their other end (the caller of incoming calls, the callee
// of outgoing ones), in the order the groups first appear; `ranges` are where the calls are written.
Json grouped_calls(const Session& session, const Project& project, const std::vector<Call>& calls, bool incoming) {
  std::vector<std::pair<const check::Symbol*, Json>> groups;
  for (const Call& call : calls) {
    const check::Symbol* other = incoming ? call.caller : call.callee;
    auto group = std::find_if(groups.begin(), groups.end(), [&](const auto& known) { return known.first == other; });
    if (group == groups.end()) group = groups.insert(groups.end(), {other, Json::array()});
    group->second.push_back(session.range_in(project, call.where.source, call.where.range));
  }
  Json result = Json::array();
  for (auto& [other, ranges] : groups) {
    result.push_back(
        {{incoming ? "from" : "to", hierarchy_item(session, project, *other)}, {"fromRanges", std::move(ranges)}});
  }
  return result;
}

Json incoming_calls(Session& session, const Json& params) {
  const std::optional<SymbolRef> target = symbol_of_params(session, params);
  if (!target) return Json::array();
  const std::vector<Call> calls = check::query::incoming_calls(*target->project->workspace, *target->symbol,
                                                               [&session] { return session.cancelled(); });
  if (session.cancelled()) return nullptr;  // the server answers RequestCancelled
  return grouped_calls(session, *target->project, calls, true);
}

Json outgoing_calls(Session& session, const Json& params) {
  const std::optional<SymbolRef> target = symbol_of_params(session, params);
  if (!target) return Json::array();
  const std::vector<Call> calls = check::query::outgoing_calls(*target->project->workspace, *target->symbol);
  return grouped_calls(session, *target->project, calls, false);
}

Json items_of(const Session& session, const Project& project, const std::vector<const check::Symbol*>& symbols) {
  Json items = Json::array();
  for (const check::Symbol* symbol : symbols) items.push_back(hierarchy_item(session, project, *symbol));
  return items;
}

Json supertypes(Session& session, const Json& params) {
  const std::optional<SymbolRef> target = symbol_of_params(session, params);
  if (!target) return Json::array();
  return items_of(session, *target->project, check::query::supertypes_of(*target->symbol));
}

Json subtypes(Session& session, const Json& params) {
  const std::optional<SymbolRef> target = symbol_of_params(session, params);
  if (!target) return Json::array();
  return items_of(session, *target->project, check::query::subtypes_of(target->project->model(), *target->symbol));
}

}  // namespace

void register_hierarchy(Router& router) {
  router.capabilities()["callHierarchyProvider"] = true;
  router.on_request("textDocument/prepareCallHierarchy", [](Session& session, const Json& params) {
    return prepare(session, params, check::query::call_hierarchy_symbol_at);
  });
  router.on_request("callHierarchy/incomingCalls", incoming_calls);
  router.on_request("callHierarchy/outgoingCalls", outgoing_calls);

  router.capabilities()["typeHierarchyProvider"] = true;
  router.on_request("textDocument/prepareTypeHierarchy", [](Session& session, const Json& params) {
    return prepare(session, params, check::query::type_hierarchy_symbol_at);
  });
  router.on_request("typeHierarchy/supertypes", supertypes);
  router.on_request("typeHierarchy/subtypes", subtypes);

  register_code_lens(router);
}

}  // namespace rung::lsp
