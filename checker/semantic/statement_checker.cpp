// Statements: assignments and their targets, conditions, CASE labels, FOR loops, EXIT/CONTINUE,
// unreachable code, jumps.
#include <fmt/format.h>

#include <map>

#include "checker/constant/const_eval.hpp"
#include "checker/semantic/body_checker.hpp"
#include "checker/semantic/il_checker.hpp"
#include "checker/semantic/sfc_checker.hpp"
#include "parser/diagnostic_codes.hpp"

namespace rung::check {
namespace {

// A STRING(n) variable stored in a shorter STRING(m): the rest is cut off at run time (OpenPCS
// warning S3048, decided from the declarations). Only values whose length is declared: variables,
// their members and elements, constants; not the results of generic string functions, whose
// length rung does not track.
void check_string_length(BodyChecker& checker, const ExprInfo& value, const Type* to, SyntaxNode where) {
  const Type* from = underlying(value.type);
  if (from->kind == TypeKind::Reference && from->element) from = underlying(from->element);
  if (!is_string_like(from) || from->kind != to->kind || from->length <= to->length || to->length == 0) return;
  const bool declared = value.assignable || (value.symbol && value.symbol->kind == SymbolKind::Variable);
  if (!declared || value.untyped_literal) return;
  checker.report(codes::kStringTooLong,
                 fmt::format("{} is stored in {}: up to {} characters may be cut off", value.type->name, to->name,
                             from->length - to->length),
                 where.range(),
                 fmt::format("declare the target {}({}) or cut the text explicitly with LEFT()",
                             to->kind == TypeKind::WString ? "WSTRING" : "STRING", from->length));
}

}  // namespace

BodyChecker::BodyChecker(const ProjectModel& model, const Symbol& pou, std::vector<Diagnostic>& out)
    : model_(model), pou_(pou), out_(out), types_(model.types()) {}

void BodyChecker::report(std::string_view code, std::string message, TextRange range, std::string help,
                         std::vector<DiagnosticLabel> labels) {
  out_.push_back(make_diagnostic(code, std::move(message), range, std::move(help), std::move(labels)));
}

void BodyChecker::check() {
  if (pou_.node.kind() == "source_file") {
    // A snippet's statements (see Collector::add_snippet): possibly several runs of them.
    for (uint32_t i = 0; i < pou_.node.named_child_count(); ++i) {
      SyntaxNode child = pou_.node.named_child(i);
      if (child.kind() == "statement_list" || child.kind() == "il_body" || child.kind() == "sfc_network") {
        check_body(child);
      }
    }
    return;
  }
  check_body(pou_.node.child_by_field("body"));
}

void BodyChecker::check_body(SyntaxNode body) {
  if (!body) return;
  if (body.kind() == "sfc_network") {
    for (uint32_t i = 0; i < body.named_child_count(); ++i) {
      SyntaxNode child = body.named_child(i);
      if (SyntaxNode name = child.child_by_field("name")) sfc_names_.insert(upper_name(name.text()));
    }
    // Transition conditions and action bodies of the network.
    for (uint32_t i = 0; i < body.named_child_count(); ++i) {
      SyntaxNode child = body.named_child(i);
      if (child.kind() == "sfc_transition") {
        // IEC transitions may be written ":= 1;" (MatIEC/Beremiz output): a BIT literal is a BOOL.
        SyntaxNode condition = child.child_by_field("condition");
        auto value = condition ? literal_value(condition) : std::nullopt;
        const bool bit_literal = value && value->is_integer() && (value->integer == 0 || value->integer == 1);
        if (condition && !bit_literal) check_condition(condition);
        if (SyntaxNode code = child.child_by_field("body"); code && code.kind() == "il_body") {
          IlChecker(*this, model_, pou_).check(code, /*transition=*/true);
        }
      } else if (child.kind() == "sfc_action_block") {
        // A named action block is a member of the POU and gets its own BodyChecker (check_source
        // visits every member): checking it here too would report each finding twice.
        const SyntaxNode name = child.child_by_field("name");
        const Symbol* member = name ? pou_.own_member(name.text()) : nullptr;
        if (member && member->node == child) continue;
        if (SyntaxNode statements = child.child_by_field("body"); statements && statements.kind() == "statement_list") {
          collect_labels(statements);
          check_statement_list(statements);
        } else if (statements && statements.kind() == "il_body") {
          IlChecker(*this, model_, pou_).check(statements);
        }
      }
    }
    check_sfc_network(*this, model_, pou_, body);
    return;
  }
  if (body.kind() == "il_body") {
    IlChecker(*this, model_, pou_).check(body, /*transition=*/pou_.kind == SymbolKind::Transition);
    return;
  }
  if (body.kind() != "statement_list") return;
  collect_labels(body);
  check_statement_list(body);
}

void BodyChecker::collect_labels(SyntaxNode list) {
  std::vector<SyntaxNode> stack{list};
  std::map<std::string, SyntaxNode> seen;
  while (!stack.empty()) {
    SyntaxNode node = stack.back();
    stack.pop_back();
    for (uint32_t i = 0; i < node.named_child_count(); ++i) {
      SyntaxNode child = node.named_child(i);
      if (child.kind() == "label") {
        SyntaxNode name = child.child_by_field("name");
        if (!name) continue;
        const std::string key = upper_name(name.text());
        auto [it, inserted] = seen.emplace(key, name);
        if (!inserted) {
          report(codes::kDuplicateLabel, fmt::format("label '{}' is declared twice", name.text()), name.range(), {},
                 {{it->second.range(), "first declared here"}});
        }
        labels_.insert(key);
      } else if (child.kind().ends_with("_statement") || child.kind() == "statement_list" ||
                 child.kind().ends_with("_clause") || child.kind() == "case_element") {
        stack.push_back(child);
      }
    }
  }
}

void BodyChecker::check_statement_list(SyntaxNode list) {
  if (!list) return;
  for (SyntaxNode statement : ast::statements(list)) check_statement(statement);
  check_unreachable(list);
}

void BodyChecker::check_unreachable(SyntaxNode list) {
  const std::vector<SyntaxNode> statements = ast::statements(list);
  for (size_t i = 0; i + 1 < statements.size(); ++i) {
    const ast::StatementKind kind = ast::statement_kind(statements[i]);
    const bool jumps_away = kind == ast::StatementKind::Exit || kind == ast::StatementKind::Continue ||
                            kind == ast::StatementKind::Jump ||
                            (kind == ast::StatementKind::Return && !statements[i].child_by_field("condition"));
    if (!jumps_away) continue;
    SyntaxNode next = statements[i + 1];
    const ast::StatementKind next_kind = ast::statement_kind(next);
    if (next_kind == ast::StatementKind::Label || next_kind == ast::StatementKind::Empty) continue;
    report(codes::kUnreachableCode,
           fmt::format("this statement is never executed: the {} before it always leaves", statements[i].child(0).text()),
           next.range(), "remove it, or make the jump conditional");
    return;
  }
}

void BodyChecker::check_statement(SyntaxNode statement) {
  if (statement.is_error() || statement.has_error()) {
    // Broken statements: still look at the parts that parsed, but no structural checks.
    if (statement.is_error()) return;
  }
  if (statement.kind() == "sfc_step_macro") {
    report_step_macro_in_st(*this, statement);
    return;
  }
  switch (ast::statement_kind(statement)) {
    case ast::StatementKind::Assignment:
      check_assignment(statement);
      break;
    case ast::StatementKind::Call:
      type_expression(statement.named_child(0), 0);
      break;
    case ast::StatementKind::If: {
      check_condition(statement.child_by_field("condition"));
      check_statement_list(statement.child_by_field("body"));
      for (uint32_t i = 0; i < statement.named_child_count(); ++i) {
        SyntaxNode clause = statement.named_child(i);
        if (clause.kind() == "elsif_clause") {
          check_condition(clause.child_by_field("condition"));
          check_statement_list(clause.child_by_field("body"));
        } else if (clause.kind() == "else_clause") {
          check_statement_list(clause.child_by_field("body"));
        }
      }
      break;
    }
    case ast::StatementKind::Case:
      check_case(statement);
      break;
    case ast::StatementKind::For:
      check_for(statement);
      break;
    case ast::StatementKind::While:
    case ast::StatementKind::Repeat:
      check_condition(statement.child_by_field("condition"));
      ++loop_depth_;
      check_statement_list(statement.child_by_field("body"));
      --loop_depth_;
      break;
    case ast::StatementKind::Exit:
    case ast::StatementKind::Continue:
      if (loop_depth_ == 0) {
        report(codes::kExitOutsideLoop,
               fmt::format("{} outside a loop", upper_name(statement.child(0).text())), statement.range(),
               "EXIT and CONTINUE leave the innermost FOR, WHILE or REPEAT; use RETURN to leave the POU");
      }
      break;
    case ast::StatementKind::Return:
      if (SyntaxNode condition = statement.child_by_field("condition")) check_condition(condition);
      break;
    case ast::StatementKind::Jump: {
      SyntaxNode label = statement.child_by_field("label");
      if (label && !labels_.contains(upper_name(label.text()))) {
        report(codes::kUnknownLabel, fmt::format("JMP to '{}', which is not a label of this POU", label.text()),
               label.range(), "declare the label as 'name:' before a statement");
      }
      break;
    }
    case ast::StatementKind::Try:
      check_statement_list(statement.child_by_field("body"));
      for (uint32_t i = 0; i < statement.named_child_count(); ++i) {
        SyntaxNode clause = statement.named_child(i);
        if (clause.kind() == "catch_clause" || clause.kind() == "finally_clause") {
          check_statement_list(clause.child_by_field("body"));
        }
      }
      break;
    default:
      break;
  }
}

const Symbol* BodyChecker::enum_value_for(const Type* target, SyntaxNode value) const {
  // MatIEC's candidate types: where an enum is expected, a bare name that is one of its values
  // means that value, even if a variable of the same name exists (Mode := HOA_HAND).
  if (!model_.profile().enum_values_typed_by_context) return nullptr;  // CODESYS: the name decides alone
  const Type* type = underlying(target);
  if (!type || type->kind != TypeKind::Enum || !type->declaration || !value || value.kind() != "identifier") {
    return nullptr;
  }
  const Symbol* found = type->declaration->own_member(value.text());
  return found && found->kind == SymbolKind::EnumValue ? found : nullptr;
}

bool BodyChecker::inside(const Symbol& pou) const {
  for (const Symbol* scope = &pou_; scope; scope = scope->owner) {
    if (scope == &pou) return true;
  }
  return false;
}

void BodyChecker::check_assignment(SyntaxNode statement) {
  SyntaxNode left = statement.child_by_field("left");
  SyntaxNode right = statement.child_by_field("right");
  SyntaxNode op = statement.child_by_field("operator");
  const std::string_view operator_text = op ? op.text() : ":=";
  ExprInfo target = type_expression(left, 0);
  // a := b := 0 (CODESYS multiple assignment): check the inner assignment, then use its target.
  ExprInfo value{.type = types_.unknown()};
  if (right && right.kind() == "assignment_expression") {
    check_assignment(right);
    value = type_expression(right.child_by_field("left"), 0);
  } else if (const Symbol* enumerator = enum_value_for(target.type, right)) {
    value = ExprInfo{.type = model_.type_of(enumerator), .symbol = enumerator};
  } else {
    value = type_expression(right, 0);
  }
  // With a syntax error inside, what parsed is a guess: names are checked, the rest would be noise.
  if (!left || statement.has_error()) return;
  if (!check_assignment_target(target, left)) return;
  if (operator_text == "S=" || operator_text == "R=") {
    if (!target.type->is_unknown() && arithmetic_type(target.type)->kind != TypeKind::Bool) {
      report(codes::kTypeMismatch, fmt::format("{} needs a BOOL target, not {}", operator_text, target.type->name),
             left.range());
    }
    return;
  }
  if (names_equal(operator_text, "REF=")) {
    const Type* type = underlying(target.type);
    if (!type->is_unknown() && type->kind != TypeKind::Reference) {
      report(codes::kInvalidDereference, fmt::format("REF= needs a REFERENCE TO variable, not {}", target.type->name),
             left.range());
    }
    return;
  }
  if (operator_text == "?=") return;  // TwinCAT assignment attempt: any interface/reference
  check_conversion(value, target.type, right);
}

// What may stand left of ':=' (and be the target of IL ST, S and R).
bool BodyChecker::check_assignment_target(const ExprInfo& target, SyntaxNode where) {
  if (target.symbol && target.symbol->kind == SymbolKind::Variable) {
    if (target.symbol->has(kConstant)) {
      report(codes::kAssignToConstant, fmt::format("'{}' is a CONSTANT and cannot be assigned", target.symbol->name),
             where.range(), {}, {{target.symbol->name_range, "declared CONSTANT here"}});
      return false;
    }
    // A VAR_EXTERNAL without CONSTANT still names the CONSTANT global (OpenPCS linker L12003).
    if (const Symbol* global = target.symbol->section == ast::VarSection::External
                                   ? model_.find_linked_global(target.symbol->name)
                                   : nullptr;
        global && global->has(kConstant)) {
      std::vector<DiagnosticLabel> labels;
      if (global->source == pou_.source) labels.push_back({global->name_range, "declared VAR_GLOBAL CONSTANT here"});
      report(codes::kAssignToConstant,
             fmt::format("'{}' is a VAR_GLOBAL CONSTANT and cannot be assigned through its VAR_EXTERNAL",
                         target.symbol->name),
             where.range(), "a CONSTANT global is read-only everywhere; copy it into a variable to work with a changed value",
             std::move(labels));
      return false;
    }
    if (target.read_only_output) {
      report(codes::kAssignToInput,
             fmt::format("'{}' is an output of the instance; only the function block itself writes it", where.text()),
             where.range(), "write an input of the instance instead, or copy the value into a variable of your own");
      return false;
    }
    for (const Symbol* variable : for_variables_) {
      if (variable == target.symbol) {
        report(codes::kForVariableModified,
               fmt::format("the FOR variable '{}' is assigned inside its loop", target.symbol->name), where.range(),
               "use WHILE if the loop needs to change its own counter");
      }
    }
  } else if (target.symbol && is_pou_kind(target.symbol->kind) && inside(*target.symbol)) {
    // F := value inside F (and a property's GET) sets the result.
  } else if (target.symbol && target.symbol->kind == SymbolKind::Property) {
    // Writing a property calls SET; a property without SET is read-only.
    if (!target.symbol->own_member("SET") && target.symbol->own_member("GET")) {
      report(codes::kAssignToInput, fmt::format("property '{}' has no SET accessor", target.symbol->name), where.range());
      return false;
    }
  } else if (!target.assignable && !target.type->is_unknown()) {
    report(codes::kNotAssignable, fmt::format("'{}' is not a valid assignment target", where.text()), where.range(),
           "only variables (and their elements, members, dereferenced pointers) can be assigned");
    return false;
  } else if (target.names_type || target.names_namespace) {
    report(codes::kNotAssignable, fmt::format("'{}' is not a valid assignment target", where.text()), where.range());
    return false;
  }
  return true;
}

void BodyChecker::check_conversion(const ExprInfo& value, const Type* target, SyntaxNode where) {
  if (!target || !value.type || !where) return;
  const Type* to = underlying(target);
  if (to->kind == TypeKind::Reference && to->element) to = underlying(to->element);
  if (to->is_unknown() || value.type->is_unknown()) return;
  const Profile& profile = model_.profile();
  // Untyped literals: the value decides, not the literal's smallest type.
  if (value.untyped_literal && value.value) {
    const ConstValue& constant = *value.value;
    const Type* base = arithmetic_type(to);
    if (constant.kind == ConstValue::Kind::Integer) {
      if (base->kind == TypeKind::Bool) {
        if (profile.bit_literals_to_bool && (constant.integer == 0 || constant.integer == 1)) return;
        report(codes::kTypeMismatch,
               fmt::format("cannot convert type '{}' to type '{}'", value.type->name, target->name), where.range(),
               fmt::format("BOOL takes TRUE or FALSE; to turn a number into BOOL write {}_TO_BOOL(x) or x <> 0",
                           value.type->name));
        return;
      }
      if (underlying(target)->kind == TypeKind::Subrange) {
        const Type* subrange = underlying(target);
        if (constant.integer < subrange->range_lower || constant.integer > subrange->range_upper) {
          report(codes::kLiteralOutOfRange,
                 fmt::format("cannot convert '{}' to type '{}': outside {}..{}", int128_to_string(constant.integer),
                             subrange->name, subrange->range_lower, subrange->range_upper),
                 where.range());
        }
        return;
      }
      if (is_any_int_or_bit(base)) {
        auto range = integer_range(base);
        if (!range) return;
        __int128 upper = range->upper;
        if (value.based_literal && base->kind == TypeKind::SignedInt) upper = upper * 2 + 1;  // 16#FFFF into INT: a bit pattern
        if (constant.integer < range->lower || constant.integer > upper) {
          report(codes::kLiteralOutOfRange,
                 fmt::format("{} does not fit into {} ({}..{})", int128_to_string(constant.integer), target->name,
                             int128_to_string(range->lower), int128_to_string(range->upper)),
                 where.range(), "use a wider type");
        }
        return;
      }
      if (base->kind == TypeKind::Real) return;
      if (base->kind == TypeKind::Enum || (base->kind == TypeKind::Duration && profile.time_and_integers_mix)) return;
    }
    if (constant.kind == ConstValue::Kind::Real && is_numeric(base) && base->kind != TypeKind::Real) {
      if (profile.narrowing_is_error) {
        report(codes::kTypeMismatch, fmt::format("cannot convert type 'REAL' to type '{}'", target->name),
               where.range(), fmt::format("use {}()", conversion_function(types_.elementary("REAL"), target)));
      } else {
        report(codes::kImplicitNarrowing,
               fmt::format("implicit conversion of a REAL constant to {} loses the fraction", target->name),
               where.range(),
               fmt::format("use {}() or TRUNC()", conversion_function(types_.elementary("REAL"), target)));
      }
      return;
    }
    if (constant.kind == ConstValue::Kind::Real && base->kind == TypeKind::Real && base->bits == 32) {
      if (const std::string problem = real_range_problem(constant.real, true); !problem.empty()) {
        report(codes::kLiteralOutOfRange, fmt::format("'{}' does not fit into {}: {}", where.text(), target->name, problem),
               where.range(), "use LREAL");
      }
      return;
    }
    if (constant.kind == ConstValue::Kind::String && is_string_like(to)) {
      const bool wide = to->kind == TypeKind::WString;
      if (const size_t length = string_length(constant.text, wide); length > to->length) {
        report(
            codes::kStringTooLong,
            fmt::format("the string has {} characters; {} holds {}, the rest is cut off", length, to->name, to->length),
            where.range(), fmt::format("declare {}({}) or shorten the text", wide ? "WSTRING" : "STRING", length));
      }
      return;
    }
    if (constant.kind == ConstValue::Kind::String && (base->kind == TypeKind::Char || base->kind == TypeKind::WChar)) return;
  }
  switch (convertibility(value.type, target, profile)) {
    case Convertibility::Same:
    case Convertibility::Implicit:
      check_string_length(*this, value, to, where);
      return;
    case Convertibility::Narrowing: {
      const std::string function = conversion_function(value.type, target);
      std::string help = function.empty() ? std::string() : fmt::format("use an explicit conversion: {}()", function);
      if (profile.narrowing_is_error) {
        report(codes::kTypeMismatch,
               fmt::format("cannot convert type '{}' to type '{}'", value.type->name, target->name), where.range(),
               std::move(help));
      } else {
        report(codes::kImplicitNarrowing,
               fmt::format("implicit conversion from {} to {} may lose data", value.type->name, target->name),
               where.range(), std::move(help));
      }
      return;
    }
    case Convertibility::Never: {
      const std::string function = conversion_function(value.type, target);
      report(codes::kTypeMismatch, fmt::format("cannot convert type '{}' to type '{}'", value.type->name, target->name),
             where.range(), function.empty() ? std::string() : fmt::format("use {}(x)", function));
      return;
    }
  }
}

void BodyChecker::check_condition(SyntaxNode condition) {
  if (!condition) return;
  ExprInfo info = type_expression(condition, 0);
  const Type* type = arithmetic_type(info.type);
  if (type->is_unknown() || type->kind == TypeKind::Bool || type->kind == TypeKind::Generic) return;
  report(codes::kConditionNotBool, fmt::format("the condition is of type {}, not BOOL", info.type->name),
         condition.range(),
         is_numeric(type) || type->kind == TypeKind::Bit ? fmt::format("compare it: ({} <> 0)", condition.text())
                                                         : std::string());
}

void BodyChecker::check_case(SyntaxNode statement) {
  ExprInfo selector = type_expression(statement.child_by_field("value"), 0);
  const Type* selector_type = arithmetic_type(selector.type);
  const bool selector_known = !selector_type->is_unknown() && selector_type->kind != TypeKind::Generic;
  if (selector_known && !is_any_int_or_bit(selector_type) && underlying(selector.type)->kind != TypeKind::Enum) {
    report(codes::kCaseLabelType,
           fmt::format("CASE needs an integer or enum selector, not {}", selector.type->name),
           statement.child_by_field("value").range());
  }
  struct Seen {
    __int128 lower, upper;
    SyntaxNode where;
  };
  std::vector<Seen> seen;
  for (uint32_t i = 0; i < statement.named_child_count(); ++i) {
    SyntaxNode element = statement.named_child(i);
    if (element.kind() == "else_clause") {
      check_statement_list(element.child_by_field("body"));
      continue;
    }
    if (element.kind() != "case_element") continue;
    for (SyntaxNode label : element.children_by_field("label")) {
      std::optional<__int128> lower, upper;
      if (label.kind() == "range") {
        auto a = model_.constant_value(label.child_by_field("lower"), &pou_);
        auto b = model_.constant_value(label.child_by_field("upper"), &pou_);
        if (a && a->is_integer()) lower = a->integer;
        if (b && b->is_integer()) upper = b->integer;
      } else {
        ExprInfo info = type_expression(label, 0);
        if (selector_known && !info.type->is_unknown() && !info.untyped_literal &&
            convertibility(info.type, selector.type, model_.profile()) == Convertibility::Never) {
          report(codes::kCaseLabelType,
                 fmt::format("label of type {} in a CASE over {}", info.type->name, selector.type->name), label.range());
        }
        auto value = info.value ? info.value : model_.constant_value(label, &pou_);
        if (value && (value->is_integer() || value->kind == ConstValue::Kind::Bool)) {
          lower = upper = value->integer;
        } else if (!info.type->is_unknown() || !info.symbol) {
          if (!value && label.kind() != "identifier" && label.kind() != "member_expression") {
            report(codes::kNotConstant, "a CASE label must be a constant", label.range(),
                   "use literals, CONSTANT variables or enum values");
          }
        }
      }
      if (!lower || !upper) continue;
      for (const Seen& other : seen) {
        if (*lower <= other.upper && other.lower <= *upper) {
          report(codes::kDuplicateCaseLabel,
                 fmt::format("CASE label {} is already used", label.text()), label.range(), {},
                 {{other.where.range(), "first used here"}});
          break;
        }
      }
      seen.push_back({*lower, *upper, label});
    }
    check_statement_list(element.child_by_field("body"));
  }
}

void BodyChecker::check_for(SyntaxNode statement) {
  SyntaxNode variable_node = statement.child_by_field("variable");
  ExprInfo variable = type_expression(variable_node, 0);
  const Type* type = arithmetic_type(variable.type);
  if (!type->is_unknown() && !is_integer(type) && type->kind != TypeKind::Generic) {
    if (!(type->kind == TypeKind::Bit && model_.profile().bits_and_integers_mix)) {
      report(codes::kForVariableType, fmt::format("the FOR variable must be an integer, not {}", variable.type->name),
             variable_node.range());
    }
  }
  for (const char* field : {"start", "end", "step"}) {
    SyntaxNode bound = statement.child_by_field(field);
    if (!bound) continue;
    ExprInfo info = type_expression(bound, 0);
    const Type* bound_type = arithmetic_type(info.type);
    if (!bound_type->is_unknown() && bound_type->kind != TypeKind::Generic && !is_any_int_or_bit(bound_type)) {
      report(codes::kForVariableType, fmt::format("FOR bounds must be integers, not {}", info.type->name), bound.range());
    } else if (!(info.untyped_literal && std::string_view(field) == "step")) {
      // (BY -1 on an unsigned counter is accepted by CODESYS: the step is not stored in it.)
      check_conversion(info, variable.type, bound);
    }
  }
  if (variable.symbol) for_variables_.push_back(variable.symbol);
  ++loop_depth_;
  check_statement_list(statement.child_by_field("body"));
  --loop_depth_;
  if (variable.symbol) for_variables_.pop_back();
}

}  // namespace rung::check
