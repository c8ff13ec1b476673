// Calls: which POU a call names, its arguments (formal name := value, informal by position,
// outputs with =>) against the callee's VAR_INPUT / VAR_OUTPUT / VAR_IN_OUT, and the result type
// (generic standard functions bind their result to the arguments: ADD(INT, INT) is INT).
#include <fmt/format.h>

#include "checker/semantic/body_checker.hpp"
#include "checker/semantic/builtins.hpp"
#include "checker/semantic/type_size.hpp"
#include "parser/diagnostic_codes.hpp"

namespace rung::check {
namespace {

struct Parameter {
  const Symbol* symbol;
  ast::VarSection section;
};

// Inputs, outputs and in-outs in declaration order, base classes first.
std::vector<Parameter> parameters_of(const Symbol* callee) {
  std::vector<const Symbol*> chain;
  for (const Symbol* s = callee; s && chain.size() < 32; s = s->base) chain.push_back(s);
  std::vector<Parameter> parameters;
  for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
    for (const Symbol* member : (*it)->ordered) {
      if (member->kind != SymbolKind::Variable) continue;
      if (member->section == ast::VarSection::Input || member->section == ast::VarSection::Output ||
          member->section == ast::VarSection::InOut) {
        parameters.push_back({member, member->section});
      }
    }
  }
  return parameters;
}

bool is_en_eno(std::string_view name) { return names_equal(name, "EN") || names_equal(name, "ENO"); }

const Parameter* find_parameter(const std::vector<Parameter>& parameters, std::string_view name) {
  for (const auto& parameter : parameters) {
    if (names_equal(parameter.symbol->name, name)) return &parameter;
  }
  return nullptr;
}

}  // namespace

ExprInfo BodyChecker::type_call(SyntaxNode call, int depth) {
  SyntaxNode function = call.child_by_field("function");
  SyntaxNode arguments = call.child_by_field("arguments");
  ExprInfo unknown{.type = types_.unknown()};
  if (!function) return unknown;
  auto type_arguments_only = [&]() {
    for (const CallArgument& argument : call_arguments(arguments)) type_expression(argument.value, depth + 1);
  };
  if (function.kind() == "identifier") {
    const std::string_view name = function.text();
    const Symbol* callee = model_.lookup(&pou_, name);
    if (!callee) {
      if (const Builtin* builtin = find_builtin(name); builtin && builtin->is_callable) {
        type_arguments_only();
        return ExprInfo{.type = builtin->value_type ? types_.elementary(builtin->value_type) : types_.unknown()};
      }
      type_arguments_only();
      std::vector<std::string_view> candidates = model_.visible_names(&pou_);
      const std::string_view suggestion = closest_name(name, candidates);
      report(codes::kUnknownLibraryName, fmt::format("unknown function or function block '{}'", name), function.range(),
             suggestion.empty()
                 ? "declare it, or if it comes from a vendor library, add that library's stubs (the 'libraries' list under [project] in rung.toml)"
                 : fmt::format("did you mean '{}'?", suggestion));
      return unknown;
    }
    if (callee->has(kObsolete)) info_for_symbol(callee, function);
    switch (callee->kind) {
      case SymbolKind::Function:
      case SymbolKind::Method:
      case SymbolKind::Action:
      case SymbolKind::Program:
        return check_call_arguments(call, callee, false, depth);
      case SymbolKind::FunctionBlock:
      case SymbolKind::Class:
        type_arguments_only();
        report(codes::kNotCallable,
               fmt::format("'{}' is a function block type; call an instance of it", callee->name), function.range(),
               fmt::format("declare an instance (e.g. fb{} : {};) and call that", callee->name, callee->name));
        return unknown;
      case SymbolKind::Variable: {
        const Type* type = underlying(model_.type_of(callee));
        if (type->kind == TypeKind::Reference && type->element) type = underlying(type->element);
        if (type->kind == TypeKind::Pou && type->declaration) {
          return check_call_arguments(call, type->declaration, true, depth);
        }
        if (!type->is_unknown() && type->kind != TypeKind::Pointer && type->kind != TypeKind::Generic) {
          report(codes::kNotCallable, fmt::format("'{}' is a variable of type {}, not something to call", name, type->name),
                 function.range());
        }
        type_arguments_only();
        return unknown;
      }
      default:
        type_arguments_only();
        return unknown;
    }
  }
  // obj.Method(), fbInstance.Action(), GVL.fb(), Library.F(), a[i](), p^()
  ExprInfo target = type_expression(function, depth + 1);
  if (target.symbol) {
    const Symbol* callee = target.symbol;
    if (callee->kind == SymbolKind::Method || callee->kind == SymbolKind::Action || callee->kind == SymbolKind::Function ||
        callee->kind == SymbolKind::Program) {
      return check_call_arguments(call, callee, false, depth);
    }
  }
  const Type* type = underlying(target.type);
  if (type->kind == TypeKind::Reference && type->element) type = underlying(type->element);
  if (type->kind == TypeKind::Pou && type->declaration && !target.names_type) {
    return check_call_arguments(call, type->declaration, true, depth);
  }
  type_arguments_only();
  return unknown;
}

