#include "checker/semantic/type_size.hpp"

#include <algorithm>

namespace rung::check {
namespace {

constexpr uint64_t kMaxAlignment = 8;  // {attribute 'pack_mode' := '8'}, the 64-bit default
constexpr uint64_t kPointerBytes = 8;
constexpr int kMaxDepth = 32;  // nested structures; deeper means a cycle in broken code

uint64_t round_up(uint64_t value, uint64_t alignment) {
  return (value + alignment - 1) / alignment * alignment;
}

std::optional<TypeLayout> layout(const ProjectModel& model, const Type* type, int depth);

// Members one after another, each at its alignment; the whole padded to the largest one. A
// UNION is as large as its largest member.
std::optional<TypeLayout> aggregate_layout(const ProjectModel& model, const Type* type, int depth) {
  const Symbol* declaration = type->declaration;
  if (!declaration) return std::nullopt;
  TypeLayout total;
  for (const Symbol* member : declaration->ordered) {
    if (member->kind != SymbolKind::Variable) continue;
    std::optional<TypeLayout> part = layout(model, model.type_of(member), depth + 1);
    if (!part) return std::nullopt;
    total.alignment = std::max(total.alignment, part->alignment);
    if (type->kind == TypeKind::Union) {
      total.size = std::max(total.size, part->size);
    } else {
      total.size = round_up(total.size, part->alignment) + part->size;
    }
  }
  total.size = round_up(total.size, total.alignment);
  return total;
}

std::optional<TypeLayout> layout(const ProjectModel& model, const Type* type, int depth) {
  if (!type || depth > kMaxDepth) return std::nullopt;
  switch (type->kind) {
    case TypeKind::Alias:
    case TypeKind::Subrange:
    case TypeKind::Enum: return layout(model, type->element, depth + 1);
    case TypeKind::String:
    case TypeKind::WString: {
      const uint64_t unit = type->kind == TypeKind::WString ? 2 : 1;
      return TypeLayout{(type->length + 1) * unit, unit};
    }
    case TypeKind::Pointer:
    case TypeKind::Reference: return TypeLayout{kPointerBytes, kPointerBytes};
    case TypeKind::Array: {
      if (type->dimensions.empty()) return std::nullopt;
      std::optional<TypeLayout> element = layout(model, type->element, depth + 1);
      if (!element) return std::nullopt;
      uint64_t count = 1;
      for (const ArrayDimension& dimension : type->dimensions) {
        if (dimension.open || !dimension.known || dimension.upper < dimension.lower) return std::nullopt;
        count *= static_cast<uint64_t>(dimension.upper - dimension.lower + 1);
      }
      return TypeLayout{count * element->size, element->alignment};
    }
    case TypeKind::Struct:
    case TypeKind::Union: return aggregate_layout(model, type, depth);
    default: {
      // Elementary values; FB instances, generics and unknown types have no size rung knows.
      if (!is_elementary(type) || type->bits == 0) return std::nullopt;
      const uint64_t bytes = std::max<uint64_t>(1, type->bits / 8);  // a BOOL takes a byte
      return TypeLayout{bytes, std::min(bytes, kMaxAlignment)};
    }
  }
}

}  // namespace

std::optional<TypeLayout> type_layout(const ProjectModel& model, const Type* type) {
  return layout(model, type, 0);
}

const Type* sizeof_result_type(TypeArena& types, uint64_t bytes) {
  if (bytes < (uint64_t{1} << 8)) return types.elementary("USINT");
  if (bytes < (uint64_t{1} << 16)) return types.elementary("UINT");
  if (bytes < (uint64_t{1} << 32)) return types.elementary("UDINT");
  return types.elementary("ULINT");
}

}  // namespace rung::check
