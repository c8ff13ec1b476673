#include "checker/query/targets.hpp"

#include "checker/query/definition.hpp"
#include "checker/query/position.hpp"
#include "checker/query/resolve.hpp"
#include "checker/query/type_at.hpp"

namespace rung::check::query {
namespace {

constexpr int kMaxTypeDepth = 64;  // ARRAY OF POINTER TO ... nests, but not without end

// The first named type on the way from `type` to its elements and targets.
const Symbol* declared_type(const Type* type) {
  for (int depth = 0; type && depth < kMaxTypeDepth; ++depth, type = type->element) {
    if (type->declaration) return type->declaration;
    if (type->kind != TypeKind::Array && type->kind != TypeKind::Pointer && type->kind != TypeKind::Reference) break;
  }
  return nullptr;
}

bool is_type_symbol(const Symbol& symbol) {
  return symbol.kind == SymbolKind::DataType || symbol.kind == SymbolKind::FunctionBlock ||
         symbol.kind == SymbolKind::Class || symbol.kind == SymbolKind::Interface;
}

bool has_result(const Symbol& symbol) {
  return symbol.kind == SymbolKind::Function || symbol.kind == SymbolKind::Method ||
         symbol.kind == SymbolKind::Property;
}

}  // namespace

std::optional<Location> declaration_at(const Workspace& workspace, SourceId source, uint32_t file_offset) {
  const ProjectModel& model = workspace.model();
  const std::optional<QueryPoint> point = query_point(workspace, source, file_offset);
  if (!point || !point->name) return std::nullopt;
  const Symbol* symbol = resolve_name(model, source, point->name, point->scope);
  if (!symbol) return std::nullopt;
  const NameSite site = name_site(model, source, point->name);
  const bool bare_name =
      (site.use == NameUse::Expression && site.expression == point->name) || site.use == NameUse::IlOperator;
  if (bare_name && point->scope && symbol->kind == SymbolKind::Variable) {
    // The name as the POU sees it: its own VAR_EXTERNAL comes before the global.
    const Symbol* local = model.lookup(point->scope, point->name.text());
    if (local && local != symbol && local->section == ast::VarSection::External &&
        canonical_symbol(model, local) == symbol) {
      return declaration_location(model, *local);
    }
  }
  return declaration_location(model, *symbol);
}

const Symbol* type_definition_at(const Workspace& workspace, SourceId source, uint32_t file_offset) {
  const ProjectModel& model = workspace.model();
  if (const Symbol* symbol = symbol_at(workspace, source, file_offset)) {
    if (is_type_symbol(*symbol)) return symbol;
    if (has_result(*symbol)) return declared_type(symbol->result_type);
    if (symbol->kind == SymbolKind::Variable || symbol->kind == SymbolKind::EnumValue) {
      return declared_type(model.type_of(symbol));
    }
  }
  // Anything else under the cursor that has a type: obj.member, a[i], a call, E#v.
  return declared_type(type_at(workspace, source, file_offset));
}

}  // namespace rung::check::query