ExprInfo BodyChecker::check_call_arguments(SyntaxNode call, const Symbol* callee, bool instance_call, int depth) {
  return check_arguments(callee, instance_call, call_arguments(call.child_by_field("arguments")), call, depth);
}

std::vector<CallArgument> call_arguments(SyntaxNode arguments) {
  std::vector<CallArgument> result;
  if (!arguments) return result;
  bool after_bar = false;
  for (uint32_t i = 0; i < arguments.child_count(); ++i) {
    SyntaxNode child = arguments.child(i);
    if (!child.is_named()) {
      after_bar = after_bar || child.text() == "|";
      continue;
    }
    const bool output = child.kind() == "output_argument";
    if (!output && child.kind() != "argument") continue;
    CallArgument argument{.node = child,
                          .name = child.child_by_field("name"),
                          .value = child.child_by_field(output ? "target" : "value"),
                          .output = output};
    // OpenPCS: after '|' come the outputs, written `actual := formal` (003.md L4518-4523).
    if (after_bar && !output && argument.name && argument.value) {
      std::swap(argument.name, argument.value);
      argument.output = true;
    }
    result.push_back(argument);
  }
  return result;
}

ExprInfo BodyChecker::check_arguments(const Symbol* callee, bool instance_call, const std::vector<CallArgument>& arguments,
                                      SyntaxNode call, int depth) {
  const std::vector<Parameter> parameters = parameters_of(callee);
  const bool is_function = callee->kind == SymbolKind::Function || callee->kind == SymbolKind::Method;
  ExprInfo result{.type = types_.void_type()};
  if (is_function) result.type = callee->result_type ? callee->result_type : types_.unknown();
  if (callee->has(kLibrary) && callee->kind == SymbolKind::Function && !callee->result_type) result.type = types_.unknown();

  std::vector<ExprInfo> bound;  // arguments given to parameters of the result's generic type
  std::vector<SyntaxNode> bound_where;
  std::vector<const Parameter*> given;
  size_t positional = 0;
  bool extensible_seen = false;
  std::vector<const Parameter*> inputs;
  for (const auto& parameter : parameters) {
    if (parameter.section == ast::VarSection::Input || parameter.section == ast::VarSection::InOut) inputs.push_back(&parameter);
    if (parameter.symbol->has(kExtensible)) extensible_seen = true;
  }
  const bool library_function = callee->has(kLibrary) && callee->kind == SymbolKind::Function;
  for (const CallArgument& argument : arguments) {
    const bool output = argument.output;
    SyntaxNode name = argument.name;
    SyntaxNode value = argument.value;
    ExprInfo value_info = argument.typed        ? *argument.typed
                          : value ? type_expression(value, depth + 1)
                                  : ExprInfo{.type = types_.unknown()};
    const Parameter* parameter = nullptr;
    if (name) {
      if (is_en_eno(name.text())) continue;
      parameter = find_parameter(parameters, name.text());
      if (!parameter) {
        // Standard functions: vendors name the parameters differently (IEC LEFT(IN, L), CODESYS
        // and TwinCAT LEFT(STR, SIZE)); extensible ones take IN3, IN4 ... beyond IN2.
        if (library_function) continue;
        std::vector<std::string_view> names;
        for (const auto& p : parameters) names.push_back(p.symbol->name);
        const std::string_view suggestion = closest_name(name.text(), names);
        report(codes::kUnknownParameter, fmt::format("'{}' has no parameter '{}'", callee->name, name.text()),
               name.range(), suggestion.empty() ? std::string() : fmt::format("did you mean '{}'?", suggestion));
        continue;
      }
      for (const Parameter* previous : given) {
        if (previous == parameter) {
          report(codes::kDuplicateParameter, fmt::format("parameter '{}' is given twice", name.text()), name.range());
        }
      }
      given.push_back(parameter);
      if (output && parameter->section != ast::VarSection::Output) {
        report(codes::kWrongArgumentDirection,
               fmt::format("'{}' is an input; use '{} := value'", parameter->symbol->name, parameter->symbol->name),
               argument.node.range());
        continue;
      }
      if (!output && parameter->section == ast::VarSection::Output) {
        report(codes::kWrongArgumentDirection,
               fmt::format("'{}' is an output; use '{} => variable'", parameter->symbol->name, parameter->symbol->name),
               argument.node.range());
        continue;
      }
    } else {
      if (positional < inputs.size()) {
        parameter = inputs[positional];
      } else if (!extensible_seen && !inputs.empty() && !instance_call) {
        report(codes::kTooManyArguments,
               fmt::format("'{}' takes {} argument(s), more are given", callee->name, inputs.size()), argument.node.range());
      }
      ++positional;
      if (parameter) given.push_back(parameter);
    }
    if (!parameter || !value) continue;
    const Type* parameter_type = model_.type_of(parameter->symbol);
    if (parameter->section == ast::VarSection::InOut && !value_info.assignable && !value_info.value &&
        !value_info.type->is_unknown()) {
      report(codes::kInOutNotAssignable,
             fmt::format("'{}' is VAR_IN_OUT: pass a variable, not an expression", parameter->symbol->name),
             value.range());
    } else if (parameter->section == ast::VarSection::InOut && value_info.value && value_info.untyped_literal) {
      report(codes::kInOutNotAssignable,
             fmt::format("'{}' is VAR_IN_OUT: pass a variable, not a constant", parameter->symbol->name), value.range());
    }
    if (output) {
      // The output's value flows into the target variable.
      if (value_info.assignable || value_info.type->is_unknown()) {
        check_conversion(ExprInfo{.type = parameter_type}, value_info.type, value);
      }
      continue;
    }
    check_conversion(value_info, parameter_type, value);
    if (callee->result_type && parameter_type == callee->result_type && parameter_type->kind == TypeKind::Generic) {
      bound.push_back(value_info);
      bound_where.push_back(value);
    }
  }
  // A VAR_IN_OUT is a reference: every call must connect it (OpenPCS S5033; CODESYS, TwinCAT).
  if (!callee->has(kLibrary)) {
    for (const Parameter& parameter : parameters) {
      if (parameter.section != ast::VarSection::InOut) continue;
      if (std::find(given.begin(), given.end(), &parameter) != given.end()) continue;
      report(codes::kMissingParameter,
             fmt::format("VAR_IN_OUT '{}' of '{}' is not connected", parameter.symbol->name, callee->name), call.range(),
             fmt::format("pass a variable: {} := ...", parameter.symbol->name));
    }
  }
  if (is_function && result.type->kind == TypeKind::Generic) {
    if (!model_.profile().generic_arguments_widen) check_one_generic_type(callee, bound, bound_where);
    result.type = bind_generic_result(callee, bound);
  }
  return result;
}

