#include "checker/query/definition.hpp"

#include "checker/query/position.hpp"
#include "checker/query/resolve.hpp"

namespace rung::check::query {

const Symbol* symbol_at(const Workspace& workspace, SourceId source, uint32_t file_offset) {
  const std::optional<QueryPoint> point = query_point(workspace, source, file_offset);
  if (!point || !point->name) return nullptr;
  return resolve_name(workspace.model(), source, point->name, point->scope);
}

std::optional<Location> definition_at(const Workspace& workspace, SourceId source, uint32_t file_offset) {
  const Symbol* symbol = symbol_at(workspace, source, file_offset);
  if (!symbol) return std::nullopt;
  return declaration_location(workspace.model(), *symbol);
}

Location declaration_location(const Workspace& workspace, const Symbol& symbol) {
  return declaration_location(workspace.model(), symbol);
}

}  // namespace rung::check::query
