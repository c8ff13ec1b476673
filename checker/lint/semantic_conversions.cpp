// L053 implicit-conversion (off by default): a value changes its elementary type without a
// conversion function, where the checker accepts that silently because nothing is lost: INT to
// DINT, INT to REAL, BYTE to WORD, REAL to LREAL. Narrowing conversions are `rung check`'s E105
// (CODESYS, TwinCAT) or an error (IEC profiles) and are not repeated here. What converts to what
// is the checker's own table (checker/types/conversions.hpp).
//
// Looked at: assignments (also `F := x` and `=> target`), arguments of calls to the project's
// own POUs (standard functions take generic ANY_* parameters, whose arguments keep their type),
// FOR bounds, and the operands of arithmetic, comparisons and bit operations whose types differ.
// Untyped literals are not conversions: `rValue := 1` gives the literal the type it needs.
#include <fmt/format.h>

#include "checker/lint/flow_support.hpp"
#include "checker/lint/semantic_rules.hpp"
#include "checker/lint/semantic_support.hpp"
#include "checker/query/resolve.hpp"

namespace rung::lint::semantic {
namespace {

using check::ExprInfo;
using check::Symbol;
using check::Type;

bool is_en_eno(std::string_view name) {
  return check::names_equal(name, "EN") || check::names_equal(name, "ENO");
}

bool is_operator_with_conversion(std::string_view op) {
  return op == "+" || op == "-" || op == "*" || op == "/" || op == "MOD" || op == "=" || op == "<>" || op == "<" ||
         op == "<=" || op == ">" || op == ">=" || op == "AND" || op == "&" || op == "OR" || op == "XOR";
}

class ConversionFinder {
 public:
  ConversionFinder(LintContext& context, const Symbol& pou) : context_(context), typer_(context.model(), pou) {}

  void run() {
    const NodeList& nodes = context_.nodes();
    walk_bodies(nodes, typer_.pou(), [&](uint32_t i) {
      const std::string_view kind = nodes.kind(i);
      if (kind == "assignment_statement" || kind == "assignment_expression") check_assignment(nodes.node(i));
      if (kind == "for_statement") check_for(nodes.node(i));
      if (kind == "call_expression") check_call(nodes.node(i));
      if (kind == "binary_expression") check_operator(nodes.node(i));
      return true;
    });
  }

 private:
  // A stored value: `value` is converted to `target` (elementary types only).
  void check_stored(const ExprInfo& value, const Type* target, SyntaxNode where) {
    if (value.untyped_literal || !value.type || !target) return;
    const Type* from = check::arithmetic_type(value.type);
    const Type* to = check::arithmetic_type(target);
    if (from == to || !is_scalar(from) || !is_scalar(to)) return;
    // Enumerations take part in arithmetic as their base type, but an enum is not an elementary
    // type to convert: leave it to the checker.
    if (check::underlying(value.type)->kind == check::TypeKind::Enum ||
        check::underlying(target)->kind == check::TypeKind::Enum) {
      return;
    }
    if (check::convertibility(value.type, target, context_.model().profile()) != check::Convertibility::Implicit)
      return;
    report(from, to, where);
  }

  void report(const Type* from, const Type* to, SyntaxNode where) {
    context_.report(
        "L053",
        fmt::format("implicit conversion from {} to {}: '{}'", from->name, to->name, flow::in_message(where.text())),
        where.range(),
        fmt::format("write the conversion to make the type change visible: {}_TO_{}({})", from->name, to->name,
                    flow::in_message(where.text())));
  }

  void check_assignment(SyntaxNode node) {
    const SyntaxNode op = node.child_by_field("operator");
    if (op && op.text() != ":=") return;  // S=, R=, REF=, ?= store no converted value
    const SyntaxNode left = node.child_by_field("left");
    const SyntaxNode right = node.child_by_field("right");
    if (!right || right.kind() == "assignment_expression") return;  // a := b := c: the inner one is checked
    auto target = typer_.type_of(left);
    auto value = typer_.type_of(right);
    if (target && value) check_stored(*value, target->type, right);
  }

  void check_for(SyntaxNode node) {
    auto counter = typer_.type_of(node.child_by_field("variable"));
    if (!counter) return;
    for (const char* field : {"start", "end", "step"}) {
      const SyntaxNode bound = node.child_by_field(field);
      if (auto value = typer_.type_of(bound)) check_stored(*value, counter->type, bound);
    }
  }

