// The type model of the checker: elementary types with sizes and ranges, the ANY_* generic
// categories of the standard, and derived types (arrays, pointers, references, strings of a
// length, subranges, enums, structs, unions, aliases, function blocks and other POUs).
//
// Types are immutable and owned by a TypeArena; everything else holds `const Type*`. Structurally
// equal derived types (ARRAY[1..3] OF INT written twice) are interned to one object, so pointer
// equality is type identity for everything but named user types, which are nominal.
#pragma once

#include <cstdint>
#include <deque>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

namespace rung::check {

struct Symbol;

enum class TypeKind : uint8_t {
  Unknown,  // could not be determined (broken code, missing library): never reported as a mismatch
  Void,     // no value (a FUNCTION without result type, a program call)
  Bool,
  Bit,          // BYTE, WORD, DWORD, LWORD (bit strings), CODESYS BIT
  SignedInt,    // SINT, INT, DINT, LINT
  UnsignedInt,  // USINT, UINT, UDINT, ULINT
  Real,         // REAL, LREAL
  Duration,     // TIME, LTIME
  Date,         // DATE, LDATE
  TimeOfDay,    // TOD, LTOD
  DateTime,     // DT, LDT
  String,       // STRING(n)
  WString,      // WSTRING(n)
  Char,
  WChar,
  Enum,
  Struct,
  Union,
  Array,
  Pointer,
  Reference,
  Subrange,
  Alias,
  Pou,      // function block, program, class, interface, function: the type of an instance
  Generic,  // ANY_* in library signatures and generic parameters
  Null,     // the NULL / 0 pointer constant
};

// The generic categories of IEC 61131-3 (table 11 of the standard, with CODESYS additions).
enum class GenericKind : uint8_t {
  Any,
  AnyDerived,
  AnyElementary,
  AnyMagnitude,
  AnyNum,
  AnyReal,
  AnyInt,
  AnySigned,
  AnyUnsigned,
  AnyBit,
  AnyString,
  AnyChars,  // strings and characters
  AnyChar,
  AnyDate,
  AnyDuration,
  AnyPointer,  // __XWORD-sized addresses (ADR)
};

struct ArrayDimension {
  int64_t lower = 0;
  int64_t upper = -1;
  bool open = false;   // ARRAY[*] in a VAR_IN_OUT
  bool known = true;   // bounds were constant-evaluated
};

struct Type {
  TypeKind kind = TypeKind::Unknown;
  std::string name;       // as shown in messages: "INT", "ARRAY[1..3] OF INT", "FB_Motor"
  uint32_t bits = 0;      // storage size in bits; 0 if unknown or not fixed
  const Type* element = nullptr;  // array element, pointer/reference target, subrange/enum base, alias target
  std::vector<ArrayDimension> dimensions;  // arrays
  uint32_t length = 0;                     // STRING(n)/WSTRING(n) characters
  int64_t range_lower = 0;                 // subranges
  int64_t range_upper = 0;
  GenericKind generic = GenericKind::Any;  // Generic
  const Symbol* declaration = nullptr;     // named user types and POU types
  bool long_variant = false;               // LTIME, LDATE, LTOD, LDT

  bool is_unknown() const { return kind == TypeKind::Unknown; }
};

// Aliases stripped (an alias of an alias of INT is INT).
const Type* underlying(const Type* type);
// Subranges, aliases and references stripped, enums to their base type: the type arithmetic sees.
const Type* arithmetic_type(const Type* type);

bool is_integer(const Type* type);  // signed or unsigned integers (after aliases/subranges)
bool is_bit_string(const Type* type);
bool is_numeric(const Type* type);  // integers and reals
bool is_any_int_or_bit(const Type* type);
bool is_string_like(const Type* type);
bool is_elementary(const Type* type);
bool is_signed(const Type* type);
// Value range of an integer type (after aliases/subranges); bit strings count as unsigned.
struct IntegerRange {
  __int128 lower = 0;
  __int128 upper = 0;
};
std::optional<IntegerRange> integer_range(const Type* type);

// Whether `type` belongs to a generic category.
bool generic_accepts(GenericKind category, const Type* type);
std::string_view generic_name(GenericKind category);

// Owns every type. Elementary types exist from the start; derived types are interned.
class TypeArena {
 public:
  TypeArena();
  TypeArena(const TypeArena&) = delete;
  TypeArena& operator=(const TypeArena&) = delete;

  const Type* unknown() const { return unknown_; }
  const Type* void_type() const { return void_; }
  const Type* null_type() const { return null_; }
  // BOOL, INT, TIME_OF_DAY, __XWORD ... (case-insensitive); nullptr if not an elementary name.
  // `vendor_names` adds TwinCAT/CODESYS built-ins (PVOID, XWORD, UXINT, XINT, BIT).
  const Type* elementary(std::string_view name, bool vendor_names = true) const;
  const Type* generic(std::string_view name) const;  // ANY_NUM ...; nullptr if not generic
  const Type* generic(GenericKind kind) const;

  const Type* string_type(bool wide, uint32_t length);  // STRING(80)
  const Type* array_of(const Type* element, std::vector<ArrayDimension> dimensions);
  const Type* pointer_to(const Type* target);
  const Type* reference_to(const Type* target);
  const Type* subrange(const Type* base, int64_t lower, int64_t upper);
  // Named user types: one per declaration (nominal), filled in by the caller.
  Type* make_named(TypeKind kind, std::string name, const Symbol* declaration);

  // Default string length of STRING without (n): 80 in every profile rung knows.
  static constexpr uint32_t kDefaultStringLength = 80;

 private:
  const Type* add(Type type);
  const Type* indirection(TypeKind kind, const Type* target);  // POINTER TO / REFERENCE TO

  std::deque<Type> storage_;
  std::map<std::string, const Type*> elementary_;  // upper-case names
  std::map<std::string, const Type*> vendor_elementary_;
  std::map<std::string, const Type*> generics_;
  std::map<std::tuple<int, const Type*, uint32_t>, const Type*> strings_pointers_;
  std::map<std::string, const Type*> arrays_subranges_;  // by display name + element identity
  std::mutex mutex_;  // bodies are checked in parallel and may ask for new derived types
  const Type* unknown_ = nullptr;
  const Type* void_ = nullptr;
  const Type* null_ = nullptr;
};

}  // namespace rung::check
