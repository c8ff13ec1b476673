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

std::string convert_help(const Type* from, const Type* to) {
  const std::string function = conversion_function(from, to);
  return function.empty() ? std::string() : fmt::format("convert explicitly, e.g. {}()", function);
}

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

bool is_en_eno(std::string_view name) {
  return names_equal(name, "EN") || names_equal(name, "ENO");
}

// The parameter a formal argument names; for library functions and blocks also by the name
// another dialect gives it (the stubs' rung.alias: CODESYS's LEFT(STR, SIZE) is IEC's LEFT(IN, L),
// CODESYS's CTU(RESET := ...) is IEC's and OpenPLC's CTU(R := ...)).
const Parameter* find_parameter(const std::vector<Parameter>& parameters, std::string_view name, bool by_alias) {
  for (const auto& parameter : parameters) {
    if (names_equal(parameter.symbol->name, name)) return &parameter;
  }
  if (!by_alias) return nullptr;
  for (const auto& parameter : parameters) {
    const Attribute* alias = parameter.symbol->attribute("rung.alias");
    if (alias && names_equal(alias->value, name)) return &parameter;
  }
  return nullptr;
}

// OpenPCS takes the length and position of LEFT, RIGHT and MID as UINT (C10035).
bool is_string_position(const Symbol* callee, const Parameter& parameter) {
  const std::string_view name = parameter.symbol->name;
  if (names_equal(callee->name, "LEFT") || names_equal(callee->name, "RIGHT")) return names_equal(name, "L");
  if (names_equal(callee->name, "MID")) return names_equal(name, "L") || names_equal(name, "P");
  return false;
}

// A FUNCTION keeps nothing between calls, so a call must give every input that has no initial
// value (CODESYS textbook L3210-3216, OpenPCS L4548); function block calls may leave inputs out,
// they keep their last values. EN is optional everywhere. A formal call also binds every
// additional output with => (MP300 manual L11195-11203); an informal call cannot name them.
// Stubs' outputs are rung's reconstruction of each vendor's, so only user functions' are required.
void report_missing_parameters(BodyChecker& checker, const Symbol* callee, const std::vector<Parameter>& parameters,
                               const std::vector<const Parameter*>& given, bool formal, SyntaxNode call) {
  std::vector<std::string_view> inputs, outputs;
  for (const Parameter& parameter : parameters) {
    if (is_en_eno(parameter.symbol->name)) continue;
    if (std::find(given.begin(), given.end(), &parameter) != given.end()) continue;
    if (parameter.section == ast::VarSection::Input && !parameter.symbol->has(kHasInitializer)) {
      inputs.push_back(parameter.symbol->name);
    } else if (parameter.section == ast::VarSection::Output && formal && !callee->has(kLibrary)) {
      outputs.push_back(parameter.symbol->name);
    }
  }
  auto quoted = [](const std::vector<std::string_view>& names) {
    std::string text;
    for (std::string_view name : names) text += fmt::format("{}'{}'", text.empty() ? "" : ", ", name);
    return text;
  };
  if (!inputs.empty()) {
    checker.report(codes::kMissingParameter,
                   fmt::format("the call of FUNCTION '{}' does not give the input{} {}", callee->name,
                               inputs.size() > 1 ? "s" : "", quoted(inputs)),
                   call.range(),
                   formal ? fmt::format("add {} := ... (only function block calls may leave inputs out)", inputs[0])
                          : "give every input, in declaration order (only function block calls may leave inputs out)");
  }
  if (!outputs.empty()) {
    checker.report(codes::kMissingParameter,
                   fmt::format("the call of FUNCTION '{}' does not bind the output{} {}", callee->name,
                               outputs.size() > 1 ? "s" : "", quoted(outputs)),
                   call.range(), fmt::format("bind it to a variable: {} => ...", outputs[0]));
  }
}

// OpenPCS: formal arguments in the order of the declaration (S3047); inputs and outputs each
// keep their own order, since OpenPCS writes the outputs after '|'.
// Parameters are compared by their place in one parameters_of() vector.
class ArgumentOrder {
 public:
  void check(BodyChecker& checker, const Symbol* callee, const Parameter& parameter, SyntaxNode name) {
    const Parameter*& last = parameter.section == ast::VarSection::Output ? last_output_ : last_input_;
    if (last && &parameter < last && !reported_) {
      reported_ = true;
      checker.report(codes::kArgumentOrder,
                     fmt::format("'{}' is declared before '{}' in '{}': give the formal arguments in that order",
                                 parameter.symbol->name, last->symbol->name, callee->name),
                     name.range(),
                     fmt::format("write {} before {} (OpenPCS passes the arguments in the order written)",
                                 parameter.symbol->name, last->symbol->name));
    }
    if (!last || &parameter > last) last = &parameter;
  }

