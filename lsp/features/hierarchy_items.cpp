#include "lsp/features/hierarchy_items.hpp"

#include <filesystem>

#include "checker/query/location.hpp"
#include "checker/query/outline.hpp"
#include "checker/query/resolve.hpp"
#include "lsp/features/symbols_kinds.hpp"
#include "lsp/json_util.hpp"

namespace rung::lsp {
namespace {

std::string file_name(const check::ProjectModel& model, check::SourceId source) {
  return std::filesystem::path(model.source(source).document->path()).filename().string();
}

// The declaration called `qualified` (Owner.Member) in `source`; "" is the file's unnamed snippet.
const check::Symbol* find_by_name(const check::ProjectModel& model, check::SourceId source,
                                  std::string_view qualified) {
  const size_t dot = qualified.find('.');
  const std::string_view first = qualified.substr(0, dot);
  const check::Symbol* found = nullptr;
  for (const check::Symbol* top : model.source(source).symbols.top_level) {
    if (!found && check::names_equal(top->name, first) && (!first.empty() || top->kind == check::SymbolKind::Program))
      found = top;
  }
  for (size_t begin = dot; found && begin != std::string_view::npos;) {
    const size_t next = qualified.find('.', begin + 1);
    found = found->own_member(qualified.substr(begin + 1, next == std::string_view::npos ? next : next - begin - 1));
    begin = next;
  }
  return found;
}

}  // namespace

std::string qualified_name(const check::Symbol& symbol) {
  std::string name(symbol.name);
  for (const check::Symbol* owner = symbol.owner; owner; owner = owner->owner) {
    name.insert(0, 1, '.').insert(0, owner->name);
  }
  return name;
}

const check::Symbol* find_declaration(const check::ProjectModel& model, check::SourceId source, uint32_t at,
                                      std::string_view qualified) {
  const size_t dot = qualified.rfind('.');
  const std::string_view last = qualified.substr(dot == std::string_view::npos ? 0 : dot + 1);
  const check::Symbol* symbol =
      last.empty() ? nullptr
                   : check::query::symbol_declared_at(model, source, {at, static_cast<uint32_t>(at + last.size())});
  return symbol && check::names_equal(symbol->name, last) ? symbol : find_by_name(model, source, qualified);
}

Json hierarchy_item(const Session& session, const Project& project, const check::Symbol& symbol) {
  const check::ProjectModel& model = project.model();
  const check::Source& source = model.source(symbol.source);
  const TextRange name = check::query::name_range_in_file(model, symbol);
  TextRange range = name;
  if (symbol.node) {
    const TextRange node = check::query::location_in_file(model, symbol.source, symbol.node.range()).range;
    range = {std::min(node.begin, name.begin), std::max(node.end, name.end)};
  }
  std::string detail = symbol.owner     ? qualified_name(*symbol.owner)
                       : source.library ? source.library_name
                                        : file_name(model, symbol.source);
  Json item{{"name", symbol.name.empty() ? file_name(model, symbol.source) : std::string(symbol.name)},
            {"kind", lsp_symbol_kind(check::query::outline_kind_of(symbol))},
            {"uri", session.uri_of(project, symbol.source)},
            {"range", session.range_in(project, symbol.source, range)},
            {"selectionRange", session.range_in(project, symbol.source, name)},
            {"data",
             {{"root", project.root.string()},
              {"path", source.document->path()},
              {"at", symbol.name_range.begin},
              {"name", qualified_name(symbol)}}}};
  if (!detail.empty()) item["detail"] = std::move(detail);
  return item;
}

std::optional<SymbolRef> symbol_of_item(Session& session, const Json& item) {
  const Json& data = json_at(item, {"data"});
  const std::string root = json_string(data, "root");
  const std::string path = json_string(data, "path");
  const std::string name = json_string(data, "name");
  const Json& at_field = json_at(data, {"at"});
  if (!at_field.is_number_unsigned()) return std::nullopt;
  const auto at = at_field.get<uint32_t>();
  for (const auto& project : session.projects()) {
    if (project->root.string() != root) continue;
    const std::optional<check::SourceId> source = project->model().find_source(path);
    if (!source || project->removed.contains(*source)) continue;
    if (const check::Symbol* symbol = find_declaration(project->model(), *source, at, name)) {
      return SymbolRef{project.get(), symbol};
    }
  }
  return std::nullopt;
}

std::optional<SymbolRef> symbol_of_params(Session& session, const Json& params) {
  const Json& item = json_at(params, {"item"});
  if (!item.is_object()) throw RpcError{ErrorCode::InvalidParams, "params.item is missing"};
  return symbol_of_item(session, item);
}

}  // namespace rung::lsp
