// L041 enum-case-incomplete: a CASE over an enumeration without ELSE whose labels miss values of
// the enumeration. A state machine that gains a state (E_State.Error) and forgets its branch
// silently does nothing in that state. Labels that are not constants make the rule stay silent:
// what they cover cannot be known.
#include <fmt/format.h>

#include <set>

#include "checker/lint/flow_support.hpp"
#include "checker/lint/semantic_rules.hpp"
#include "checker/lint/semantic_support.hpp"

namespace rung::lint::semantic {
namespace {

using check::Symbol;

constexpr size_t kNamedMissing = 6;  // more missing values are counted, not listed

struct Covered {
  std::vector<std::pair<__int128, __int128>> ranges;
  bool contains(__int128 value) const {
    for (const auto& [lower, upper] : ranges) {
      if (lower <= value && value <= upper) return true;
    }
    return false;
  }
};

std::optional<__int128> integer_of(ExpressionTyper& typer, SyntaxNode label) {
  std::optional<check::ConstValue> value;
  if (auto info = typer.type_of(label)) value = info->value;
  if (!value) value = typer.model().constant_value(label, &typer.pou());
  if (!value || !(value->is_integer() || value->kind == check::ConstValue::Kind::Bool)) return std::nullopt;
  return value->integer;
}

// What the labels of `statement` cover; nullopt when a label is not a constant.
std::optional<Covered> covered_by_labels(ExpressionTyper& typer, SyntaxNode statement) {
  Covered covered;
  for (SyntaxNode element : statement.children_of_kind("case_element")) {
    for (SyntaxNode label : element.children_by_field("label")) {
      if (label.kind() == "range") {
        auto lower = integer_of(typer, label.child_by_field("lower"));
        auto upper = integer_of(typer, label.child_by_field("upper"));
        if (!lower || !upper) return std::nullopt;
        covered.ranges.emplace_back(*lower, *upper);
      } else {
        auto value = integer_of(typer, label);
        if (!value) return std::nullopt;
        covered.ranges.emplace_back(*value, *value);
      }
    }
  }
  return covered;
}

void check_case(LintContext& context, ExpressionTyper& typer, SyntaxNode statement) {
  if (statement.has_error() || statement.first_child_of_kind("else_clause")) return;
  const SyntaxNode selector = statement.child_by_field("value");
  auto info = typer.type_of(selector);
  if (!info) return;
  const check::Type* type = check::underlying(info->type);
  if (type->kind != check::TypeKind::Enum || !type->declaration) return;
  const Symbol& enumeration = *type->declaration;
  auto covered = covered_by_labels(typer, statement);
  if (!covered) return;
  std::vector<std::string> missing;
  std::set<__int128> seen;  // values that share a number are one value
  for (const Symbol* value : enumeration.ordered) {
    if (value->kind != check::SymbolKind::EnumValue) continue;
    auto number = context.model().enum_value(value);
    if (!number) return;  // a value rung could not compute: no judgement
    if (covered->contains(*number) || !seen.insert(*number).second) continue;
    missing.push_back(fmt::format("{}.{}", enumeration.name, value->name));
  }
  if (missing.empty()) return;
  std::string list;
  for (size_t i = 0; i < missing.size() && i < kNamedMissing; ++i) list += (i ? ", " : "") + missing[i];
  if (missing.size() > kNamedMissing) list += fmt::format(" and {} more", missing.size() - kNamedMissing);
  context.report("L041", fmt::format("CASE on {} has no ELSE and misses {}", flow::in_message(selector.text()), list),
                 {statement.begin(), selector.end()},
                 fmt::format("add a branch for each missing value of {} (or an ELSE), so that every state is "
                             "handled on purpose",
                             enumeration.name));
}

}  // namespace

void check_enum_case(LintContext& context) {
  for (const Symbol* pou : context.pous()) {
    ExpressionTyper typer(context.model(), *pou);
    const NodeList& nodes = context.nodes();
    walk_bodies(nodes, *pou, [&](uint32_t i) {
      if (nodes.kind(i) == "case_statement") check_case(context, typer, nodes.node(i));
      return true;
    });
  }
}

}  // namespace rung::lint::semantic
