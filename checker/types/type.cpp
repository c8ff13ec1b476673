#include "checker/types/type.hpp"

#include <fmt/format.h>

#include <array>

#include "checker/symbols/names.hpp"

namespace rung::check {
namespace {

struct ElementarySpec {
  std::string_view name;
  TypeKind kind;
  uint32_t bits;
  bool long_variant = false;
};

// Sizes from IEC 61131-3 table 10; CODESYS and TwinCAT agree on all of them.
constexpr std::array kElementary = {
    ElementarySpec{"BOOL", TypeKind::Bool, 1},
    ElementarySpec{"BYTE", TypeKind::Bit, 8},
    ElementarySpec{"WORD", TypeKind::Bit, 16},
    ElementarySpec{"DWORD", TypeKind::Bit, 32},
    ElementarySpec{"LWORD", TypeKind::Bit, 64},
    ElementarySpec{"SINT", TypeKind::SignedInt, 8},
    ElementarySpec{"INT", TypeKind::SignedInt, 16},
    ElementarySpec{"DINT", TypeKind::SignedInt, 32},
    ElementarySpec{"LINT", TypeKind::SignedInt, 64},
    ElementarySpec{"USINT", TypeKind::UnsignedInt, 8},
    ElementarySpec{"UINT", TypeKind::UnsignedInt, 16},
    ElementarySpec{"UDINT", TypeKind::UnsignedInt, 32},
    ElementarySpec{"ULINT", TypeKind::UnsignedInt, 64},
    ElementarySpec{"REAL", TypeKind::Real, 32},
    ElementarySpec{"LREAL", TypeKind::Real, 64},
    ElementarySpec{"TIME", TypeKind::Duration, 32},
    ElementarySpec{"LTIME", TypeKind::Duration, 64, true},
    ElementarySpec{"DATE", TypeKind::Date, 32},
    ElementarySpec{"LDATE", TypeKind::Date, 64, true},
    ElementarySpec{"TIME_OF_DAY", TypeKind::TimeOfDay, 32},
    ElementarySpec{"LTIME_OF_DAY", TypeKind::TimeOfDay, 64, true},
    ElementarySpec{"DATE_AND_TIME", TypeKind::DateTime, 32},
    ElementarySpec{"LDATE_AND_TIME", TypeKind::DateTime, 64, true},
    ElementarySpec{"CHAR", TypeKind::Char, 8},
    ElementarySpec{"WCHAR", TypeKind::WChar, 16},
    // CODESYS pointer-sized integers (64-bit targets: 64 bits; rung assumes 64).
    ElementarySpec{"__XWORD", TypeKind::Bit, 64},
    ElementarySpec{"__UXINT", TypeKind::UnsignedInt, 64},
    ElementarySpec{"__XINT", TypeKind::SignedInt, 64},
};

// Short spellings that name the same type.
constexpr std::array<std::pair<std::string_view, std::string_view>, 4> kSynonyms = {{
    {"TOD", "TIME_OF_DAY"},
    {"LTOD", "LTIME_OF_DAY"},
    {"DT", "DATE_AND_TIME"},
    {"LDT", "LDATE_AND_TIME"},
}};

// TwinCAT / CODESYS built-in names outside IEC; a user type of the same name wins over them.
constexpr std::array<std::pair<std::string_view, std::string_view>, 4> kVendorSynonyms = {{
    {"XWORD", "__XWORD"},
    {"UXINT", "__UXINT"},
    {"XINT", "__XINT"},
    {"PVOID", "__XWORD"},
}};

struct GenericSpec {
  std::string_view name;
  GenericKind kind;
};

constexpr std::array kGenerics = {
    GenericSpec{"ANY", GenericKind::Any},
    GenericSpec{"ANY_DERIVED", GenericKind::AnyDerived},
    GenericSpec{"ANY_ELEMENTARY", GenericKind::AnyElementary},
    GenericSpec{"ANY_MAGNITUDE", GenericKind::AnyMagnitude},
    GenericSpec{"ANY_NUM", GenericKind::AnyNum},
    GenericSpec{"ANY_REAL", GenericKind::AnyReal},
    GenericSpec{"ANY_INT", GenericKind::AnyInt},
    GenericSpec{"ANY_SIGNED", GenericKind::AnySigned},
    GenericSpec{"ANY_UNSIGNED", GenericKind::AnyUnsigned},
    GenericSpec{"ANY_BIT", GenericKind::AnyBit},
    GenericSpec{"ANY_STRING", GenericKind::AnyString},
    GenericSpec{"ANY_CHARS", GenericKind::AnyChars},
    GenericSpec{"ANY_CHAR", GenericKind::AnyChar},
    GenericSpec{"ANY_DATE", GenericKind::AnyDate},
    GenericSpec{"ANY_DURATION", GenericKind::AnyDuration},
    GenericSpec{"ANY_POINTER", GenericKind::AnyPointer},
};

std::string dimension_text(const std::vector<ArrayDimension>& dimensions) {
  std::string text;
  for (const auto& dimension : dimensions) {
    if (!text.empty()) text += ", ";
    if (dimension.open) {
      text += "*";
    } else if (!dimension.known) {
      text += "?..?";
    } else {
      text += fmt::format("{}..{}", dimension.lower, dimension.upper);
    }
  }
  return text;
}

}  // namespace

const Type* underlying(const Type* type) {
  // Bounded: alias chains are built from declarations; a cycle is cut by the resolver.
  for (int depth = 0; type && type->kind == TypeKind::Alias && type->element && depth < 64; ++depth) {
    type = type->element;
  }
  return type;
}

const Type* arithmetic_type(const Type* type) {
  for (int depth = 0; type && depth < 64; ++depth) {
    if ((type->kind == TypeKind::Alias || type->kind == TypeKind::Subrange || type->kind == TypeKind::Enum ||
         type->kind == TypeKind::Reference) &&
        type->element) {
      type = type->element;
    } else {
      break;
    }
  }
  return type;
}

bool is_integer(const Type* type) {
  type = arithmetic_type(type);
  return type && (type->kind == TypeKind::SignedInt || type->kind == TypeKind::UnsignedInt);
}

bool is_bit_string(const Type* type) {
  type = arithmetic_type(type);
  return type && type->kind == TypeKind::Bit;
}

bool is_numeric(const Type* type) {
  type = arithmetic_type(type);
  return type && (is_integer(type) || type->kind == TypeKind::Real);
}

bool is_any_int_or_bit(const Type* type) { return is_integer(type) || is_bit_string(type); }

bool is_string_like(const Type* type) {
  type = underlying(type);
  return type && (type->kind == TypeKind::String || type->kind == TypeKind::WString);
}

bool is_elementary(const Type* type) {
  type = arithmetic_type(type);
  if (!type) return false;
  switch (type->kind) {
    case TypeKind::Bool:
    case TypeKind::Bit:
    case TypeKind::SignedInt:
    case TypeKind::UnsignedInt:
    case TypeKind::Real:
    case TypeKind::Duration:
    case TypeKind::Date:
    case TypeKind::TimeOfDay:
    case TypeKind::DateTime:
    case TypeKind::String:
    case TypeKind::WString:
    case TypeKind::Char:
    case TypeKind::WChar:
      return true;
    default:
      return false;
  }
}

bool is_signed(const Type* type) {
  type = arithmetic_type(type);
  return type && (type->kind == TypeKind::SignedInt || type->kind == TypeKind::Real);
}

std::optional<IntegerRange> integer_range(const Type* type) {
  type = underlying(type);
  if (!type) return std::nullopt;
  if (type->kind == TypeKind::Subrange) return IntegerRange{type->range_lower, type->range_upper};
  type = arithmetic_type(type);
  if (!type || type->bits == 0 || type->bits > 64) return std::nullopt;
  const __int128 one = 1;
  switch (type->kind) {
    case TypeKind::SignedInt:
      return IntegerRange{-(one << (type->bits - 1)), (one << (type->bits - 1)) - 1};
    case TypeKind::UnsignedInt:
    case TypeKind::Bit:
      return IntegerRange{0, (one << type->bits) - 1};
    case TypeKind::Bool:
      return IntegerRange{0, 1};
    default:
      return std::nullopt;
  }
}

bool generic_accepts(GenericKind category, const Type* type) {
  type = underlying(type);
  if (!type || type->is_unknown()) return true;
  if (type->kind == TypeKind::Generic) return true;  // checked where it is bound
  const Type* base = arithmetic_type(type);
  const TypeKind kind = base ? base->kind : type->kind;
  switch (category) {
    case GenericKind::Any:
      return true;
    case GenericKind::AnyDerived:
      return !is_elementary(type);
    case GenericKind::AnyElementary:
      return is_elementary(type);
    case GenericKind::AnyMagnitude:
      return is_numeric(type) || kind == TypeKind::Duration;
    case GenericKind::AnyNum:
      return is_numeric(type);
    case GenericKind::AnyReal:
      return kind == TypeKind::Real;
    case GenericKind::AnyInt:
      return is_integer(type);
    case GenericKind::AnySigned:
      return kind == TypeKind::SignedInt;
    case GenericKind::AnyUnsigned:
      return kind == TypeKind::UnsignedInt;
    case GenericKind::AnyBit:
      return kind == TypeKind::Bit || kind == TypeKind::Bool;
    case GenericKind::AnyString:
      return kind == TypeKind::String || kind == TypeKind::WString;
    case GenericKind::AnyChars:
      return kind == TypeKind::String || kind == TypeKind::WString || kind == TypeKind::Char ||
             kind == TypeKind::WChar;
    case GenericKind::AnyChar:
      return kind == TypeKind::Char || kind == TypeKind::WChar;
    case GenericKind::AnyDate:
      return kind == TypeKind::Date || kind == TypeKind::TimeOfDay || kind == TypeKind::DateTime;
    case GenericKind::AnyDuration:
      return kind == TypeKind::Duration;
    case GenericKind::AnyPointer:
      return kind == TypeKind::Pointer || kind == TypeKind::Null || is_any_int_or_bit(type);
  }
  return true;
}

std::string_view generic_name(GenericKind category) {
  for (const auto& spec : kGenerics) {
    if (spec.kind == category) return spec.name;
  }
  return "ANY";
}

TypeArena::TypeArena() {
  unknown_ = add(Type{.kind = TypeKind::Unknown, .name = "?"});
  void_ = add(Type{.kind = TypeKind::Void, .name = "VOID"});
  null_ = add(Type{.kind = TypeKind::Null, .name = "NULL"});
  for (const auto& spec : kElementary) {
    elementary_[std::string(spec.name)] =
        add(Type{.kind = spec.kind, .name = std::string(spec.name), .bits = spec.bits, .long_variant = spec.long_variant});
  }
  // STRING and WSTRING without a length.
  elementary_["STRING"] = string_type(false, kDefaultStringLength);
  elementary_["WSTRING"] = string_type(true, kDefaultStringLength);
  for (const auto& [alias, target] : kSynonyms) elementary_[std::string(alias)] = elementary_.at(std::string(target));
  for (const auto& [alias, target] : kVendorSynonyms) {
    vendor_elementary_[std::string(alias)] = elementary_.at(std::string(target));
  }
  // CODESYS BIT: a BOOL packed into a bit of a structure.
  vendor_elementary_["BIT"] = add(Type{.kind = TypeKind::Bool, .name = "BIT", .bits = 1});
  for (const auto& spec : kGenerics) {
    generics_[std::string(spec.name)] = add(Type{.kind = TypeKind::Generic, .name = std::string(spec.name), .generic = spec.kind});
  }
}

const Type* TypeArena::add(Type type) {
  storage_.push_back(std::move(type));
  return &storage_.back();
}

const Type* TypeArena::elementary(std::string_view name, bool vendor_names) const {
  const std::string key = upper_name(name);
  if (auto found = elementary_.find(key); found != elementary_.end()) return found->second;
  if (vendor_names) {
    if (auto found = vendor_elementary_.find(key); found != vendor_elementary_.end()) return found->second;
  }
  return nullptr;
}

const Type* TypeArena::generic(std::string_view name) const {
  auto found = generics_.find(upper_name(name));
  return found == generics_.end() ? nullptr : found->second;
}

const Type* TypeArena::generic(GenericKind kind) const { return generic(generic_name(kind)); }

const Type* TypeArena::string_type(bool wide, uint32_t length) {
  std::lock_guard lock(mutex_);
  auto key = std::make_tuple(wide ? 1 : 0, nullptr, length);
  if (auto found = strings_pointers_.find(key); found != strings_pointers_.end()) return found->second;
  std::string name = wide ? "WSTRING" : "STRING";
  if (length != kDefaultStringLength) name += fmt::format("({})", length);
  const Type* type = add(Type{.kind = wide ? TypeKind::WString : TypeKind::String,
                              .name = std::move(name),
                              .bits = (length + 1) * (wide ? 16u : 8u),
                              .length = length});
  strings_pointers_.emplace(key, type);
  return type;
}

const Type* TypeArena::array_of(const Type* element, std::vector<ArrayDimension> dimensions) {
  std::lock_guard lock(mutex_);
  std::string name = fmt::format("ARRAY[{}] OF {}", dimension_text(dimensions), element->name);
  std::string key = fmt::format("{}|{}", static_cast<const void*>(element), name);
  if (auto found = arrays_subranges_.find(key); found != arrays_subranges_.end()) return found->second;
  uint64_t count = 1;
  bool sized = element->bits != 0;
  for (const auto& dimension : dimensions) {
    if (dimension.open || !dimension.known || dimension.upper < dimension.lower) {
      sized = false;
      break;
    }
    count *= static_cast<uint64_t>(dimension.upper - dimension.lower + 1);
  }
  const uint64_t element_bits = element->bits == 1 ? 8 : element->bits;  // BOOL array elements take a byte
  const uint64_t bits = sized ? count * element_bits : 0;
  const Type* type = add(Type{.kind = TypeKind::Array,
                              .name = std::move(name),
                              .bits = bits > UINT32_MAX ? 0 : static_cast<uint32_t>(bits),
                              .element = element,
                              .dimensions = std::move(dimensions)});
  arrays_subranges_.emplace(std::move(key), type);
  return type;
}

const Type* TypeArena::pointer_to(const Type* target) { return indirection(TypeKind::Pointer, target); }

const Type* TypeArena::reference_to(const Type* target) { return indirection(TypeKind::Reference, target); }

const Type* TypeArena::indirection(TypeKind kind, const Type* target) {
  std::lock_guard lock(mutex_);
  auto key = std::make_tuple(kind == TypeKind::Pointer ? 2 : 3, target, 0u);
  if (auto found = strings_pointers_.find(key); found != strings_pointers_.end()) return found->second;
  const std::string prefix = kind == TypeKind::Pointer ? "POINTER TO " : "REFERENCE TO ";
  const Type* type = add(Type{.kind = kind, .name = prefix + target->name, .bits = 64, .element = target});
  strings_pointers_.emplace(key, type);
  return type;
}

const Type* TypeArena::subrange(const Type* base, int64_t lower, int64_t upper) {
  std::lock_guard lock(mutex_);
  std::string name = fmt::format("{}({}..{})", base->name, lower, upper);
  std::string key = fmt::format("{}|{}", static_cast<const void*>(base), name);
  if (auto found = arrays_subranges_.find(key); found != arrays_subranges_.end()) return found->second;
  const Type* type = add(Type{.kind = TypeKind::Subrange,
                              .name = std::move(name),
                              .bits = base->bits,
                              .element = base,
                              .range_lower = lower,
                              .range_upper = upper});
  arrays_subranges_.emplace(std::move(key), type);
  return type;
}

Type* TypeArena::make_named(TypeKind kind, std::string name, const Symbol* declaration) {
  std::lock_guard lock(mutex_);
  storage_.push_back(Type{.kind = kind, .name = std::move(name), .declaration = declaration});
  return &storage_.back();
}

}  // namespace rung::check
