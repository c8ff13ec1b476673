// L051 pointer-arithmetic: arithmetic on addresses. `pData := ADR(aBuffer) + i * SIZEOF(aBuffer[0])`
// compiles, but nothing checks the result: one wrong factor and the program writes memory that
// belongs to other variables (or the runtime). Indexing an array, or a REFERENCE, says the same
// with bounds the compiler and the runtime check.
//
// An operand is an address when it is a POINTER, a PVOID, or an ADR()/ADRINST() call; arithmetic
// whose result is stored in a POINTER or PVOID counts too (`pData := dwBase + 4`). ADD and SUB
// calls with such an operand are the same operators written as functions.
#include <fmt/format.h>

#include <set>

#include "checker/lint/flow_support.hpp"
#include "checker/lint/semantic_rules.hpp"
#include "checker/lint/semantic_support.hpp"

namespace rung::lint::semantic {
namespace {

using check::ExprInfo;
using check::Symbol;

// `op` as written: MOD in any case.
bool is_arithmetic(std::string_view op) {
  return op == "+" || op == "-" || op == "*" || op == "/" || check::names_equal(op, "MOD");
}

// A library function (or builtin) of this name, not a project POU that happens to share it.
bool calls_standard(const ExpressionTyper& typer, SyntaxNode call, std::initializer_list<std::string_view> names) {
  const SyntaxNode function = call.child_by_field("function");
  if (!function || function.kind() != "identifier") return false;
  bool named = false;
  for (std::string_view name : names) named = named || check::names_equal(function.text(), name);
  if (!named) return false;
  const Symbol* callee = typer.model().lookup(&typer.pou(), function.text());
  return !callee || callee->has(check::kLibrary);
}

// PVOID is an address-sized integer type that only ever holds addresses (TwinCAT); after typing it
// is __XWORD like XWORD, so the declaration says which it is.
bool declared_pvoid(const ExprInfo& info) {
  return info.symbol && info.symbol->kind == check::SymbolKind::Variable && info.symbol->type_node &&
         check::names_equal(info.symbol->type_node.text(), "PVOID");
}

bool holds_address(ExpressionTyper& typer, SyntaxNode operand) {
  operand = without_parentheses(operand);
  if (!operand) return false;
  if (operand.kind() == "call_expression" && calls_standard(typer, operand, {"ADR", "ADRINST"})) return true;
  auto info = typer.type_of(operand);
  if (!info) return false;
  return check::underlying(info->type)->kind == check::TypeKind::Pointer || declared_pvoid(*info);
}

class PointerArithmetic {
 public:
  PointerArithmetic(LintContext& context, const Symbol& pou)
      : context_(context), nodes_(context.nodes()), typer_(context.model(), pou) {}

  void run() {
    walk_bodies(nodes_, typer_.pou(), [&](uint32_t i) {
      const std::string_view kind = nodes_.kind(i);
      if (kind == "binary_expression") return !check_binary(i);
      if (kind == "call_expression") return !check_call(i);
      if (kind == "assignment_statement") check_assignment(i);
      return true;
    });
  }

 private:
  // Returns whether node `i` was reported (then the parts inside are not looked at again).
  bool check_binary(uint32_t i) {
    static const TSFieldId kLeft = NodeList::field_id("left");
    static const TSFieldId kRight = NodeList::field_id("right");
    if (reported_.contains(nodes_.begin(i))) return true;  // reported as the value of a pointer assignment
    if (!is_arithmetic(operator_text(nodes_, i))) return false;
    if (!holds_address(typer_, nodes_.node(nodes_.child_by_field(i, kLeft))) &&
        !holds_address(typer_, nodes_.node(nodes_.child_by_field(i, kRight)))) {
      return false;
    }
    report(nodes_.node(i));
    return true;
  }

  bool check_call(uint32_t i) {
    static const TSFieldId kFunction = NodeList::field_id("function");
    // ADD and SUB only: the other calls are not looked at any further.
    const uint32_t function = nodes_.child_by_field(i, kFunction);
    if (function == NodeList::kNone ||
        (!check::names_equal(nodes_.text(function), "ADD") && !check::names_equal(nodes_.text(function), "SUB"))) {
      return false;
    }
    const SyntaxNode node = nodes_.node(i);
    if (!calls_standard(typer_, node, {"ADD", "SUB"})) return false;
    for (const check::CallArgument& argument : check::call_arguments(node.child_by_field("arguments"))) {
      if (!argument.output && holds_address(typer_, argument.value)) {
        report(node);
        return true;
      }
    }
    return false;
  }

  // pData := dwBase + nOffset: the arithmetic computes an address even if no operand is typed as one.
  void check_assignment(uint32_t i) {
    static const TSFieldId kLeft = NodeList::field_id("left");
    static const TSFieldId kRight = NodeList::field_id("right");
    const uint32_t value = nodes_.child_by_field(i, kRight);
    if (value == NodeList::kNone) return;
    if (nodes_.kind(value) != "binary_expression" && nodes_.kind(value) != "parenthesized_expression") return;
    const SyntaxNode right = without_parentheses(nodes_.node(value));
    if (!right || right.kind() != "binary_expression" || !is_arithmetic(ast::operator_of(right))) return;
    auto target = typer_.type_of(nodes_.node(nodes_.child_by_field(i, kLeft)));
    if (!target || !(check::underlying(target->type)->kind == check::TypeKind::Pointer || declared_pvoid(*target))) {
      return;
    }
    report(right);
  }

  void report(SyntaxNode node) {
    if (!reported_.insert(node.begin()).second) return;
    context_.report("L051", fmt::format("pointer arithmetic: '{}'", flow::in_message(node.text())), node.range(),
                    "an address computed wrong overwrites memory nothing checks: index an array (aData[i]) or "
                    "use REFERENCE TO instead");
  }

  LintContext& context_;
  const NodeList& nodes_;
  ExpressionTyper typer_;
  std::set<uint32_t> reported_;  // start offsets of the expressions reported
};

}  // namespace

void check_pointer_arithmetic(LintContext& context) {
  for (const Symbol* pou : context.pous()) PointerArithmetic(context, *pou).run();
}

}  // namespace rung::lint::semantic
