// Symbols: every named thing a project declares — POUs and their members, data types, variables,
// enum values, global variable lists, configurations. A Symbol points into the syntax tree of the
// file that declares it; it is owned by that file's FileSymbols, so re-reading one file replaces
// exactly its symbols.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "checker/symbols/names.hpp"
#include "checker/types/type.hpp"
#include "parser/ast.hpp"
#include "parser/syntax_tree.hpp"

namespace rung::check {

enum class SymbolKind : uint8_t {
  Program,
  Function,
  FunctionBlock,
  Class,
  Interface,
  Method,
  Property,
  Action,
  Transition,
  DataType,  // STRUCT, UNION, ENUM, alias, subrange type
  Variable,  // VAR*, struct fields, global variables
  EnumValue,
  GlobalList,  // a GVL: the qualifier of its variables
  Namespace,   // a library namespace
  Configuration,
  Resource,
  Task,
  ProgramInstance,  // PROGRAM x WITH task : Type
  Step,             // SFC step (implicit variables x, t)
};
std::string_view symbol_kind_name(SymbolKind kind);
bool is_pou_kind(SymbolKind kind);       // Program .. Transition
bool is_callable_kind(SymbolKind kind);  // Program, Function, FunctionBlock, Method, Action, Class

// Flags of a variable or a POU, set from qualifiers, modifiers and attributes.
enum SymbolFlag : uint32_t {
  kConstant = 1u << 0,
  kRetain = 1u << 1,
  kPersistent = 1u << 2,
  kHasInitializer = 1u << 3,
  kAbstract = 1u << 4,
  kFinal = 1u << 5,
  kPrivate = 1u << 6,
  kProtected = 1u << 7,
  kInternal = 1u << 8,
  kPublic = 1u << 9,
  kQualifiedOnly = 1u << 10,  // {attribute 'qualified_only'} on a GVL or enum
  kHide = 1u << 11,
  kObsolete = 1u << 12,
  kExtensible = 1u << 13,  // rung.extensible: the parameter may repeat (IN2, IN3, ...)
  kLibrary = 1u << 14,     // declared in a stub library
  kStrict = 1u << 15,      // {attribute 'strict'} on an enum
  kOverride = 1u << 16,    // METHOD OVERRIDE
  kInputAssumed = 1u << 17,
};

struct Attribute {
  std::string name;   // lower-case as vendors spell them: qualified_only, obsolete, ...
  std::string value;  // text after := without quotes, may be empty
};

using SourceId = uint32_t;
constexpr SourceId kNoSource = UINT32_MAX;

struct Symbol {
  SymbolKind kind = SymbolKind::Variable;
  std::string_view name;  // points into the declaring file's tree text
  SourceId source = kNoSource;
  TextRange name_range;  // in the declaring file's tree coordinates
  SyntaxNode node;       // the declaration (POU, var_declaration, type_declaration, enum_value, ...)
  Symbol* owner = nullptr;
  uint32_t flags = 0;
  std::vector<Attribute> attributes;

  // Variables: the section and the written type; `type` is filled in by the linker.
  ast::VarSection section = ast::VarSection::Unknown;
  SyntaxNode type_node;  // also: a FUNCTION's / METHOD's / PROPERTY's result type
  SyntaxNode location_node;  // AT %IX0.0
  const Type* type = nullptr;  // variable's type; the POU's own instance type; a data type

  // POUs, structs, enums, GVLs: members by name and in declaration order.
  std::unordered_map<std::string_view, Symbol*, NameHash, NameEqual> members;
  std::vector<Symbol*> ordered;
  std::vector<SyntaxNode> base_nodes;       // EXTENDS (names as written)
  std::vector<SyntaxNode> interface_nodes;  // IMPLEMENTS
  const Symbol* base = nullptr;             // resolved EXTENDS (first), by the linker
  std::vector<const Symbol*> bases;         // every EXTENDS target (interfaces may have several)
  std::vector<const Symbol*> interfaces;    // resolved IMPLEMENTS
  const Type* result_type = nullptr;        // FUNCTION/METHOD/PROPERTY result

  bool has(SymbolFlag flag) const { return (flags & flag) != 0; }
  const Attribute* attribute(std::string_view name) const;
  // A member declared here (not inherited).
  Symbol* own_member(std::string_view member_name) const {
    auto found = members.find(member_name);
    return found == members.end() ? nullptr : found->second;
  }
};

}  // namespace rung::check
