#include "checker/types/conversions.hpp"

#include <fmt/format.h>

#include "checker/symbols/names.hpp"
#include "checker/symbols/symbol.hpp"

namespace rung::check {
namespace {

// The name conversion functions use for a type: STRING for STRING(43), the elementary type behind
// an alias, subrange or enum; empty for other types.
std::string_view conversion_name(const Type* type) {
  const Type* base = arithmetic_type(type);
  if (!base || !is_elementary(base)) return {};
  if (base->kind == TypeKind::String) return "STRING";
  if (base->kind == TypeKind::WString) return "WSTRING";
  return base->name;
}

bool fits_range(const Type* from, const Type* to) {
  auto a = integer_range(from);
  auto b = integer_range(to);
  return a && b && a->lower >= b->lower && a->upper <= b->upper;
}

bool same_declaration(const Type* a, const Type* b) { return a == b || (a->declaration && a->declaration == b->declaration); }

Convertibility numeric(const Type* from, const Type* to, const Profile& profile) {
  const bool from_real = from->kind == TypeKind::Real, to_real = to->kind == TypeKind::Real;
  if (from_real && to_real) return from->bits <= to->bits ? Convertibility::Implicit : Convertibility::Narrowing;
  if (to_real) return Convertibility::Implicit;  // integers to REAL/LREAL
  if (from_real) return Convertibility::Narrowing;
  const bool bit_mix = (from->kind == TypeKind::Bit) != (to->kind == TypeKind::Bit);
  if (bit_mix && !profile.bits_and_integers_mix) return Convertibility::Never;
  return fits_range(from, to) ? Convertibility::Implicit : Convertibility::Narrowing;
}

}  // namespace

std::string conversion_function(const Type* from, const Type* to) {
  // No conversion function makes an enum value.
  const std::string_view target = to && underlying(to)->kind != TypeKind::Enum ? conversion_name(to) : "";
  if (target.empty() || !from) return {};
  // An enumeration converts with the overloaded TO_<type>.
  if (underlying(from)->kind == TypeKind::Enum) return fmt::format("TO_{}", target);
  const std::string_view source = conversion_name(from);
  if (source.empty() || names_equal(source, target)) return {};
  return fmt::format("{}_TO_{}", source, target);
}

bool derives_from(const Type* type, const Type* base) {
  if (!type || !base || !type->declaration || !base->declaration) return false;
  // Breadth-first over EXTENDS and IMPLEMENTS; bounded against cycles.
  std::vector<const Symbol*> pending{type->declaration};
  for (size_t i = 0; i < pending.size() && i < 256; ++i) {
    const Symbol* symbol = pending[i];
    if (symbol == base->declaration) return true;
    for (const Symbol* parent : symbol->bases) pending.push_back(parent);
    for (const Symbol* parent : symbol->interfaces) pending.push_back(parent);
  }
  return false;
}

Convertibility convertibility(const Type* from, const Type* to, const Profile& profile) {
  if (!from || !to) return Convertibility::Same;
  from = underlying(from);
  to = underlying(to);
  if (from == to || from->is_unknown() || to->is_unknown() || from->kind == TypeKind::Void) return Convertibility::Same;
  // Reading a reference reads what it refers to; writing one writes there.
  if (from->kind == TypeKind::Reference && from->element) return convertibility(from->element, to, profile);
  if (to->kind == TypeKind::Reference && to->element) return convertibility(from, to->element, profile);
  if (to->kind == TypeKind::Generic) {
    if (generic_accepts(to->generic, from)) return Convertibility::Same;
    // CODESYS and TwinCAT accept integers where IEC asks for bit strings (SHL, ROL, AND ...) and
    // bit strings where it asks for numbers; integers widen to REAL everywhere.
    if (to->generic == GenericKind::AnyBit && profile.bits_and_integers_mix && is_integer(from)) return Convertibility::Same;
    if ((to->generic == GenericKind::AnyInt || to->generic == GenericKind::AnyNum ||
         to->generic == GenericKind::AnyMagnitude || to->generic == GenericKind::AnyUnsigned ||
         to->generic == GenericKind::AnySigned) &&
        profile.bits_and_integers_mix && is_bit_string(from)) {
      return Convertibility::Same;
    }
    if (to->generic == GenericKind::AnyReal && is_integer(from) && profile.generic_arguments_widen) {
      return Convertibility::Implicit;
    }
    return Convertibility::Never;
  }
  if (from->kind == TypeKind::Generic) return Convertibility::Same;
  if (to->kind == TypeKind::Subrange) return convertibility(from, to->element, profile);
  if (from->kind == TypeKind::Subrange) return convertibility(from->element, to, profile);

  if (from->kind == TypeKind::Enum || to->kind == TypeKind::Enum) {
    if (same_declaration(from, to)) return Convertibility::Same;
    const bool strict = (to->declaration && to->declaration->has(kStrict)) || (from->declaration && from->declaration->has(kStrict));
    if (from->kind == TypeKind::Enum && to->kind == TypeKind::Enum) return Convertibility::Narrowing;
    if (!profile.enums_are_integers || strict) return Convertibility::Never;
    const Type* other = from->kind == TypeKind::Enum ? to : from;
    if (!is_any_int_or_bit(other)) return Convertibility::Never;
    return convertibility(arithmetic_type(from), arithmetic_type(to), profile);
  }

  switch (to->kind) {
    case TypeKind::Bool:
      return from->kind == TypeKind::Bool ? Convertibility::Same : Convertibility::Never;
    case TypeKind::Bit:
    case TypeKind::SignedInt:
    case TypeKind::UnsignedInt:
    case TypeKind::Real:
      if (is_numeric(from) || from->kind == TypeKind::Bit) return numeric(from, to, profile);
      if (from->kind == TypeKind::Bool) return profile.bits_and_integers_mix && to->kind == TypeKind::Bit ? Convertibility::Implicit : Convertibility::Never;
      if ((from->kind == TypeKind::Char || from->kind == TypeKind::WChar) && to->kind != TypeKind::Real) {
        return profile.bits_and_integers_mix ? Convertibility::Implicit : Convertibility::Never;
      }
      if ((from->kind == TypeKind::Duration || from->kind == TypeKind::Date || from->kind == TypeKind::TimeOfDay ||
           from->kind == TypeKind::DateTime) && to->kind != TypeKind::Real) {
        return profile.time_and_integers_mix ? (to->bits >= from->bits ? Convertibility::Implicit : Convertibility::Narrowing)
                                             : Convertibility::Never;
      }
      if ((from->kind == TypeKind::Pointer || from->kind == TypeKind::Null) && to->kind != TypeKind::Real) {
        return profile.bits_and_integers_mix ? Convertibility::Implicit : Convertibility::Never;
      }
      return Convertibility::Never;
    case TypeKind::Duration:
    case TypeKind::Date:
    case TypeKind::TimeOfDay:
    case TypeKind::DateTime:
      if (from->kind == to->kind) return from->bits <= to->bits ? Convertibility::Implicit : Convertibility::Narrowing;
      if (is_any_int_or_bit(from)) return profile.time_and_integers_mix ? Convertibility::Implicit : Convertibility::Never;
      return Convertibility::Never;
    case TypeKind::String:
    case TypeKind::WString:
      if (from->kind == to->kind) return Convertibility::Same;  // longer strings are cut at run time
      if (from->kind == TypeKind::String || from->kind == TypeKind::WString) return Convertibility::Narrowing;
      return Convertibility::Never;
    case TypeKind::Char:
    case TypeKind::WChar:
      if (from->kind == to->kind) return Convertibility::Same;
      if (from->kind == TypeKind::Char || from->kind == TypeKind::WChar || is_any_int_or_bit(from)) {
        return profile.bits_and_integers_mix ? Convertibility::Narrowing : Convertibility::Never;
      }
      return Convertibility::Never;
    case TypeKind::Pointer:
      if (from->kind == TypeKind::Pointer || from->kind == TypeKind::Null) return Convertibility::Implicit;
      if (is_any_int_or_bit(from)) return profile.bits_and_integers_mix ? Convertibility::Implicit : Convertibility::Never;
      return Convertibility::Never;
    case TypeKind::Array: {
      if (from->kind != TypeKind::Array) return Convertibility::Never;
      if (from->dimensions.size() != to->dimensions.size()) return Convertibility::Never;
      for (size_t i = 0; i < to->dimensions.size(); ++i) {
        const auto& a = from->dimensions[i];
        const auto& b = to->dimensions[i];
        if (a.open || b.open || !a.known || !b.known) continue;
        if (a.upper - a.lower != b.upper - b.lower) return Convertibility::Never;
      }
      const Convertibility element = convertibility(from->element, to->element, profile);
      return element == Convertibility::Never || element == Convertibility::Narrowing ? Convertibility::Never
                                                                                        : Convertibility::Same;
    }
    case TypeKind::Struct:
    case TypeKind::Union:
    case TypeKind::Pou:
      if (same_declaration(from, to) || derives_from(from, to)) return Convertibility::Same;
      if (from->kind == TypeKind::Null || (from->kind == TypeKind::Pou && !from->declaration)) return Convertibility::Same;
      // Interfaces are references: 0 / NULL and integers of pointer size are accepted by CODESYS.
      if (to->declaration && to->declaration->kind == SymbolKind::Interface && from->kind == TypeKind::Pou &&
          from->declaration && from->declaration->kind == SymbolKind::Interface) {
        return Convertibility::Never;
      }
      return Convertibility::Never;
    default:
      return Convertibility::Same;
  }
}

const Type* common_numeric_type(const Type* a, const Type* b, const TypeArena& types) {
  a = arithmetic_type(a);
  b = arithmetic_type(b);
  if (!a || !b) return nullptr;
  if (a->kind == TypeKind::Real || b->kind == TypeKind::Real) {
    const uint32_t bits = std::max(a->kind == TypeKind::Real ? a->bits : 0u, b->kind == TypeKind::Real ? b->bits : 0u);
    return types.elementary(bits > 32 ? "LREAL" : "REAL");
  }
  if (a == b) return a;
  // Mixed signedness: the signed type wide enough for both, as CODESYS computes.
  const Type* wider = a->bits >= b->bits ? a : b;
  if (a->kind == b->kind) return wider;
  if (a->kind == TypeKind::Bit && b->kind == TypeKind::Bit) return wider;
  const Type* signed_one = a->kind == TypeKind::SignedInt ? a : (b->kind == TypeKind::SignedInt ? b : nullptr);
  if (!signed_one) return wider;
  const Type* other = signed_one == a ? b : a;
  if (signed_one->bits > other->bits) return signed_one;
  switch (std::max(a->bits, b->bits)) {
    case 8:
      return types.elementary("INT");
    case 16:
      return types.elementary("DINT");
    default:
      return types.elementary("LINT");
  }
}

}  // namespace rung::check