void BodyChecker::check_one_generic_type(const Symbol* callee, const std::vector<ExprInfo>& arguments,
                                         const std::vector<SyntaxNode>& where) {
  // Strict IEC (OpenPCS): all arguments of one generic type T have the same type, and an untyped
  // constant adapts to it only within its kind: 1 becomes any integer or bit string, not REAL
  // (S5027: LD 1 / MAX rReal).
  const Type* typed = nullptr;
  for (const ExprInfo& argument : arguments) {
    if (!argument.untyped_literal && !arithmetic_type(argument.type)->is_unknown()) {
      typed = argument.type;
      break;
    }
  }
  if (!typed) return;
  for (size_t i = 0; i < arguments.size(); ++i) {
    const ExprInfo& argument = arguments[i];
    const Type* type = arithmetic_type(argument.type);
    if (type->is_unknown() || type->kind == TypeKind::Generic) continue;
    const bool fits = argument.untyped_literal
                          ? (is_any_int_or_bit(type) && is_any_int_or_bit(arithmetic_type(typed))) ||
                                (type->kind == TypeKind::Real && arithmetic_type(typed)->kind == TypeKind::Real) ||
                                convertibility(argument.type, typed, model_.profile()) == Convertibility::Same
                          : convertibility(argument.type, typed, model_.profile()) == Convertibility::Same;
    if (fits) continue;
    report(codes::kTypeMismatch,
           fmt::format("{} takes arguments of one type: {} and {} differ", callee->name, typed->name, argument.type->name),
           where[i].range(), fmt::format("convert explicitly, e.g. {}_TO_{}()", argument.type->name, typed->name));
    return;
  }
}

const Type* BodyChecker::bind_generic_result(const Symbol* callee, const std::vector<ExprInfo>& arguments) {
  (void)callee;
  const Type* typed = nullptr;
  const Type* literal = nullptr;
  for (const ExprInfo& argument : arguments) {
    const Type* type = arithmetic_type(argument.type);
    if (type->is_unknown()) return types_.unknown();
    if (argument.untyped_literal) {
      literal = literal ? (common_numeric_type(literal, type, types_) ? common_numeric_type(literal, type, types_) : literal) : type;
      continue;
    }
    if (!typed) {
      typed = argument.type;
    } else if (is_numeric(typed) && is_numeric(type)) {
      const Type* common = common_numeric_type(typed, type, types_);
      typed = common ? common : typed;
    }
  }
  if (typed) return typed;
  if (literal) return literal;
  return types_.unknown();
}

}  // namespace rung::check
