// L001-L004: names start with the prefix rung.toml [lint.naming] sets for their type, scope or
// kind. Every key has a default (the Hungarian-style conventions of the CODESYS textbook and
// TwinCAT projects); a key set to "" is not checked. Keys are case-sensitive: upper-case keys are
// IEC type names and declaration keywords (BOOL, ARRAY, FUNCTION_BLOCK, STRUCT), lower-case keys
// are kinds of variables (instance, struct, enum) and scopes (global, input, ...).
#include <fmt/format.h>

#include <array>

#include "checker/lint/naming_patterns.hpp"
#include "checker/lint/naming_rules.hpp"
#include "checker/lint/structure_pou.hpp"

namespace rung::lint::naming {
namespace {

using check::Symbol;
using check::SymbolKind;
using check::Type;
using check::TypeKind;

struct DefaultPattern {
  std::string_view key;
  std::string_view pattern;
};

// L001: prefixes by type. The elementary ones are the CODESYS textbook's Hungarian prefixes
// (BOOL b, BYTE by, ... LREAL lr); derived types follow TwinCAT habits (st, e, fb, ref).
constexpr std::array kTypeDefaults = {
    DefaultPattern{"BOOL", "b"},
    DefaultPattern{"BIT", "b"},
    DefaultPattern{"BYTE", "by"},
    DefaultPattern{"WORD", "w"},
    DefaultPattern{"DWORD", "dw"},
    DefaultPattern{"LWORD", "lw"},
    DefaultPattern{"SINT", "si"},
    DefaultPattern{"USINT", "usi"},
    DefaultPattern{"INT", "i"},
    DefaultPattern{"UINT", "ui"},
    DefaultPattern{"DINT", "di"},
    DefaultPattern{"UDINT", "udi"},
    DefaultPattern{"LINT", "li"},
    DefaultPattern{"ULINT", "uli"},
    DefaultPattern{"REAL", "r"},
    DefaultPattern{"LREAL", "lr"},
    DefaultPattern{"TIME", "t"},
    DefaultPattern{"LTIME", "lt"},
    DefaultPattern{"DATE", "d"},
    DefaultPattern{"LDATE", "ld"},
    DefaultPattern{"TIME_OF_DAY", "tod"},
    DefaultPattern{"LTIME_OF_DAY", "ltod"},
    DefaultPattern{"DATE_AND_TIME", "dt"},
    DefaultPattern{"LDATE_AND_TIME", "ldt"},
    DefaultPattern{"STRING", "s"},
    DefaultPattern{"WSTRING", "ws"},
    DefaultPattern{"CHAR", "ch"},
    DefaultPattern{"WCHAR", "wch"},
    DefaultPattern{"ARRAY", "a"},
    DefaultPattern{"POINTER", "p"},
    DefaultPattern{"REFERENCE", "ref"},
    DefaultPattern{"instance", "fb"},
    DefaultPattern{"struct", "st"},
    DefaultPattern{"union", "u"},
    DefaultPattern{"enum", "e"},
    DefaultPattern{"interface", "i"},
};

// The short spellings of the long date and time type names, also accepted as keys.
constexpr std::array kTypeSynonyms = {
    DefaultPattern{"TIME_OF_DAY", "TOD"},
    DefaultPattern{"LTIME_OF_DAY", "LTOD"},
    DefaultPattern{"DATE_AND_TIME", "DT"},
    DefaultPattern{"LDATE_AND_TIME", "LDT"},
};

std::string_view default_for(std::string_view key) {
  for (const DefaultPattern& row : kTypeDefaults) {
    if (row.key == key) return row.pattern;
  }
  return {};
}

// The pattern a key has under the project's settings.
std::string type_pattern(const LintContext& context, std::string_view key) {
  std::string_view pattern = context.naming(key, default_for(key));
  for (const DefaultPattern& synonym : kTypeSynonyms) {
    if (synonym.key == key) pattern = context.naming(key, context.naming(synonym.pattern, default_for(key)));
  }
  return std::string(pattern);
}

struct TypeLevel {
  std::string key;      // the [lint.naming] key
  std::string pattern;  // its prefix pattern
};

// One level per type constructor, outermost first: POINTER TO ARRAY OF BYTE gives POINTER,
// ARRAY, BYTE. Empty for types no key names (generic, unknown).
std::vector<TypeLevel> type_levels(const LintContext& context, const Type* type) {
  std::vector<TypeLevel> levels;
  for (int depth = 0; type && depth < 8; ++depth) {
    type = check::underlying(type);
    std::string key;
    const Type* next = nullptr;
    switch (type->kind) {
      case TypeKind::Subrange: type = type->element; continue;
      case TypeKind::Array: key = "ARRAY", next = type->element; break;
      case TypeKind::Pointer: key = "POINTER", next = type->element; break;
      case TypeKind::Reference: key = "REFERENCE", next = type->element; break;
      case TypeKind::Pou:
        key = type->declaration && type->declaration->kind == SymbolKind::Interface ? "interface" : "instance";
        break;
      case TypeKind::Struct: key = "struct"; break;
      case TypeKind::Union: key = "union"; break;
      case TypeKind::Enum: key = "enum"; break;
      case TypeKind::String: key = "STRING"; break;
      case TypeKind::WString: key = "WSTRING"; break;
      case TypeKind::Bool:
      case TypeKind::Bit:
      case TypeKind::SignedInt:
      case TypeKind::UnsignedInt:
      case TypeKind::Real:
      case TypeKind::Duration:
      case TypeKind::Date:
      case TypeKind::TimeOfDay:
      case TypeKind::DateTime:
      case TypeKind::Char:
      case TypeKind::WChar: key = type->name; break;
      default: break;
    }
    if (key.empty()) break;
    levels.push_back({key, type_pattern(context, key)});
    type = next;
  }
  return levels;
}

struct Scope {
  std::string_view key;
  std::string_view fallback;
  std::string_view label;  // for messages: "global variable"
};

Scope scope_of(const Symbol& variable) {
  using ast::VarSection;
  const bool constant = variable.has(check::kConstant);
  switch (variable.section) {
    case VarSection::Global:
      return constant ? Scope{"global_constant", "gc_", "global constant"} : Scope{"global", "g_", "global variable"};
    case VarSection::Input: return {"input", "", "input"};
    case VarSection::Output: return {"output", "", "output"};
    case VarSection::InOut: return {"in_out", "", "in-out parameter"};
    case VarSection::Temp: return {"temp", "", "temporary variable"};
    case VarSection::Stat:
    case VarSection::Inst:
      return constant ? Scope{"constant", "c_", "constant"} : Scope{"static", "", "static variable"};
    default: return constant ? Scope{"constant", "c_", "constant"} : Scope{"local", "", "local variable"};
  }
}

bool is_parameter(const Symbol& variable) {
  using ast::VarSection;
  return variable.section == VarSection::Input || variable.section == VarSection::Output ||
         variable.section == VarSection::InOut;
}

}  // namespace

// VAR_EXTERNAL repeats a global's name (judged where it is declared), struct fields belong to
// their type, VAR_CONFIG and VAR_ACCESS name paths; parameters of a method whose signature an
// interface or base gives are judged there.
std::vector<const Symbol*> named_variables(const LintContext& context) {
  using ast::VarSection;
  std::vector<const Symbol*> out;
  for (const Symbol& symbol : context.source().symbols.storage) {
    if (symbol.kind != SymbolKind::Variable || symbol.name.empty() || !symbol.owner) continue;
    const Symbol& owner = *symbol.owner;
    if (!check::is_pou_kind(owner.kind) && owner.kind != SymbolKind::GlobalList &&
        symbol.section != VarSection::Global) {
      continue;
    }
    if (symbol.section == VarSection::External || symbol.section == VarSection::Config ||
        symbol.section == VarSection::Access || symbol.section == VarSection::Unknown) {
      continue;
    }
    if (is_parameter(symbol) && signature_is_given(context.model(), owner)) continue;
    out.push_back(&symbol);
  }
  return out;
}

namespace {

// MAX_SPEED: constants written in capitals are the other common convention, without type prefix.
bool is_capitals_constant(const Symbol& variable) {
  if (!variable.has(check::kConstant)) return false;
  for (char c : variable.name) {
    if (c >= 'a' && c <= 'z') return false;
  }
  return true;
}

}  // namespace

void check_variable_prefix(LintContext& context) {
  LoopCounters counters(context.nodes());
  for (const Symbol* variable : named_variables(context)) {
    if (is_capitals_constant(*variable) || counters.contains(*variable)) continue;
    const Type* type = context.model().type_of(variable);
    const std::vector<TypeLevel> levels = type_levels(context, type);
    if (levels.empty() || alternatives(levels.front().pattern).empty()) continue;
    // The scope prefix comes first (g_bStart): the type prefix follows it.
    const Scope scope = scope_of(*variable);
    const std::string_view name = variable->name;
    const size_t scope_length = matched_prefix_length(name, context.naming(scope.key, scope.fallback));
    const std::string_view rest = name.substr(scope_length);
    std::vector<std::string> chain;
    chain.reserve(levels.size());
    for (const TypeLevel& level : levels) chain.push_back(level.pattern);
    if (has_prefix_chain(rest, chain)) continue;
    const TypeLevel& first = levels.front();
    context.report(
        "L001",
        fmt::format("'{}' is {}: its name should start with {} (e.g. {}{})", name, type->name,
                    describe_pattern(first.pattern), name.substr(0, scope_length), suggested_name(rest, first.pattern)),
        variable->name_range,
        fmt::format("the prefix shows the type wherever the name is used; rung.toml [lint.naming] {} = "
                    "\"...\" sets it (\"\" turns this check off for {})",
                    first.key, first.key));
  }
}

void check_scope_prefix(LintContext& context) {
  for (const Symbol* variable : named_variables(context)) {
    if (is_capitals_constant(*variable)) continue;
    const Scope scope = scope_of(*variable);
    const std::string_view pattern = context.naming(scope.key, scope.fallback);
    if (alternatives(pattern).empty() || has_prefix(variable->name, pattern)) continue;
    context.report("L002",
                   fmt::format("{} '{}' should start with {} (e.g. {})", scope.label, variable->name,
                               describe_pattern(pattern), suggested_name(variable->name, pattern)),
                   variable->name_range,
                   fmt::format("the prefix shows where a name is declared wherever it is used; rung.toml "
                               "[lint.naming] {} = \"...\" sets it (\"\" turns this check off)",
                               scope.key));
  }
}

namespace {

struct PouKey {
  SymbolKind kind;
  std::string_view key;
  std::string_view fallback;
};

// L003 defaults: the TwinCAT / CODESYS habits (FB_Motor, F_Scale or FC_Scale, PRG_Main,
// I_Mover or IMover). Members are not prefixed by default.
constexpr std::array kPouDefaults = {
    PouKey{SymbolKind::Program, "PROGRAM", "PRG_|P_"},
    PouKey{SymbolKind::Function, "FUNCTION", "F_|FC_"},
    PouKey{SymbolKind::FunctionBlock, "FUNCTION_BLOCK", "FB_"},
    PouKey{SymbolKind::Class, "CLASS", ""},
    PouKey{SymbolKind::Interface, "INTERFACE", "I"},
    PouKey{SymbolKind::Method, "METHOD", ""},
    PouKey{SymbolKind::Property, "PROPERTY", ""},
    PouKey{SymbolKind::Action, "ACTION", ""},
};

// The program the IDE creates with every project keeps its name.
bool is_default_program(const Symbol& pou) {
  return pou.kind == SymbolKind::Program &&
         (check::names_equal(pou.name, "MAIN") || check::names_equal(pou.name, "PLC_PRG"));
}

}  // namespace

void check_pou_prefix(LintContext& context) {
  for (const Symbol* pou : context.pous()) {
    if (pou->name.empty() || is_default_program(*pou) || signature_is_given(context.model(), *pou)) continue;
    for (const PouKey& row : kPouDefaults) {
      if (row.kind != pou->kind) continue;
      const std::string_view pattern = context.naming(row.key, row.fallback);
      if (alternatives(pattern).empty() || has_prefix(pou->name, pattern)) break;
      context.report("L003",
                     fmt::format("{} should start with {} (e.g. {})", pou_label(*pou), describe_pattern(pattern),
                                 suggested_name(pou->name, pattern)),
                     pou->name_range,
                     fmt::format("a prefix shows what kind of POU a name is wherever it is used; rung.toml "
                                 "[lint.naming] {} = \"...\" sets it (\"\" turns this check off)",
                                 row.key));
      break;
    }
  }
}

namespace {

struct TypeKey {
  ast::TypeKind kind;
  std::string_view key;
  std::string_view fallback;
  std::string_view label;
};

constexpr std::array kDataTypeDefaults = {
    TypeKey{ast::TypeKind::Struct, "STRUCT", "ST_", "structure"},
    TypeKey{ast::TypeKind::Enum, "ENUM", "E_", "enumeration"},
    TypeKey{ast::TypeKind::Union, "UNION", "U_", "union"},
    TypeKey{ast::TypeKind::Alias, "ALIAS", "T_", "type"},
};

}  // namespace

void check_type_prefix(LintContext& context) {
  const SyntaxNode root = context.root();
  if (!root) return;
  for (const ast::TypeDeclaration& declaration : ast::outline(root).types) {
    const SyntaxNode name = declaration.node().child_by_field("name");
    if (!name || name.is_missing()) continue;
    for (const TypeKey& row : kDataTypeDefaults) {
      if (row.kind != declaration.kind()) continue;
      const std::string_view pattern = context.naming(row.key, row.fallback);
      if (alternatives(pattern).empty() || has_prefix(name.text(), pattern)) break;
      context.report("L004",
                     fmt::format("{} '{}' should start with {} (e.g. {})", row.label, name.text(),
                                 describe_pattern(pattern), suggested_name(name.text(), pattern)),
                     name.range(),
                     fmt::format("a prefix shows what kind of type a name is wherever it is used; rung.toml "
                                 "[lint.naming] {} = \"...\" sets it (\"\" turns this check off)",
                                 row.key));
      break;
    }
  }
}

}  // namespace rung::lint::naming
