// What an expression is: its type, the declaration it names, its constant value.
#include <fmt/format.h>

#include <algorithm>

#include "checker/constant/const_eval.hpp"
#include "checker/semantic/body_checker.hpp"
#include "checker/semantic/builtins.hpp"
#include "checker/semantic/il_checker.hpp"
#include "checker/semantic/pragma_checker.hpp"
#include "parser/diagnostic_codes.hpp"

namespace rung::check {
namespace {

constexpr int kMaxDepth = 400;  // deeper expressions are typed Unknown (no stack exhaustion)

bool is_comparison(std::string_view op) {
  return op == "=" || op == "<>" || op == "<" || op == "<=" || op == ">" || op == ">=";
}

bool is_logical(std::string_view op) {
  return op == "AND" || op == "&" || op == "OR" || op == "XOR" || op == "AND_THEN" || op == "OR_ELSE";
}

// The operand of SIZEOF, XSIZEOF or __NEW, which may name a type instead of a value
// (SIZEOF(BOOL), __NEW(INT)); `identifier` stands alone as the call's argument.
bool is_type_operand(SyntaxNode identifier) {
  SyntaxNode argument = identifier.parent();
  if (!argument || argument.kind() != "argument" || argument.child_by_field("name")) return false;
  SyntaxNode list = argument.parent();
  SyntaxNode call = list ? list.parent() : SyntaxNode();
  if (!call || call.kind() != "call_expression") return false;
  SyntaxNode function = call.child_by_field("function");
  if (!function || function.kind() != "identifier") return false;
  const std::string_view name = function.text();
  return names_equal(name, "SIZEOF") || names_equal(name, "XSIZEOF") || names_equal(name, "__NEW");
}

// A variable of a {attribute 'qualified_only'} list or a value of such an enum written without
// its qualifier: the name exists, so "not declared" would send the user the wrong way.
void report_qualified_only(BodyChecker& checker, const Symbol* hidden, SyntaxNode name, SourceId here) {
  const Symbol* owner = hidden->owner;
  const std::string_view owner_name = owner ? owner->name : std::string_view("?");
  const bool list = owner && owner->kind == SymbolKind::GlobalList;
  std::vector<DiagnosticLabel> labels;
  if (hidden->source == here) labels.push_back({hidden->name_range, "declared here"});
  checker.report(codes::kQualifiedAccessRequired,
                 fmt::format("'{}' is in the {} '{}', which has {{attribute 'qualified_only'}}", name.text(),
                             list ? "global variable list" : "enumeration", owner_name),
                 name.range(), fmt::format("write {}.{}", owner_name, hidden->name), std::move(labels));
}

// An enum value written without its type while two enumerations define that name (002 L14524-
// 14561: colors_1.blue and colors_2.blue are fine, a bare blue is an error). Project enums hide
// library ones of the same name, as project POUs hide library POUs. Returns whether it reported.
bool report_ambiguous_enum_value(BodyChecker& checker, const ProjectModel& model, const Symbol* value, SyntaxNode name,
                                 SourceId here) {
  const auto* candidates = model.find_enum_values(value->name);
  if (!candidates) return false;
  std::vector<const Symbol*> enums;
  for (const Symbol* candidate : *candidates) {
    if (candidate->has(kLibrary) != value->has(kLibrary) || !candidate->owner) continue;
    // Two declarations of one enumeration (a type declared twice, reported on its own) do not
    // make its values ambiguous.
    const auto same_enum = [&](const Symbol* e) { return names_equal(e->name, candidate->owner->name); };
    if (std::none_of(enums.begin(), enums.end(), same_enum)) enums.push_back(candidate->owner);
  }
  if (enums.size() < 2) return false;
  std::vector<DiagnosticLabel> labels;
  for (const Symbol* candidate : *candidates) {
    if (candidate->source == here && candidate->has(kLibrary) == value->has(kLibrary)) {
      labels.push_back({candidate->name_range, fmt::format("a value of '{}'", candidate->owner->name)});
    }
  }
  checker.report(codes::kAmbiguousName,
                 fmt::format("'{}' is ambiguous: it is a value of both '{}' and '{}'{}", name.text(), enums[0]->name,
                             enums[1]->name, enums.size() > 2 ? " (and more)" : ""),
                 name.range(),
                 fmt::format("write the enumeration's name in front: {}.{} or {}.{}", enums[0]->name, value->name,
                             enums[1]->name, value->name),
                 std::move(labels));
  return true;
}

// Whether `node` stands in an IL instruction (asked only for the rare IL-only forms: parent() walks
// down from the root in tree-sitter 0.20).
bool inside_il(SyntaxNode node) {
  for (SyntaxNode up = node.parent(); up; up = up.parent()) {
    const std::string_view kind = up.kind();
    if (kind == "il_instruction" || kind == "il_body") return true;
    if (kind == "statement_list") return false;
  }
  return false;
}

// Values that can never have a member after '.': elementary values, strings, subranges, arrays
// (an enumeration's values are reached through its type name, not through a variable).
bool has_no_members(const Type* type) {
  if (type->kind == TypeKind::Subrange || type->kind == TypeKind::Array) return true;
  return type->kind != TypeKind::Enum && is_elementary(type);
}

}  // namespace

ExprInfo BodyChecker::type_of(SyntaxNode expression) { return type_expression(expression, 0); }

ExprInfo BodyChecker::type_expression(SyntaxNode expression, int depth) {
  ExprInfo unknown{.type = types_.unknown()};
  if (!expression || depth > kMaxDepth || expression.is_error() || expression.is_missing()) return unknown;
  switch (ast::expression_kind(expression)) {
    case ast::ExpressionKind::Literal:
      return type_literal(expression);
    case ast::ExpressionKind::Parenthesized: {
      ExprInfo inner = type_expression(expression.named_child(0), depth + 1);
      inner.assignable = false;
      return inner;
    }
    case ast::ExpressionKind::Identifier:
      return type_identifier(expression);
    case ast::ExpressionKind::Member:
      return type_member(expression, depth);
    case ast::ExpressionKind::Index:
      return type_index(expression, depth);
    case ast::ExpressionKind::Dereference:
      return type_dereference(expression, depth);
    case ast::ExpressionKind::Binary:
      return type_binary(expression, depth);
    case ast::ExpressionKind::Unary:
      return type_unary(expression, depth);
    case ast::ExpressionKind::Call:
      return type_call(expression, depth);
    case ast::ExpressionKind::DirectAddress:
      return ExprInfo{.type = types_.unknown(), .assignable = true};
    default:
      if (expression.kind() == "global_reference") return type_identifier(expression);
      if (expression.kind() == "il_expression") {
        // `(a ADD b)` is an IL argument form (CAL fb(P := (a ADD b))); the grammar also lets it
        // through in ST calls, where it is not the language.
        if (!inside_il(expression)) {
          report(codes::kSyntaxError, "an IL expression in Structured Text", expression.range(),
                 "write the ST expression, e.g. (a + b)");
        }
        return IlChecker(*this, model_, pou_).value_of(expression);
      }
      // Initializers, assignment expressions: their parts are still checked for names.
      for (uint32_t i = 0; i < expression.named_child_count(); ++i) {
        SyntaxNode child = expression.named_child(i);
        if (child.kind() == "field_initializer") {
          type_expression(child.child_by_field("value"), depth + 1);
        } else {
          type_expression(child, depth + 1);
        }
      }
      return unknown;
  }
}

const Type* BodyChecker::literal_type(const ConstValue& value, bool based) const {
  // Untyped constants take the smallest type that holds them (CODESYS: 211 is USINT).
  switch (value.kind) {
    case ConstValue::Kind::Integer: {
      const __int128 v = value.integer;
      if (based) {
        if (v <= 0xFF) return types_.elementary("BYTE");
        if (v <= 0xFFFF) return types_.elementary("WORD");
        if (v <= 0xFFFFFFFFll) return types_.elementary("DWORD");
        return types_.elementary("LWORD");
      }
      if (v >= 0) {
        if (v <= 255) return types_.elementary("USINT");
        if (v <= 65535) return types_.elementary("UINT");
        if (v <= 4294967295ll) return types_.elementary("UDINT");
        return types_.elementary("ULINT");
      }
      if (v >= -128) return types_.elementary("SINT");
      if (v >= -32768) return types_.elementary("INT");
      if (v >= -2147483648ll) return types_.elementary("DINT");
      return types_.elementary("LINT");
    }
    case ConstValue::Kind::Real:
      return types_.elementary("REAL");  // adapts to LREAL where needed
    case ConstValue::Kind::Bool:
      return types_.elementary("BOOL");
    case ConstValue::Kind::Duration:
      return types_.elementary("TIME");
    case ConstValue::Kind::String:
      return types_.string_type(false, static_cast<uint32_t>(std::max<size_t>(1, string_length(value.text, false))));
    case ConstValue::Kind::Date:
      return types_.elementary("DATE");
  }
  return types_.unknown();
}

ExprInfo BodyChecker::type_literal(SyntaxNode literal) {
  const std::string_view kind = literal.kind();
  ExprInfo info{.type = types_.unknown()};
  if (kind == "date_literal" || kind == "time_of_day_literal" || kind == "date_and_time_literal") {
    const std::string_view text = literal.text();
    const bool long_variant = !text.empty() && (text[0] == 'L' || text[0] == 'l');
    if (kind == "date_literal") info.type = types_.elementary(long_variant ? "LDATE" : "DATE");
    if (kind == "time_of_day_literal") info.type = types_.elementary(long_variant ? "LTOD" : "TOD");
    if (kind == "date_and_time_literal") info.type = types_.elementary(long_variant ? "LDT" : "DT");
    if (const std::string problem = point_in_time_literal_problem(text); !problem.empty()) {
      report(codes::kLiteralOutOfRange, fmt::format("invalid {} literal '{}': {}", info.type->name, text, problem),
             literal.range());
    }
    return info;
  }
  if (kind == "time_literal") {
    std::string problem;
    const Profile& profile = model_.profile();
    auto value = parse_duration_literal(literal.text(), &problem, profile.duration_rules);
    const std::string_view text = literal.text();
    info.type = types_.elementary(!text.empty() && (text[0] == 'L' || text[0] == 'l') ? "LTIME" : "TIME");
    // TIME is 32 bits of milliseconds, unsigned in CODESYS (T#49d17h2m47s295ms), signed in OpenPCS.
    const __int128 max_time_nanoseconds = static_cast<__int128>(profile.max_time_milliseconds) * 1'000'000;
    if (!value && !problem.empty()) {
      const bool needs_ltime = problem.find("LTIME") != std::string::npos;
      report(codes::kLiteralOutOfRange, fmt::format("invalid duration '{}': {}", text, problem), literal.range(),
             needs_ltime ? "write an LTIME#... literal, or round to milliseconds"
                         : "write the units from the largest to the smallest, the last one within its range: T#1d2h3m4s5ms");
    } else if (value && info.type->name == "TIME" && (*value > max_time_nanoseconds || *value < -max_time_nanoseconds)) {
      report(codes::kLiteralOutOfRange,
             fmt::format("'{}' does not fit in a TIME (at most {})", text,
                         duration_literal_text(max_time_nanoseconds)),
             literal.range(), "use LTIME for longer durations");
    } else if (value) {
      info.value = ConstValue::of_duration(*value);
    }
    return info;
  }
  if (kind == "string_literal") {
    if (const std::string problem = string_escape_problem(literal.text()); !problem.empty()) {
      report(codes::kLiteralOutOfRange, fmt::format("invalid string literal: {}", problem), literal.range(),
             "write $$ for a dollar sign");
    }
    bool wide = false;
    auto text = parse_string_literal(literal.text(), &wide);
    if (text) {
      info.value = ConstValue{.kind = ConstValue::Kind::String, .text = *text};
      info.type = types_.string_type(wide, static_cast<uint32_t>(std::max<size_t>(1, string_length(*text, wide))));
    }
    info.untyped_literal = true;
    return info;
  }
  if (kind == "typed_literal") {
    SyntaxNode type_node = literal.child_by_field("type");
    SyntaxNode value_node = literal.child_by_field("value");
    const Type* type = type_node ? types_.elementary(type_node.text()) : nullptr;
    if (!type && type_node) {
      // E_Color#Red: an enum value written with its type.
      const Symbol* enum_type = model_.find_global(type_node.text());
      if (enum_type && enum_type->kind == SymbolKind::DataType && value_node) {
        const Symbol* value = model_.find_member(enum_type, value_node.text());
        if (!value) {
          report(codes::kUnknownMember, fmt::format("'{}' has no value '{}'", enum_type->name, value_node.text()),
                 value_node.range());
        }
        // E_Color#Red is the value Red, as constant as a bare Red (CASE labels need its number).
        if (value && value->kind == SymbolKind::EnumValue) return info_for_symbol(value, value_node);
        return ExprInfo{.type = model_.type_of(enum_type), .symbol = value};
      }
      if (!enum_type && type_node) {
        report(codes::kUnknownLibraryName, fmt::format("unknown type '{}'", type_node.text()), type_node.range());
      }
      return info;
    }
    info.type = type ? type : types_.unknown();
    auto value = literal_value(literal);
    if (value && type) {
      // A typed literal must fit its type without loss (CODESYS: error, L4303-4305).
      if (value->is_integer()) {
        if (auto range = integer_range(type); range && (value->integer < range->lower || value->integer > range->upper)) {
          report(codes::kLiteralOutOfRange,
                 fmt::format("'{}' does not fit into {} ({}..{})", literal.text(), type->name,
                             int128_to_string(range->lower), int128_to_string(range->upper)),
                 literal.range(), "use a wider type");
        } else if (type->kind == TypeKind::Bool && value->integer > 1) {
          report(codes::kLiteralOutOfRange, fmt::format("'{}' is not a BOOL value", literal.text()), literal.range());
        }
      } else if (value->kind == ConstValue::Kind::Real && is_integer(type)) {
        report(codes::kLiteralOutOfRange,
               fmt::format("'{}' has a fraction: it does not fit into {} without loss", literal.text(), type->name),
               literal.range(), fmt::format("write an integer, or use REAL_TO_{}()", type->name));
      } else if (value->kind == ConstValue::Kind::Real && type->kind == TypeKind::Real) {
        if (const std::string problem = real_range_problem(value->real, type->bits == 32); !problem.empty()) {
          report(codes::kLiteralOutOfRange, fmt::format("'{}' does not fit into {}: {}", literal.text(), type->name, problem),
                 literal.range(), type->bits == 32 ? "use LREAL" : std::string());
        }
      }
      info.value = value;
    }
    return info;
  }
  auto value = literal_value(literal);
  if (!value) {
    if (kind == "integer_literal") {
      report(codes::kLiteralOutOfRange, fmt::format("'{}' is too large for any integer type", literal.text()),
             literal.range());
    }
    return info;
  }
  if (value->kind == ConstValue::Kind::Real) {
    // Only a value beyond LREAL is wrong here; REAL or LREAL is decided where it is stored.
    if (const std::string problem = real_range_problem(value->real, false); !problem.empty()) {
      report(codes::kLiteralOutOfRange, fmt::format("'{}' is {}", literal.text(), problem), literal.range());
      return info;
    }
  }
  info.value = value;
  info.untyped_literal = value->kind != ConstValue::Kind::Bool;
  // 2#, 8#, 16#: a bit pattern; 10#30000 is just a decimal number.
  info.based_literal = kind == "integer_literal" && literal.text().find('#') != std::string_view::npos &&
                       !literal.text().starts_with("10#");
  info.type = literal_type(*value, info.based_literal);
  return info;
}

ExprInfo BodyChecker::info_for_symbol(const Symbol* symbol, SyntaxNode where) {
  ExprInfo info{.type = types_.unknown(), .symbol = symbol};
  if (symbol->has(kObsolete) && !inside(*symbol)) out_.push_back(obsolete_use(*symbol, where.range()));
  switch (symbol->kind) {
    case SymbolKind::Variable:
      info.type = model_.type_of(symbol);
      info.assignable = true;
      return info;
    case SymbolKind::EnumValue:
      info.type = model_.type_of(symbol);
      if (auto number = model_.enum_value(symbol)) info.value = ConstValue::of_integer(*number);
      return info;
    case SymbolKind::Function:
    case SymbolKind::Method:
    case SymbolKind::Property:
      // Inside itself the POU's name is its result variable; a property reads through GET.
      info.type = symbol->result_type ? symbol->result_type : types_.unknown();
      info.assignable = true;
      return info;
    case SymbolKind::Program:
      info.type = model_.type_of(symbol);  // the program's single instance
      return info;
    case SymbolKind::DataType:
    case SymbolKind::FunctionBlock:
    case SymbolKind::Interface:
    case SymbolKind::Class:
      info.type = model_.type_of(symbol);
      info.names_type = true;
      return info;
    case SymbolKind::GlobalList:
      info.names_namespace = true;
      return info;
    default:
      return info;
  }
}

// Also `.x` (a global_reference): CODESYS's global scope operator names the global x even where
// a local x hides it (002 L10254-10263).
ExprInfo BodyChecker::type_identifier(SyntaxNode identifier) {
  if (identifier.kind() == "qualified_name") {
    return ExprInfo{.type = types_.unknown()};  // namespaces written as a.b.c in declarations
  }
  const bool global_only = identifier.kind() == "global_reference";
  SyntaxNode name_node = global_only ? identifier.child_by_field("name") : identifier;
  if (!name_node) return ExprInfo{.type = types_.unknown()};
  const std::string_view name = name_node.text();
  if (const Symbol* symbol = global_only ? model_.lookup_global(name) : model_.lookup(&pou_, name)) {
    // Inside its own enumeration (the default after the value list: E : (A, B) := B) a value is
    // not ambiguous: the enumeration's own names come first there.
    if (symbol->kind == SymbolKind::EnumValue && symbol->owner != &pou_ &&
        report_ambiguous_enum_value(*this, model_, symbol, name_node, pou_.source)) {
      return ExprInfo{.type = types_.unknown()};  // which enum it is stays open: no follow-up errors
    }
    return info_for_symbol(symbol, name_node);
  }
  if (model_.is_library_namespace(name)) return ExprInfo{.type = types_.unknown(), .names_namespace = true};
  if (!global_only) {
    if (sfc_names_.contains(upper_name(name))) return ExprInfo{.type = types_.unknown(), .assignable = true};
    if (const Builtin* builtin = find_builtin(name)) {
      return ExprInfo{.type = builtin->value_type ? types_.elementary(builtin->value_type) : types_.unknown(),
                      .names_namespace = builtin->is_namespace};
    }
  }
  if (const Symbol* hidden = model_.find_qualified_only(name)) {
    report_qualified_only(*this, hidden, name_node, pou_.source);
    return info_for_symbol(hidden, name_node);
  }
  if (global_only) {
    report(codes::kUndeclaredName, fmt::format("there is no global variable '{}'", name), identifier.range(),
           fmt::format("'.{}' names a global only; write '{}' for a local or parameter", name, name));
    return ExprInfo{.type = types_.unknown(), .assignable = true};
  }
  if (const Type* type = types_.elementary(name); type && is_type_operand(identifier)) {
    return ExprInfo{.type = type, .names_type = true};
  }
  if (!model_.has_unresolved_base(&pou_)) report_undeclared(identifier);
  return ExprInfo{.type = types_.unknown(), .assignable = true};
}


void BodyChecker::report_undeclared(SyntaxNode name) {
  const std::vector<std::string_view> candidates = model_.visible_names(&pou_);
  const std::string_view suggestion = closest_name(name.text(), candidates);
  // `TcUnit.RUN()`, `Tc2_System.F_GetTime()`, `E_State.Idle`: an unknown qualifier with no close
  // local name is most likely a library (or its enum) that rung has no stubs for. Such names are
  // E002, the one code for "add the library's stubs", so they can be counted and silenced apart
  // from real typos.
  SyntaxNode parent = name.parent();
  if (suggestion.empty() && parent && parent.kind() == "member_expression" &&
      parent.child_by_field("object") == name) {
    report(codes::kUnknownLibraryName, fmt::format("unknown name '{}' (a library namespace, global list or type)", name.text()),
           name.range(),
           "if it comes from a vendor library, add that library's stubs (the 'libraries' list under [project] in "
           "rung.toml); otherwise declare it");
    return;
  }
  report(codes::kUndeclaredName, fmt::format("'{}' is not declared", name.text()), name.range(),
         suggestion.empty() ? "declare it in a VAR section or a global variable list"
                            : fmt::format("did you mean '{}'?", suggestion));
}

ExprInfo BodyChecker::type_member(SyntaxNode expression, int depth) {
  SyntaxNode object_node = expression.child_by_field("object");
  SyntaxNode member_node = expression.child_by_field("member");
  ExprInfo object = type_expression(object_node, depth + 1);
  // Members of something unknown stay unknown, and writable: one missing type, one diagnostic.
  ExprInfo unknown{.type = types_.unknown(), .assignable = true};
  if (!member_node) return unknown;
  const std::string_view member = member_node.text();
  // Bit access: w.3, and CODESYS constant bit numbers w.cBit (a CONSTANT of an integer type).
  const bool literal_bit = member_node.kind() == "integer_literal";
  std::optional<ConstValue> constant_bit;
  if (!literal_bit && member_node.kind() == "identifier" && !object.names_type && !object.names_namespace &&
      underlying(object.type)->kind != TypeKind::Enum && is_any_int_or_bit(arithmetic_type(object.type))) {
    constant_bit = model_.constant_value(member_node, &pou_);
    if (constant_bit && !constant_bit->is_integer()) constant_bit.reset();
  }
  if (literal_bit || constant_bit) {
    const Type* base = arithmetic_type(object.type);
    // IEC: bits of bit strings only (OpenPCS S5031: not of a DINT); CODESYS: of integers too.
    const bool bits_of_integer = is_integer(base) && !model_.profile().bits_and_integers_mix;
    if (!base->is_unknown() && is_any_int_or_bit(base) && !bits_of_integer) {
      auto bit = literal_bit ? parse_integer_literal(member) : std::optional<__int128>(constant_bit->integer);
      if (bit && base->bits && (*bit >= base->bits || *bit < 0)) {
        report(codes::kIndexOutOfRange,
               fmt::format("bit {} does not exist in {} ({} bits)", int128_to_string(*bit), base->name, base->bits),
               member_node.range());
      }
    } else if (!base->is_unknown() && base->kind != TypeKind::Bool) {
      report(codes::kInvalidOperand, fmt::format("bit access on a value of type {}", object.type->name),
             member_node.range());
    }
    return ExprInfo{.type = types_.elementary("BOOL"), .assignable = object.assignable || base->is_unknown()};
  }
  if (member_node.kind() == "direct_variable") return unknown;
  if (object.names_namespace) {
    // GVL.x, Library.F, __SYSTEM.X
    const Symbol* qualifier = object.symbol;
    if (qualifier && qualifier->kind == SymbolKind::GlobalList) {
      if (const Symbol* found = model_.find_member(qualifier, member)) return info_for_symbol(found, member_node);
      // Lists of the same name in other files (TwinCAT GVLs split in several objects).
      if (const Symbol* variable = model_.find_in_global_lists(qualifier->name, member)) {
        return info_for_symbol(variable, member_node);
      }
      if (const Symbol* variable = model_.find_global_variable(member)) return info_for_symbol(variable, member_node);
      std::vector<std::string_view> names;
      names.reserve(qualifier->ordered.size());
      for (const Symbol* variable : qualifier->ordered) names.push_back(variable->name);
      const std::string_view suggestion = closest_name(member, names);
      report(codes::kUnknownMember, fmt::format("global variable list '{}' has no variable '{}'", qualifier->name, member),
             member_node.range(), suggestion.empty() ? std::string() : fmt::format("did you mean '{}'?", suggestion));
      return unknown;
    }
    if (object_node.kind() == "identifier" && model_.is_library_namespace(object_node.text())) {
      if (const Symbol* found = model_.find_in_library(object_node.text(), member)) return info_for_symbol(found, member_node);
    }
    return unknown;
  }
  if (object.names_type) {
    // E_Color.Red (enum values), FB_X.Constant (not IEC; tolerated as unknown)
    const Symbol* type_symbol = object.symbol;
    if (type_symbol && type_symbol->kind == SymbolKind::DataType) {
      if (const Symbol* value = model_.find_member(type_symbol, member)) return info_for_symbol(value, member_node);
      if (underlying(model_.type_of(type_symbol))->kind == TypeKind::Enum) {
        report(codes::kUnknownMember, fmt::format("enum '{}' has no value '{}'", type_symbol->name, member),
               member_node.range());
      }
    }
    return unknown;
  }
  const Type* type = underlying(object.type);
  if (type->kind == TypeKind::Reference && type->element) type = underlying(type->element);
  if (has_no_members(type) && (!object.symbol || object.symbol->kind == SymbolKind::Variable)) {
    // i.a with i : INT (OpenPCS S3006). A POU's name stands for its result inside it, so
    // F.x there is left alone.
    const Type* base = arithmetic_type(type);
    const bool bits = is_bit_string(base) || (is_integer(base) && model_.profile().bits_and_integers_mix);
    report(codes::kUnknownMember,
           fmt::format("'{}' is {}, which has no members: '{}' cannot follow the '.'", object_node.text(),
                       object.type->name, member),
           member_node.range(),
           bits ? "bit access needs a bit number: a literal (w.3) or a CONSTANT"
                : "only structures and function block instances have members");
    return unknown;
  }
  if (type->is_unknown() || !type->declaration) return unknown;
  if (type->kind == TypeKind::Pointer) return unknown;
  const Symbol* container = type->declaration;
  const Symbol* found = model_.find_member(container, member);
  if (!found && model_.has_unresolved_base(container)) return unknown;
  if (!found) {
    std::vector<std::string_view> names;
    int depth = 0;
    for (const Symbol* c = container; c && depth < 32; c = c->base, ++depth) {  // bounded: EXTENDS may cycle
      for (const Symbol* m : c->ordered) names.push_back(m->name);
    }
    const std::string_view suggestion = closest_name(member, names);
    report(codes::kUnknownMember, fmt::format("'{}' has no member '{}'", type->name, member), member_node.range(),
           suggestion.empty() ? std::string() : fmt::format("did you mean '{}'?", suggestion));
    return unknown;
  }
  ExprInfo info = info_for_symbol(found, member_node);
  info.names_type = false;
  if (found->kind == SymbolKind::Variable && container->kind != SymbolKind::DataType &&
      found->section == ast::VarSection::Output && object.symbol != &pou_) {
    info.read_only_output = true;  // fb.Q is written by the FB, read by the caller
  }
  if (found->kind == SymbolKind::Variable && container->kind != SymbolKind::DataType) {
    const bool inside = container == &pou_ || container == pou_.owner;
    if (!inside && (found->section == ast::VarSection::Var || found->section == ast::VarSection::Temp) &&
        !found->has(kLibrary)) {
      // CODESYS allows reading a program's or FB's local variables from outside (instance.local).
      info.assignable = object.assignable || object.symbol;
    }
  }
  return info;
}

ExprInfo BodyChecker::type_index(SyntaxNode expression, int depth) {
  ExprInfo object = type_expression(expression.child_by_field("object"), depth + 1);
  std::vector<SyntaxNode> indices = expression.children_by_field("index");
  std::vector<ExprInfo> index_infos;
  for (SyntaxNode index : indices) {
    ExprInfo info = type_expression(index, depth + 1);
    const Type* index_type = arithmetic_type(info.type);
    if (!index_type->is_unknown() && !is_any_int_or_bit(index_type) && index_type->kind != TypeKind::Generic) {
      report(codes::kTypeMismatch, fmt::format("an array index must be an integer, not {}", info.type->name),
             index.range());
    }
    index_infos.push_back(std::move(info));
  }
  const Type* type = underlying(object.type);
  if (type->kind == TypeKind::Reference && type->element) type = underlying(type->element);
  ExprInfo result{.type = types_.unknown(), .assignable = object.assignable || type->is_unknown()};
  if (type->is_unknown()) return result;
  if (type->kind == TypeKind::String || type->kind == TypeKind::WString) {
    result.type = types_.elementary(type->kind == TypeKind::String ? "BYTE" : "WORD");  // CODESYS s[i]: a character code
    return result;
  }
  if (type->kind == TypeKind::Pointer) {
    result.type = type->element ? type->element : types_.unknown();  // pointer indexing (TwinCAT)
    return result;
  }
  if (type->kind != TypeKind::Array) {
    report(codes::kWrongIndexCount, fmt::format("'{}' is not an array (type {})", expression.child_by_field("object").text(), object.type->name),
           expression.range());
    return result;
  }
  if (!type->dimensions.empty() && indices.size() != type->dimensions.size()) {
    // a[i][j] on ARRAY[..,..] is a different shape: accept a prefix (array of arrays written flat).
    if (indices.size() > type->dimensions.size()) {
      report(codes::kWrongIndexCount,
             fmt::format("{} has {} dimension(s), {} index(es) given", type->name, type->dimensions.size(), indices.size()),
             expression.range());
      return result;
    }
    if (indices.size() < type->dimensions.size()) {
      report(codes::kWrongIndexCount,
             fmt::format("{} has {} dimension(s), {} index(es) given", type->name, type->dimensions.size(), indices.size()),
             expression.range());
      return result;
    }
  }
  for (size_t i = 0; i < indices.size() && i < type->dimensions.size(); ++i) {
    const ArrayDimension& dimension = type->dimensions[i];
    if (dimension.open || !dimension.known) continue;
    auto value = model_.constant_value(indices[i], &pou_);
    if (value && value->is_integer() && (value->integer < dimension.lower || value->integer > dimension.upper)) {
      report(codes::kIndexOutOfRange,
             fmt::format("index {} is outside the bounds {}..{}", int128_to_string(value->integer), dimension.lower,
                         dimension.upper),
             indices[i].range(), "valid indexes are the declared bounds, both included");
    }
  }
  result.type = type->element ? type->element : types_.unknown();
  return result;
}

ExprInfo BodyChecker::type_dereference(SyntaxNode expression, int depth) {
  SyntaxNode operand = expression.child_by_field("operand");
  // THIS^ and SUPER^: the instance itself and its base.
  if (operand && operand.kind() == "identifier" && (names_equal(operand.text(), "THIS") || names_equal(operand.text(), "SUPER"))) {
    const Symbol* block = &pou_;
    while (block && block->kind != SymbolKind::FunctionBlock && block->kind != SymbolKind::Class) block = block->owner;
    if (!block) {
      report(codes::kInvalidThisSuper, fmt::format("{}^ is only valid inside a function block", operand.text()),
             operand.range());
      return ExprInfo{.type = types_.unknown()};
    }
    if (names_equal(operand.text(), "SUPER")) {
      if (!block->base) {
        if (block->base_nodes.empty()) {
          report(codes::kInvalidThisSuper, fmt::format("SUPER^ in '{}', which extends nothing", block->name), operand.range());
        }
        return ExprInfo{.type = types_.unknown()};
      }
      return ExprInfo{.type = model_.type_of(block->base), .symbol = block->base, .assignable = true};
    }
    return ExprInfo{.type = model_.type_of(block), .symbol = block, .assignable = true};
  }
  ExprInfo inner = type_expression(operand, depth + 1);
  const Type* type = underlying(inner.type);
  if (type->is_unknown()) return ExprInfo{.type = types_.unknown(), .assignable = true};
  if (type->kind == TypeKind::Pointer || type->kind == TypeKind::Reference) {
    return ExprInfo{.type = type->element ? type->element : types_.unknown(), .assignable = true};
  }
  if (is_any_int_or_bit(type) && type->bits >= 32) {
    return ExprInfo{.type = types_.unknown(), .assignable = true};  // an address held in a DWORD/__XWORD
  }
  report(codes::kInvalidDereference, fmt::format("'^' needs a POINTER or REFERENCE, not {}", inner.type->name),
         expression.range());
  return ExprInfo{.type = types_.unknown()};
}

ExprInfo BodyChecker::type_unary(SyntaxNode expression, int depth) {
  ExprInfo operand = type_expression(expression.child_by_field("operand"), depth + 1);
  const std::string op = ast::operator_of(expression);
  ExprInfo result{.type = operand.type};
  if (op == "-" && operand.value && operand.untyped_literal) {
    // -5 is one literal: fold it so that it takes the smallest signed type.
    ConstValue value = *operand.value;
    if (value.kind == ConstValue::Kind::Integer || value.kind == ConstValue::Kind::Duration) value.integer = -value.integer;
    if (value.kind == ConstValue::Kind::Real) value.real = -value.real;
    result.value = value;
    result.untyped_literal = true;
    result.type = literal_type(value, false);
    return result;
  }
  return unary_result(op, operand, expression.range());
}

// NOT, unary - and + applied to a typed operand (also IL NOT and the N modifier).
ExprInfo BodyChecker::unary_result(std::string_view op, const ExprInfo& operand, TextRange range) {
  ExprInfo result{.type = operand.type};
  const Type* type = arithmetic_type(operand.type);
  if (type->is_unknown() || type->kind == TypeKind::Generic) return result;
  if (op == "NOT") {
    if (type->kind != TypeKind::Bool && !is_any_int_or_bit(type)) {
      report(codes::kInvalidOperand, fmt::format("NOT is not defined for {}", operand.type->name), range);
      result.type = types_.unknown();
    }
    if (operand.value && operand.value->kind == ConstValue::Kind::Bool) {
      result.value = ConstValue::of_bool(operand.value->integer == 0);
    }
  } else if (op == "-" || op == "+") {
    if (!is_numeric(type) && type->kind != TypeKind::Duration &&
        !(type->kind == TypeKind::Bit && model_.profile().bits_and_integers_mix)) {
      report(codes::kInvalidOperand, fmt::format("unary '{}' is not defined for {}", op, operand.type->name),
             range);
      result.type = types_.unknown();
    }
  }
  return result;
}

ExprInfo BodyChecker::type_binary(SyntaxNode expression, int depth) {
  SyntaxNode left_node = expression.child_by_field("left");
  SyntaxNode right_node = expression.child_by_field("right");
  ExprInfo left = type_expression(left_node, depth + 1);
  ExprInfo right = type_expression(right_node, depth + 1);
  const std::string op = ast::operator_of(expression);
  ExprInfo result{.type = types_.unknown()};
  // Fold literal-only arithmetic so that 2 * 1000 still counts as an untyped literal.
  if (left.value && right.value && left.untyped_literal && right.untyped_literal && !is_comparison(op)) {
    ConstEvaluator evaluator(nullptr);
    if (auto value = evaluator.evaluate(expression)) {
      result.value = value;
      result.untyped_literal = true;
      result.type = literal_type(*value, left.based_literal && right.based_literal);
      return result;
    }
  }
  return binary_result(op, left, right, right_node, expression.range());
}

// The type of `left op right` for typed operands (also IL ADD, GT, AND ...: `shown` is the
// operator as written there, for the messages).
ExprInfo BodyChecker::binary_result(std::string_view op, const ExprInfo& left, const ExprInfo& right,
                                   SyntaxNode right_node, TextRange range, std::string_view shown) {
  ExprInfo result{.type = types_.unknown()};
  const std::string_view name = shown.empty() ? op : shown;
  if ((op == "/" || op == "MOD") && right.value && right.value->is_number() && right.value->as_real() == 0) {
    report(codes::kDivisionByZero, fmt::format("division by zero ('{}' by a constant 0)", name), right_node.range());
  } else if ((op == "/" || op == "MOD") && !right.value) {
    auto constant = model_.constant_value(right_node, &pou_);
    if (constant && constant->is_number() && constant->as_real() == 0) {
      report(codes::kDivisionByZero, fmt::format("division by zero: '{}' is a constant 0", right_node.text()),
             right_node.range());
    }
  }
  const Type* a = arithmetic_type(left.type);
  const Type* b = arithmetic_type(right.type);
  const bool unknown = a->is_unknown() || b->is_unknown() || a->kind == TypeKind::Generic || b->kind == TypeKind::Generic;
  if (is_comparison(op)) {
    result.type = types_.elementary("BOOL");
    // Structures and arrays have no order and no '=' (OpenPCS S3028/S3030: LD s1 / GT s2).
    auto aggregate = [](const Type* t) {
      return t->kind == TypeKind::Struct || t->kind == TypeKind::Union || t->kind == TypeKind::Array;
    };
    if (!unknown && (aggregate(a) || aggregate(b))) {
      report(codes::kInvalidOperand, fmt::format("cannot compare {} with {}", left.type->name, right.type->name), range,
             "compare the members one by one");
      return result;
    }
    if (!unknown) {
      const bool comparable =
          (is_numeric(a) || a->kind == TypeKind::Bit) == (is_numeric(b) || b->kind == TypeKind::Bit) ||
          left.untyped_literal || right.untyped_literal;
      const bool strings = is_string_like(a) != is_string_like(b);
      if (!comparable || strings) {
        if (convertibility(left.type, right.type, model_.profile()) == Convertibility::Never &&
            convertibility(right.type, left.type, model_.profile()) == Convertibility::Never) {
          report(codes::kInvalidOperand,
                 fmt::format("cannot compare {} with {}", left.type->name, right.type->name), range);
        }
      }
    }
    return result;
  }
  if (is_logical(op)) {
    if (unknown) {
      result.type = a->kind == TypeKind::Bool || b->kind == TypeKind::Bool ? types_.elementary("BOOL") : types_.unknown();
      return result;
    }
    if (a->kind == TypeKind::Bool && b->kind == TypeKind::Bool) {
      result.type = a;
      return result;
    }
    const bool a_bits = is_any_int_or_bit(a), b_bits = is_any_int_or_bit(b);
    if (a_bits && b_bits) {
      result.type = left.untyped_literal ? b : (right.untyped_literal ? a : (a->bits >= b->bits ? a : b));
      return result;
    }
    if ((a->kind == TypeKind::Bool && b_bits && right.untyped_literal) || (b->kind == TypeKind::Bool && a_bits && left.untyped_literal)) {
      result.type = types_.elementary("BOOL");
      return result;
    }
    if ((a->kind == TypeKind::Bool && b_bits) || (b->kind == TypeKind::Bool && a_bits)) {
      result.type = a->kind == TypeKind::Bool ? b : a;  // CODESYS widens the BOOL; IEC rejects it
      if (model_.profile().bits_and_integers_mix) return result;
    }
    report(codes::kInvalidOperand,
           fmt::format("{} is not defined for {} and {}", name, left.type->name, right.type->name), range,
           "use BOOL operands, or bit strings/integers of matching width");
    result.type = types_.unknown();
    return result;
  }
  // Arithmetic: + - * / MOD **
  if (unknown) {
    result.type = left.untyped_literal ? b : a;
    return result;
  }
  const TypeKind ak = a->kind, bk = b->kind;
  auto is_time_point = [](TypeKind k) { return k == TypeKind::Date || k == TypeKind::TimeOfDay || k == TypeKind::DateTime; };
  if (ak == TypeKind::Duration || bk == TypeKind::Duration || is_time_point(ak) || is_time_point(bk)) {
    if (ak == TypeKind::Duration && bk == TypeKind::Duration && (op == "+" || op == "-")) {
      result.type = a->bits >= b->bits ? a : b;
    } else if (ak == TypeKind::Duration && is_numeric(b) && (op == "*" || op == "/")) {
      result.type = a;
    } else if (bk == TypeKind::Duration && is_numeric(a) && op == "*") {
      result.type = b;
    } else if (is_time_point(ak) && bk == TypeKind::Duration && (op == "+" || op == "-") &&
               (ak != TypeKind::Date || model_.profile().time_and_integers_mix)) {
      // IEC has no DATE +/- TIME (a DATE counts days; table 30 of the 2nd ed.; OpenPCS S3020).
      result.type = a;
    } else if (is_time_point(ak) && ak == bk && op == "-") {
      result.type = types_.elementary("TIME");
    } else if (model_.profile().time_and_integers_mix && (is_any_int_or_bit(a) || is_any_int_or_bit(b))) {
      result.type = ak == TypeKind::Duration || is_time_point(ak) ? a : b;  // TIME + 100 in CODESYS: ms
    } else if (ak == TypeKind::Duration && bk == TypeKind::Duration && op == "/") {
      result.type = types_.elementary("DINT");
    } else {
      report(codes::kInvalidOperand,
             fmt::format("'{}' is not defined for {} and {}", name, left.type->name, right.type->name), range);
    }
    return result;
  }
  if (ak == TypeKind::Pointer || bk == TypeKind::Pointer) {
    result.type = ak == TypeKind::Pointer ? a : b;  // CODESYS pointer arithmetic, in bytes
    return result;
  }
  if (op == "MOD" && (ak == TypeKind::Real || bk == TypeKind::Real)) {
    report(codes::kInvalidOperand, fmt::format("MOD needs integers, not {} and {}", left.type->name, right.type->name),
           range, "use a - TRUNC(a / b) * b for REAL");
    return result;
  }
  const bool a_num = is_numeric(a) || (ak == TypeKind::Bit && model_.profile().bits_and_integers_mix);
  const bool b_num = is_numeric(b) || (bk == TypeKind::Bit && model_.profile().bits_and_integers_mix);
  if (!a_num || !b_num) {
    const bool bits_and_numbers = (ak == TypeKind::Bit || bk == TypeKind::Bit) && !is_string_like(a) &&
                                  !is_string_like(b) && ak != TypeKind::Bool && bk != TypeKind::Bool;
    if (bits_and_numbers && !model_.profile().bit_string_arithmetic) {
      // IEC: bit strings are not numbers (OpenPCS S3035: LD BitMask / SUB 3 with a WORD).
      const Type* bits = ak == TypeKind::Bit ? left.type : right.type;
      report(codes::kInvalidOperand, fmt::format("'{}' is not defined for the bit string {}", name, bits->name), range,
             fmt::format("convert it to a number first: {}_TO_UINT() (or UDINT, ULINT)", arithmetic_type(bits)->name));
      result.type = ak == TypeKind::Bit ? a : b;
      return result;
    }
    if (bits_and_numbers) {
      result.type = ak == TypeKind::Bit ? a : b;  // a bit string with a number where they do not mix: one error at the assignment
      return result;
    }
    report(codes::kInvalidOperand,
           fmt::format("'{}' is not defined for {} and {}", name, left.type->name, right.type->name), range,
           ak == TypeKind::Bool || bk == TypeKind::Bool ? "BOOL is not a number: use BOOL_TO_INT()" : std::string());
    return result;
  }
  if (left.untyped_literal && !right.untyped_literal) {
    result.type = (bk == TypeKind::Real || !(ak == TypeKind::Real)) ? b : common_numeric_type(a, b, types_);
  } else if (right.untyped_literal && !left.untyped_literal) {
    result.type = (ak == TypeKind::Real || !(bk == TypeKind::Real)) ? a : common_numeric_type(a, b, types_);
  } else {
    const Type* common = common_numeric_type(a, b, types_);
    result.type = common ? common : a;
  }
  if (op == "**") result.type = types_.elementary(a->bits > 32 || b->bits > 32 ? "LREAL" : "REAL");
  return result;
}

}  // namespace rung::check
