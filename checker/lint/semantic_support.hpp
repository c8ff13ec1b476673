// Helpers the semantic lint rules share (rules_semantic.cpp, semantic_*.cpp): the bodies of a POU,
// typing expressions with the checker's own BodyChecker, and the small questions about expressions
// several rules ask.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "checker/lint/lint_rule.hpp"
#include "checker/semantic/body_checker.hpp"
#include "parser/ast.hpp"

namespace rung::lint::semantic {

// The bodies of `pou`: its statement list, IL body or SFC network (a snippet may have several).
std::vector<SyntaxNode> bodies_of(const check::Symbol& pou);

// Whether `node` is an SFC action block that is a POU of its own (a member of `pou`): rules visit
// it as that member, not again inside the network.
bool is_member_action_block(const check::Symbol& pou, SyntaxNode node);

// Calls enter(i) in preorder for the named nodes of `pou`'s bodies (indices into `nodes`, the node
// list of `pou`'s file); enter returns whether to descend. Comments, pragmas and member action
// blocks are not entered.
template <typename Enter>
void walk_bodies(const NodeList& nodes, const check::Symbol& pou, Enter&& enter) {
  for (SyntaxNode body : bodies_of(pou)) {
    nodes.walk(nodes.index_of(body), [&](uint32_t i) {
      if (nodes.is_extra(i) || !nodes.is_named(i)) return false;
      if (nodes.kind(i) == "sfc_action_block" && is_member_action_block(pou, nodes.node(i))) return false;
      return enter(i);
    });
  }
}

// Types expressions of one POU the way `rung check` does (BodyChecker::type_of). An expression
// with a name that does not resolve is not typed: its type would be a guess, and the checker
// already reports the name (looking for a "did you mean" again for every use would also be slow).
class ExpressionTyper {
 public:
  ExpressionTyper(const check::ProjectModel& model, const check::Symbol& pou);

  std::optional<check::ExprInfo> type_of(SyntaxNode expression);
  const check::ProjectModel& model() const { return model_; }
  const check::Symbol& pou() const { return pou_; }

 private:
  bool names_resolve(SyntaxNode expression) const;
  bool name_resolves(std::string_view name) const;

  const check::ProjectModel& model_;
  const check::Symbol& pou_;
  std::vector<Diagnostic> scratch_;  // what typing reports: rung check's business, dropped
  std::unique_ptr<check::BodyChecker> checker_;
};

// The expression inside any number of parentheses.
SyntaxNode without_parentheses(SyntaxNode expression);

// Whether `expression` reads a variable and nothing else: a name, a member, an element or a
// dereference (no call, no operator, no literal).
bool is_variable_access(SyntaxNode expression);

// Whether `expression` contains a name that is not a member after '.' nor a parameter name: an
// expression made of literals only has none.
bool contains_name(SyntaxNode expression);

// "Main.st:12": where a tree offset of a source is, as a user finds it (file name and line).
std::string place_of(const check::ProjectModel& model, check::SourceId source, uint32_t tree_offset);

// An elementary scalar type whose values convert between each other: BOOL, bit strings, integers,
// REAL, durations, dates, characters (not enums, pointers, strings or aggregates).
bool is_scalar(const check::Type* type);

}  // namespace rung::lint::semantic
