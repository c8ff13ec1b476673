#include "runner/compile/layout.hpp"

#include <algorithm>

#include "checker/symbols/names.hpp"
#include "runner/vm/program.hpp"

namespace rung::run {
namespace {

using check::Symbol;
using check::SymbolKind;
using check::Type;
using check::TypeKind;

constexpr uint64_t kMaxAlignment = 8;
constexpr int kMaxDepth = 64;

uint64_t round_up(uint64_t value, uint64_t alignment) { return (value + alignment - 1) / alignment * alignment; }

bool is_frame_pou(const Symbol* pou) {
  return pou->kind == SymbolKind::Function || pou->kind == SymbolKind::Method;
}

// The steps of an SFC network and what their action associations name (see SfcLayout).
SfcLayout sfc_layout(SyntaxNode network) {
  SfcLayout sfc;
  for (uint32_t i = 0; i < network.named_child_count(); ++i) {
    SyntaxNode step = network.named_child(i);
    SyntaxNode name = step.child_by_field("name");
    if (step.kind() != "sfc_step" || !name || sfc.step_index(name.text()) >= 0) continue;
    sfc.steps.push_back(check::upper_name(name.text()));
    sfc.initial.push_back(step.child(0).kind() == "INITIAL_STEP");
    for (uint32_t j = 0; j < step.named_child_count(); ++j) {
      SyntaxNode association = step.named_child(j);
      SyntaxNode action = association.child_by_field("name");
      if (association.kind() != "sfc_action" || !action || sfc.action_index(action.text()) >= 0) continue;
      sfc.actions.push_back(check::upper_name(action.text()));
    }
  }
  return sfc;
}

}  // namespace

int SfcLayout::step_index(std::string_view name) const {
  for (size_t i = 0; i < steps.size(); ++i) {
    if (check::names_equal(steps[i], name)) return static_cast<int>(i);
  }
  return -1;
}

int SfcLayout::action_index(std::string_view name) const {
  for (size_t i = 0; i < actions.size(); ++i) {
    if (check::names_equal(actions[i], name)) return static_cast<int>(i);
  }
  return -1;
}

const Type* Layouts::storage_type(const Type* type) {
  for (int depth = 0; type && depth < kMaxDepth; ++depth) {
    switch (type->kind) {
      case TypeKind::Alias:
      case TypeKind::Subrange:
        type = type->element;
        continue;
      default: return type;
    }
  }
  return type;
}

Scalar Layouts::scalar_of(const Type* type) {
  type = storage_type(type);
  if (!type) return Scalar::None;
  switch (type->kind) {
    case TypeKind::Bool: return Scalar::U8;
    case TypeKind::Enum: return type->element ? scalar_of(type->element) : Scalar::S16;
    case TypeKind::Pointer:
    case TypeKind::Null: return Scalar::U64;
    case TypeKind::Real: return type->bits == 32 ? Scalar::F32 : Scalar::F64;
    case TypeKind::SignedInt:
      switch (type->bits) {
        case 8: return Scalar::S8;
        case 16: return Scalar::S16;
        case 32: return Scalar::S32;
        default: return Scalar::I64;
      }
    case TypeKind::Bit:
    case TypeKind::UnsignedInt:
    case TypeKind::Duration:
    case TypeKind::Date:
    case TypeKind::TimeOfDay:
    case TypeKind::DateTime:
    case TypeKind::Char:
    case TypeKind::WChar:
      switch (type->bits) {
        case 1:
        case 8: return Scalar::U8;
        case 16: return Scalar::U16;
        case 32: return Scalar::U32;
        default: return Scalar::U64;
      }
    case TypeKind::Pou:
      // An interface value is the address of the object that implements it.
      return type->declaration && type->declaration->kind == SymbolKind::Interface ? Scalar::U64 : Scalar::None;
    default: return Scalar::None;
  }
}

bool Layouts::held_by_reference(const Symbol* variable) {
  if (variable->section == ast::VarSection::InOut) return true;
  const Type* type = variable->type;
  return type && type->kind == TypeKind::Reference;
}

size_t Layouts::open_dimensions(const Symbol* variable) {
  if (!held_by_reference(variable)) return 0;
  const Type* type = storage_type(variable->type);
  if (!type || type->kind != TypeKind::Array) return 0;
  size_t open = 0;
  for (const check::ArrayDimension& dimension : type->dimensions) open += dimension.open ? 1 : 0;
  return open == 0 ? 0 : type->dimensions.size();
}

uint64_t Layouts::granularity(const Type* type, int depth) {
  type = storage_type(type);
  if (!type || depth > 32) return 1;
  switch (type->kind) {
    case TypeKind::Array: return granularity(type->element, depth + 1);
    case TypeKind::String: return 1;
    case TypeKind::WString: return 2;
    case TypeKind::Struct:
    case TypeKind::Union:
    case TypeKind::Pou: {
      uint64_t largest = 1;
      if (!type->declaration) return of(type).alignment;
      for (const Symbol* member : type->declaration->ordered) {
        if (member->kind == SymbolKind::Variable && member->type) {
          largest = std::max(largest, held_by_reference(member) ? 8 : granularity(member->type, depth + 1));
        }
      }
      return largest;
    }
    default: return std::max<uint64_t>(1, of(type).size);
  }
}

bool Layouts::in_instance(const Symbol* variable) {
  switch (variable->section) {
    case ast::VarSection::Var:
    case ast::VarSection::Input:
    case ast::VarSection::Output:
    case ast::VarSection::InOut:
    case ast::VarSection::Inst: return true;
    default: return false;
  }
}

bool Layouts::has_instance_header(const Symbol* pou) {
  return pou->kind == SymbolKind::FunctionBlock || pou->kind == SymbolKind::Class;
}

TypeLayout Layouts::of(const Type* type) {
  if (!type) return TypeLayout{};
  if (auto found = types_.find(type); found != types_.end()) return found->second;
  TypeLayout layout = compute(type, 0);
  types_.emplace(type, layout);
  return layout;
}

TypeLayout Layouts::variable_layout(const Symbol* variable, int depth) {
  if (held_by_reference(variable)) return TypeLayout{kOpenBoundsOffset + 16 * open_dimensions(variable), 8};
  return compute(variable->type, depth + 1);
}

TypeLayout Layouts::struct_layout(const Symbol* declaration, bool is_union, int depth) {
  TypeLayout total;
  uint64_t offset = 0;
  // STRUCT ... EXTENDS: the base's fields come first.
  if (declaration->base && declaration->base->type) {
    const TypeLayout base = compute(declaration->base->type, depth + 1);
    offset = base.size;
    total.alignment = base.alignment;
  }
  for (const Symbol* member : declaration->ordered) {
    if (member->kind != SymbolKind::Variable) continue;
    const TypeLayout part = variable_layout(member, depth);
    total.alignment = std::max(total.alignment, part.alignment);
    if (is_union) {
      offsets_[member] = 0;
      offset = std::max(offset, part.size);
    } else {
      offset = round_up(offset, part.alignment);
      offsets_[member] = offset;
      offset += part.size;
    }
  }
  total.size = round_up(std::max<uint64_t>(offset, 1), total.alignment);
  return total;
}

TypeLayout Layouts::compute(const Type* type, int depth) {
  if (!type || depth > kMaxDepth) return TypeLayout{};
  switch (type->kind) {
    case TypeKind::Alias:
    case TypeKind::Subrange: return compute(type->element, depth + 1);
    case TypeKind::Enum: return type->element ? compute(type->element, depth + 1) : TypeLayout{2, 2};
    case TypeKind::String:
    case TypeKind::WString: {
      const uint64_t unit = type->kind == TypeKind::WString ? 2 : 1;
      return TypeLayout{(uint64_t{type->length} + 1) * unit, unit};
    }
    case TypeKind::Pointer:
    case TypeKind::Reference:
    case TypeKind::Null: return TypeLayout{8, 8};
    case TypeKind::Array: {
      const TypeLayout element = compute(type->element, depth + 1);
      uint64_t count = 1;
      for (const check::ArrayDimension& dimension : type->dimensions) {
        if (dimension.open || dimension.upper < dimension.lower) return TypeLayout{8, 8};
        count *= static_cast<uint64_t>(dimension.upper - dimension.lower + 1);
      }
      return TypeLayout{count * element.size, element.alignment};
    }
    case TypeKind::Struct:
    case TypeKind::Union:
      if (!type->declaration) return TypeLayout{};
      if (auto found = types_.find(type); found != types_.end()) return found->second;
      return types_[type] = struct_layout(type->declaration, type->kind == TypeKind::Union, depth);
    case TypeKind::Pou: {
      const Symbol* declaration = type->declaration;
      if (!declaration) return TypeLayout{};
      if (declaration->kind == SymbolKind::Interface) return TypeLayout{8, 8};
      const PouLayout& layout = pou(declaration);
      return TypeLayout{layout.instance_size, layout.instance_alignment};
    }
    default: {
      if (type->bits == 0) return TypeLayout{};
      const uint64_t bytes = std::max<uint64_t>(1, type->bits / 8);
      return TypeLayout{bytes, std::min(bytes, kMaxAlignment)};
    }
  }
}

const PouLayout& Layouts::pou(const Symbol* symbol) {
  if (auto found = pous_.find(symbol); found != pous_.end()) return found->second;
  PouLayout layout;
  // The instance: header, the base's variables, then the POU's own.
  if (!is_frame_pou(symbol) && symbol->kind != SymbolKind::Action && symbol->kind != SymbolKind::Transition) {
    uint64_t offset = has_instance_header(symbol) ? kInstanceHeaderBytes : 0;
    uint64_t alignment = 8;
    if (symbol->base && symbol->base != symbol && check::is_pou_kind(symbol->base->kind)) {
      const PouLayout& base = pou(symbol->base);
      layout.instance_variables = base.instance_variables;
      offset = std::max(offset, base.instance_size);
    }
    for (const Symbol* member : symbol->ordered) {
      if (member->kind != SymbolKind::Variable || !in_instance(member)) continue;
      const TypeLayout part = variable_layout(member, 0);
      offset = round_up(offset, part.alignment);
      offsets_[member] = offset;
      offset += part.size;
      alignment = std::max(alignment, part.alignment);
      layout.instance_variables.push_back(member);
    }
    // An SFC body keeps its steps' and actions' state after the variables (see SfcLayout).
    if (SyntaxNode body = symbol->node ? symbol->node.child_by_field("body") : SyntaxNode();
        body && body.kind() == "sfc_network") {
      SfcLayout sfc = sfc_layout(body);
      offset = round_up(offset, 8);
      sfc.offset = offset;
      offset += sfc.size();
      layout.sfc = std::move(sfc);
    }
    layout.instance_size = round_up(offset, alignment);
    layout.instance_alignment = alignment;
  }
  // The frame: a function's or method's result and every variable; a body's VAR_TEMP. The result
  // and the parameters come first, so a method and its overrides agree on where arguments go.
  uint64_t frame = 0;
  auto place_in_frame = [&](const Symbol* member) {
    const TypeLayout part = variable_layout(member, 0);
    frame = round_up(frame, part.alignment);
    offsets_[member] = frame;
    frame += part.size;
    layout.frame_variables.push_back(member);
  };
  if (const Type* result = result_type(symbol)) {
    layout.result_offset = 0;
    frame = compute(result, 0).size;
  }
  auto is_frame_variable = [&](const Symbol* member) {
    if (member->kind != SymbolKind::Variable) return false;
    if (is_frame_pou(symbol) || symbol->kind == SymbolKind::Action) {
      return member->section != ast::VarSection::Stat && member->section != ast::VarSection::External &&
             member->section != ast::VarSection::Global;
    }
    return member->section == ast::VarSection::Temp;
  };
  auto is_parameter = [](const Symbol* member) {
    return member->section == ast::VarSection::Input || member->section == ast::VarSection::InOut ||
           member->section == ast::VarSection::Output;
  };
  for (const Symbol* member : symbol->ordered) {
    if (is_frame_variable(member) && is_parameter(member)) place_in_frame(member);
  }
  layout.param_bytes = frame;
  for (const Symbol* member : symbol->ordered) {
    if (is_frame_variable(member) && !is_parameter(member)) place_in_frame(member);
  }
  layout.frame_size = round_up(frame, 8);
  return pous_[symbol] = std::move(layout);
}

const Type* Layouts::result_type(const Symbol* pou) {
  auto usable = [](const Type* type) { return type && type->kind != TypeKind::Void && !type->is_unknown(); };
  // A property's GET and SET carry the property's type: the value they return or receive.
  if (pou->owner && pou->owner->kind == SymbolKind::Property && !usable(pou->result_type)) {
    return usable(pou->owner->result_type) ? pou->owner->result_type : nullptr;
  }
  return usable(pou->result_type) ? pou->result_type : nullptr;
}

uint64_t Layouts::offset(const Symbol* variable) const {
  auto found = offsets_.find(variable);
  return found == offsets_.end() ? 0 : found->second;
}

}  // namespace rung::run
