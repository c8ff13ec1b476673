#include "checker/query/type_hierarchy.hpp"

#include <algorithm>

#include "checker/query/definition.hpp"
#include "checker/query/targets.hpp"

namespace rung::check::query {
namespace {

bool contains(const std::vector<const Symbol*>& symbols, const Symbol* symbol) {
  return std::find(symbols.begin(), symbols.end(), symbol) != symbols.end();
}

}  // namespace

bool takes_part_in_types(const Symbol& symbol) {
  switch (symbol.kind) {
    case SymbolKind::FunctionBlock:
    case SymbolKind::Class:
    case SymbolKind::Interface: return true;
    case SymbolKind::DataType: return symbol.node && symbol.node.kind() == "struct_type";
    default: return false;
  }
}

const Symbol* type_hierarchy_symbol_at(const Workspace& workspace, SourceId source, uint32_t file_offset) {
  const Symbol* named = symbol_at(workspace, source, file_offset);
  if (named && takes_part_in_types(*named)) return named;
  // A variable, member or expression: its type.
  const Symbol* type = named ? type_definition_at(workspace, source, file_offset) : nullptr;
  return type && takes_part_in_types(*type) ? type : nullptr;
}

std::vector<const Symbol*> supertypes_of(const Symbol& type) {
  std::vector<const Symbol*> supertypes;
  for (const Symbol* base : type.bases) {
    if (base && !contains(supertypes, base)) supertypes.push_back(base);
  }
  for (const Symbol* interface : type.interfaces) {
    if (interface && !contains(supertypes, interface)) supertypes.push_back(interface);
  }
  return supertypes;
}

std::vector<const Symbol*> subtypes_of(const ProjectModel& model, const Symbol& type) {
  std::vector<const Symbol*> subtypes;
  for (SourceId id = 0; id < model.source_count(); ++id) {
    for (const Symbol* candidate : model.source(id).symbols.top_level) {
      if (candidate != &type && takes_part_in_types(*candidate) &&
          (contains(candidate->bases, &type) || contains(candidate->interfaces, &type))) {
        subtypes.push_back(candidate);
      }
    }
  }
  return subtypes;
}

}  // namespace rung::check::query
