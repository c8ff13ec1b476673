// Call and type hierarchy items (LSP CallHierarchyItem / TypeHierarchyItem, which share their
// shape): a declaration as the client shows it, and the `data` that finds it again when the client
// hands the item back with callHierarchy/incomingCalls or typeHierarchy/subtypes.
#pragma once

#include <optional>

#include "lsp/session.hpp"

namespace rung::lsp {

struct SymbolRef {
  Project* project = nullptr;
  const check::Symbol* symbol = nullptr;
};

// The item of `symbol`, declared in a file of `project` (a stub library's file too).
Json hierarchy_item(const Session& session, const Project& project, const check::Symbol& symbol);

// The declaration an item the server made stands for; nullopt when it is gone (its file was
// deleted, its project closed, the declaration removed).
std::optional<SymbolRef> symbol_of_item(Session& session, const Json& item);

// Owner.Member.Accessor: with the name token's start, what finds a declaration again when the
// client hands it back (find_declaration).
std::string qualified_name(const check::Symbol& symbol);
// The declaration of `source` whose name token starts at tree offset `at` and spells the last part
// of `qualified`; else (the file changed since) the one `qualified` names, "" naming the file's
// unnamed snippet; nullptr if there is none.
const check::Symbol* find_declaration(const check::ProjectModel& model, check::SourceId source, uint32_t at,
                                      std::string_view qualified);

// The project-wide declaration a request's params.item names (throws RpcError(InvalidParams)
// when params has no item object).
std::optional<SymbolRef> symbol_of_params(Session& session, const Json& params);

}  // namespace rung::lsp