 private:
  const Parameter* last_input_ = nullptr;
  const Parameter* last_output_ = nullptr;
  bool reported_ = false;
};

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
             suggestion.empty() ? "declare it, or if it comes from a vendor library, add that library's stubs (the "
                                  "'libraries' list under [project] in rung.toml)"
                                : fmt::format("did you mean '{}'?", suggestion));
      return unknown;
    }
    if (callee->has(kObsolete)) info_for_symbol(callee, function);
    switch (callee->kind) {
      case SymbolKind::Function:
      case SymbolKind::Method:
      case SymbolKind::Action:
      case SymbolKind::Program: return check_call_arguments(call, callee, false, depth);
      case SymbolKind::FunctionBlock:
      case SymbolKind::Class:
        report(codes::kNotCallable, fmt::format("'{}' is a function block type; call an instance of it", callee->name),
               function.range(),
               fmt::format("declare an instance (e.g. fb{} : {};) and call that", callee->name, callee->name));
        // The arguments are still checked against the block's parameters, as the instance call
        // the author meant would be.
        check_call_arguments(call, callee, true, depth);
        return unknown;
      case SymbolKind::Variable: {
        const Type* type = underlying(model_.type_of(callee));
        if (type->kind == TypeKind::Reference && type->element) type = underlying(type->element);
        if (type->kind == TypeKind::Pou && type->declaration) {
          return check_call_arguments(call, type->declaration, true, depth);
        }
        if (!type->is_unknown() && type->kind != TypeKind::Pointer && type->kind != TypeKind::Generic) {
          report(codes::kNotCallable,
                 fmt::format("'{}' is a variable of type {}, not something to call", name, type->name),
                 function.range());
        }
        type_arguments_only();
        return unknown;
      }
      default: type_arguments_only(); return unknown;
    }
  }
  // obj.Method(), fbInstance.Action(), GVL.fb(), Library.F(), a[i](), p^()
  ExprInfo target = type_expression(function, depth + 1);
  if (target.symbol) {
    const Symbol* callee = target.symbol;
    if (callee->kind == SymbolKind::Method || callee->kind == SymbolKind::Action ||
        callee->kind == SymbolKind::Function || callee->kind == SymbolKind::Program) {
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
  arguments.for_each_child([&](SyntaxNode child) {
    if (!child.is_named()) {
      after_bar = after_bar || child.text() == "|";
      return;
    }
    const bool output = child.kind() == "output_argument";
    if (!output && child.kind() != "argument") return;
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
  });
  return result;
}

ExprInfo BodyChecker::check_arguments(const Symbol* callee, bool instance_call,
                                      const std::vector<CallArgument>& arguments, SyntaxNode call, int depth) {
  if (callee->kind == SymbolKind::Program && pou_.kind == SymbolKind::Function) {
    // A function keeps no state and may run any number of times per cycle; a program is one
    // instance with state (AK800 manual L2726, IEC 61131-3 table of POU calls).
    SyntaxNode name = call.child_by_field("function");
    report(codes::kInvalidCallTarget,
           fmt::format("FUNCTION '{}' cannot call the PROGRAM '{}'", pou_.name, callee->name),
           (name ? name : call).range(), "call the program from another program or from a task");
  }
  const std::vector<Parameter> parameters = parameters_of(callee);
  const bool is_function = callee->kind == SymbolKind::Function || callee->kind == SymbolKind::Method;
  ExprInfo result{.type = types_.void_type()};
  if (is_function) result.type = callee->result_type ? callee->result_type : types_.unknown();
  if (callee->has(kLibrary) && callee->kind == SymbolKind::Function && !callee->result_type)
    result.type = types_.unknown();

  std::vector<ExprInfo> bound;  // arguments given to parameters of the result's generic type
  std::vector<SyntaxNode> bound_where;
  std::vector<const Parameter*> given;
  size_t positional = 0;
  bool extensible_seen = false;
  std::vector<const Parameter*> inputs;  // what informal arguments bind to, in order; EN is never positional
  for (const auto& parameter : parameters) {
    if ((parameter.section == ast::VarSection::Input || parameter.section == ast::VarSection::InOut) &&
        !is_en_eno(parameter.symbol->name)) {
      inputs.push_back(&parameter);
    }
    if (parameter.symbol->has(kExtensible)) extensible_seen = true;
  }
  const bool library_function = callee->has(kLibrary) && callee->kind == SymbolKind::Function;
  const Profile& profile = model_.profile();
  bool formal = false;
  bool vendor_names = false;  // a standard function's argument under a name the stub does not know
  ArgumentOrder order;
  for (const CallArgument& argument : arguments) {
    const bool output = argument.output;
    SyntaxNode name = argument.name;
    SyntaxNode value = argument.value;
    ExprInfo value_info = argument.typed ? *argument.typed
                          : value        ? type_expression(value, depth + 1)
                                         : ExprInfo{.type = types_.unknown()};
    const Parameter* parameter = nullptr;
    if (name) {
      formal = true;
      if (is_en_eno(name.text())) continue;
      parameter = find_parameter(parameters, name.text(), callee->has(kLibrary));
      if (!parameter) {
        // Standard functions: vendors name the parameters differently (IEC LEFT(IN, L), CODESYS
        // and TwinCAT LEFT(STR, SIZE)); extensible ones take IN3, IN4 ... beyond IN2.
        if (library_function) {
          vendor_names = true;
          continue;
        }
        std::vector<std::string_view> names;
        names.reserve(parameters.size());
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
      if (profile.formal_arguments_in_order) order.check(*this, callee, *parameter, name);
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
               fmt::format("'{}' takes {} argument(s), more are given", callee->name, inputs.size()),
               argument.node.range());
      }
      ++positional;
      if (parameter) given.push_back(parameter);
    }
    if (!parameter || !value) continue;
    const Type* parameter_type = model_.type_of(parameter->symbol);
    if (profile.string_positions_are_uint && library_function && is_string_position(callee, *parameter)) {
      parameter_type = types_.elementary("UINT");
    }
    // VAR_IN_OUT CONSTANT is passed by reference but read only: CODESYS and TwinCAT accept
    // constants and expressions for it, and strings of any length.
    const bool constant_in_out = parameter->section == ast::VarSection::InOut && parameter->symbol->has(kConstant);
    if (constant_in_out) {
      const Type* from = underlying(value_info.type);
      const Type* to = underlying(parameter_type);
      if (is_string_like(from) && is_string_like(to) && from->kind == to->kind) continue;
    } else if (parameter->section == ast::VarSection::InOut && !value_info.assignable && !value_info.value &&
               !value_info.type->is_unknown()) {
      report(codes::kInOutNotAssignable,
             fmt::format("'{}' is VAR_IN_OUT: pass a variable, not an expression", parameter->symbol->name),
             value.range());
    } else if (parameter->section == ast::VarSection::InOut && value_info.value && value_info.untyped_literal) {
      report(codes::kInOutNotAssignable,
             fmt::format("'{}' is VAR_IN_OUT: pass a variable, not a constant", parameter->symbol->name),
             value.range());
    }
    if (output) {
      // The output's value flows into the target variable.
      if (value_info.assignable || value_info.type->is_unknown()) {
        check_conversion(ExprInfo{.type = parameter_type, .symbol = parameter->symbol}, value_info.type, value);
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
             fmt::format("VAR_IN_OUT '{}' of '{}' is not connected", parameter.symbol->name, callee->name),
             call.range(), fmt::format("pass a variable: {} := ...", parameter.symbol->name));
    }
  }
  if (callee->kind == SymbolKind::Function && !instance_call && !vendor_names &&
      !callee->attribute("rung.interface_assumed")) {
    report_missing_parameters(*this, callee, parameters, given, formal, call);
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
    report(
        codes::kTypeMismatch,
        fmt::format("{} takes arguments of one type: {} and {} differ", callee->name, typed->name, argument.type->name),
        where[i].range(), convert_help(argument.type, typed));
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
      literal =
          literal ? (common_numeric_type(literal, type, types_) ? common_numeric_type(literal, type, types_) : literal)
                  : type;
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
