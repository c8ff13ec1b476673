#include "checker/query/members.hpp"

#include <unordered_set>

namespace rung::check::query {
namespace {

constexpr int kMaxInheritanceDepth = 32;  // EXTENDS may form a cycle in broken code

bool shown_after_dot(const Symbol& container, const Symbol& member) {
  if (member.has(kHide) || member.name.empty()) return false;
  switch (member.kind) {
    case SymbolKind::EnumValue:
    case SymbolKind::Method:
    case SymbolKind::Property:
    case SymbolKind::Action: return true;
    case SymbolKind::Variable: break;
    default: return false;  // POU-local types
  }
  if (container.kind == SymbolKind::DataType || container.kind == SymbolKind::GlobalList) return true;
  const ast::VarSection section = member.section;
  if (container.kind == SymbolKind::Program) return section != ast::VarSection::Temp;
  return section == ast::VarSection::Input || section == ast::VarSection::Output || section == ast::VarSection::InOut;
}

void add_members(const Symbol& container, const Symbol& declaring, int depth,
                 std::unordered_set<std::string_view, NameHash, NameEqual>& seen, std::vector<const Symbol*>& out) {
  if (depth > kMaxInheritanceDepth) return;
  for (const Symbol* member : declaring.ordered) {
    if (shown_after_dot(container, *member) && seen.insert(member->name).second) out.push_back(member);
  }
  // Interfaces may extend several interfaces; every other kind extends one base.
  for (const Symbol* base : declaring.bases) add_members(container, *base, depth + 1, seen, out);
}

}  // namespace

std::vector<const Symbol*> members_of(const Symbol* container) {
  std::vector<const Symbol*> members;
  if (!container) return members;
  std::unordered_set<std::string_view, NameHash, NameEqual> seen;
  add_members(*container, *container, 0, seen, members);
  return members;
}

std::vector<const Symbol*> members_of(const Type* type) {
  if (!type) return {};
  type = underlying(type);
  if (type->kind == TypeKind::Reference && type->element) type = underlying(type->element);
  if (type->kind != TypeKind::Struct && type->kind != TypeKind::Union && type->kind != TypeKind::Pou) return {};
  return members_of(type->declaration);
}

}  // namespace rung::check::query
