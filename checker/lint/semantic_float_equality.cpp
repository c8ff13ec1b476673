// L040 float-equality: `=` or `<>` (or EQ/NE) with a REAL or LREAL operand. A REAL holds most
// decimal fractions only approximately (0.1 is 0.100000001490116...), and every arithmetic step
// rounds, so two values that "should" be equal rarely are: `rLevel = 0.3` can stay FALSE forever.
// A comparison with a literal 0.0 is reported too: after arithmetic a result that should be zero
// is often 1E-8.
#include <fmt/format.h>

#include "checker/lint/flow_support.hpp"
#include "checker/lint/semantic_rules.hpp"
#include "checker/lint/semantic_support.hpp"

namespace rung::lint::semantic {
namespace {

using check::ExprInfo;
using check::TypeKind;

// A REAL/LREAL operand that is a value computed or stored at run time: an untyped literal takes
// the other side's type, so `i = 1.5` compares integers converted exactly and is not reported.
bool is_runtime_real(const ExprInfo& info) {
  const check::Type* type = check::arithmetic_type(info.type);
  return type->kind == TypeKind::Real && !info.untyped_literal && !info.value;
}

std::string real_name(const ExprInfo& a, const ExprInfo& b) {
  const check::Type* type = check::arithmetic_type(is_runtime_real(a) ? a.type : b.type);
  return type->name;
}

void report(LintContext& context, SyntaxNode where, std::string_view type_name, std::string_view left,
            std::string_view right, bool equal) {
  context.report("L040", fmt::format("exact comparison of {} values: '{}'", type_name, flow::in_message(where.text())),
                 where.range(),
                 fmt::format("rounding makes exactly {} {} values rare: compare with a tolerance, e.g. "
                             "ABS({} - {}) {} 1.0E-6",
                             equal ? "equal" : "different", type_name, flow::in_message(left), flow::in_message(right),
                             equal ? "<" : ">="));
}

void check_pou(LintContext& context, const check::Symbol& pou) {
  static const TSFieldId kFunction = NodeList::field_id("function");
  static const TSFieldId kLeft = NodeList::field_id("left");
  static const TSFieldId kRight = NodeList::field_id("right");
  ExpressionTyper typer(context.model(), pou);
  const NodeList& nodes = context.nodes();
  walk_bodies(nodes, pou, [&](uint32_t i) {
    const std::string_view kind = nodes.kind(i);
    if (kind == "binary_expression") {
      const std::string_view op = operator_text(nodes, i);
      if (op != "=" && op != "<>") return true;
      const SyntaxNode left = nodes.node(nodes.child_by_field(i, kLeft));
      const SyntaxNode right = nodes.node(nodes.child_by_field(i, kRight));
      auto a = typer.type_of(left);
      auto b = typer.type_of(right);
      if (!a || !b || !(is_runtime_real(*a) || is_runtime_real(*b))) return true;
      report(context, nodes.node(i), real_name(*a, *b), left.text(), right.text(), op == "=");
      return true;
    }
    if (kind == "call_expression") {
      // EQ(a, b) and NE(a, b), the standard functions of '=' and '<>'.
      const uint32_t function = nodes.child_by_field(i, kFunction);
      if (function == NodeList::kNone || nodes.kind(function) != "identifier") return true;
      const std::string_view name = nodes.text(function);
      const bool equal = check::names_equal(name, "EQ");
      if (!equal && !check::names_equal(name, "NE")) return true;
      const check::Symbol* callee = context.model().lookup(&pou, name);
      if (!callee || !callee->has(check::kLibrary)) return true;  // a project's own EQ is something else
      const SyntaxNode node = nodes.node(i);
      const std::vector<check::CallArgument> arguments = check::call_arguments(node.child_by_field("arguments"));
      if (arguments.size() != 2 || arguments[0].output || arguments[1].output) return true;
      auto a = typer.type_of(arguments[0].value);
      auto b = typer.type_of(arguments[1].value);
      if (!a || !b || !(is_runtime_real(*a) || is_runtime_real(*b))) return true;
      report(context, node, real_name(*a, *b), arguments[0].value.text(), arguments[1].value.text(), equal);
    }
    return true;
  });
}

}  // namespace

void check_float_equality(LintContext& context) {
  for (const check::Symbol* pou : context.pous()) check_pou(context, *pou);
}

}  // namespace rung::lint::semantic