  // The parameter an argument binds to: by name, or by position among the inputs (and in-outs)
  // in declaration order, the base block's first; nullptr when there is none.
  const Symbol* parameter_of(const Symbol& callee, const check::CallArgument& argument, size_t position) const {
    if (argument.name) {
      const Symbol* parameter = context_.model().find_member(&callee, argument.name.text());
      return parameter && parameter->kind == check::SymbolKind::Variable ? parameter : nullptr;
    }
    std::vector<const Symbol*> chain;
    for (const Symbol* s = &callee; s && chain.size() < 32; s = s->base) chain.push_back(s);
    size_t index = 0;
    for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
      for (const Symbol* member : (*it)->ordered) {
        if (member->kind != check::SymbolKind::Variable || is_en_eno(member->name)) continue;
        if (member->section != ast::VarSection::Input && member->section != ast::VarSection::InOut) continue;
        if (index++ == position) return member;
      }
    }
    return nullptr;
  }

  void check_call(SyntaxNode call) {
    auto function = typer_.type_of(call.child_by_field("function"));
    const Symbol* callee = function ? check::query::callee_of(*function) : nullptr;
    if (!callee || callee->has(check::kLibrary)) return;
    size_t position = 0;
    for (const check::CallArgument& argument : check::call_arguments(call.child_by_field("arguments"))) {
      const size_t at = argument.name ? 0 : position++;
      if (!argument.value || (argument.name && is_en_eno(argument.name.text()))) continue;
      const Symbol* parameter = parameter_of(*callee, argument, at);
      if (!parameter || parameter->section == ast::VarSection::InOut) continue;  // in-outs are passed, not converted
      auto value = typer_.type_of(argument.value);
      if (!value) continue;
      const Type* parameter_type = context_.model().type_of(parameter);
      if (argument.output && parameter->section == ast::VarSection::Output) {
        check_stored(ExprInfo{.type = parameter_type}, value->type, argument.value);
      } else if (!argument.output && parameter->section == ast::VarSection::Input) {
        check_stored(*value, parameter_type, argument.value);
      }
    }
  }

  // a + b with a : INT, b : DINT: a is widened to DINT (both, for INT and UINT, to DINT).
  void check_operator(SyntaxNode node) {
    const std::string op = ast::operator_of(node);
    if (!is_operator_with_conversion(op)) return;
    const SyntaxNode left = node.child_by_field("left");
    const SyntaxNode right = node.child_by_field("right");
    auto a = typer_.type_of(left);
    auto b = typer_.type_of(right);
    if (!a || !b || a->untyped_literal || b->untyped_literal) return;
    const Type* ta = check::arithmetic_type(a->type);
    const Type* tb = check::arithmetic_type(b->type);
    if (ta == tb) return;
    auto number = [](const Type* t) { return check::is_numeric(t) || t->kind == check::TypeKind::Bit; };
    if (!number(ta) || !number(tb)) return;  // TIME * INT, BOOL AND WORD ...: operators of their own
    if (check::underlying(a->type)->kind == check::TypeKind::Enum ||
        check::underlying(b->type)->kind == check::TypeKind::Enum) {
      return;
    }
    const Type* common = check::common_numeric_type(ta, tb, context_.model().types());
    if (!common) return;
    const check::Profile& profile = context_.model().profile();
    const bool left_widened =
        ta != common && check::convertibility(ta, common, profile) == check::Convertibility::Implicit;
    const bool right_widened =
        tb != common && check::convertibility(tb, common, profile) == check::Convertibility::Implicit;
    if (left_widened && right_widened) {
      context_.report("L053",
                      fmt::format("implicit conversion of {} and {} to {}: '{}'", ta->name, tb->name, common->name,
                                  flow::in_message(node.text())),
                      node.range(),
                      fmt::format("convert the operands to one type with conversion functions ({}_TO_{}, {}_TO_{})",
                                  ta->name, common->name, tb->name, common->name));
    } else if (left_widened) {
      report(ta, common, left);
    } else if (right_widened) {
      report(tb, common, right);
    }
  }

  LintContext& context_;
  ExpressionTyper typer_;
};

}  // namespace

void check_implicit_conversions(LintContext& context) {
  for (const Symbol* pou : context.pous()) ConversionFinder(context, *pou).run();
}

}  // namespace rung::lint::semantic
