#include "checker/lint/semantic_support.hpp"

#include <filesystem>

#include "checker/semantic/builtins.hpp"

namespace rung::lint::semantic {

using check::Symbol;

namespace {

constexpr int kMaxDepth = 200;  // deeper expressions are left alone (no stack exhaustion)

bool is_body_kind(std::string_view kind) {
  return kind == "statement_list" || kind == "il_body" || kind == "sfc_network";
}

}  // namespace

std::vector<SyntaxNode> bodies_of(const Symbol& pou) {
  std::vector<SyntaxNode> bodies;
  if (!pou.node) return bodies;
  if (pou.node.kind() == "source_file") {  // a snippet's statements (file_symbols.cpp)
    for (SyntaxNode child : pou.node.named_children()) {
      if (is_body_kind(child.kind())) bodies.push_back(child);
    }
  } else if (SyntaxNode body = pou.node.child_by_field("body")) {
    bodies.push_back(body);
  }
  return bodies;
}

bool is_member_action_block(const Symbol& pou, SyntaxNode node) {
  if (node == pou.node) return false;
  const SyntaxNode name = node.child_by_field("name");
  const Symbol* member = name ? pou.own_member(name.text()) : nullptr;
  return member && member->node == node;
}

ExpressionTyper::ExpressionTyper(const check::ProjectModel& model, const Symbol& pou)
    : model_(model), pou_(pou), checker_(std::make_unique<check::BodyChecker>(model, pou, scratch_)) {}

std::optional<check::ExprInfo> ExpressionTyper::type_of(SyntaxNode expression) {
  if (!expression || expression.has_error() || !names_resolve(expression)) return std::nullopt;
  scratch_.clear();
  return checker_->type_of(expression);
}

bool ExpressionTyper::name_resolves(std::string_view name) const {
  return model_.lookup(&pou_, name) || check::names_equal(name, "THIS") || check::names_equal(name, "SUPER") ||
         model_.is_library_namespace(name) || check::find_builtin(name);
}

bool ExpressionTyper::names_resolve(SyntaxNode expression) const {
  // An explicit stack: the parts of an expression whose names are looked up where they stand.
  std::vector<std::pair<SyntaxNode, int>> pending{{expression, 0}};
  while (!pending.empty()) {
    auto [node, depth] = pending.back();
    pending.pop_back();
    if (!node || node.is_extra() || !node.is_named()) continue;
    if (depth > kMaxDepth) return false;
    const std::string_view kind = node.kind();
    if (kind == "identifier") {
      if (!name_resolves(node.text())) return false;
    } else if (kind == "global_reference") {
      const SyntaxNode name = node.child_by_field("name");
      if (!name || !model_.lookup_global(name.text())) return false;
    } else if (kind == "member_expression") {
      // The member is a name of the object's type; the object is looked up here.
      pending.push_back({node.child_by_field("object"), depth + 1});
    } else if (kind == "argument" || kind == "output_argument") {
      pending.push_back({node.child_by_field(kind == "argument" ? "value" : "target"), depth + 1});
    } else if (kind == "typed_literal" || kind == "direct_variable") {
      // E_Color#Red, %IX0.0: no name looked up in scope.
    } else {
      for (SyntaxNode child : node.named_children()) pending.push_back({child, depth + 1});
    }
  }
  return true;
}

SyntaxNode without_parentheses(SyntaxNode expression) {
  for (int depth = 0; expression && expression.kind() == "parenthesized_expression" && depth < kMaxDepth; ++depth) {
    expression = expression.named_child(0);
  }
  return expression;
}

bool is_variable_access(SyntaxNode expression) {
  for (int depth = 0; expression && depth < kMaxDepth; ++depth) {
    const std::string_view kind = expression.kind();
    if (kind == "identifier" || kind == "global_reference") return true;
    if (kind == "member_expression" || kind == "index_expression") {
      expression = expression.child_by_field("object");
    } else if (kind == "dereference_expression") {
      expression = expression.child_by_field("operand");
    } else if (kind == "parenthesized_expression") {
      expression = expression.named_child(0);
    } else {
      return false;
    }
  }
  return false;
}

bool contains_name(SyntaxNode expression) {
  bool found = false;
  walk_preorder(expression, [&](SyntaxNode node) {
    if (found || node.is_extra()) return false;
    const std::string_view kind = node.kind();
    if (kind == "identifier" || kind == "global_reference" || kind == "direct_variable") found = true;
    // E_Color#Red names a value, but a literal one: its type is written with it.
    return !found && kind != "typed_literal";
  });
  return found;
}

std::string place_of(const check::ProjectModel& model, check::SourceId source, uint32_t tree_offset) {
  const Document& document = *model.source(source).document;
  const FilePosition at = document.position_of_tree_offset(tree_offset);
  return std::filesystem::path(document.path()).filename().string() + ":" + std::to_string(at.line);
}

bool is_scalar(const check::Type* type) {
  // The elementary types without the strings: the ones a conversion function turns into each other.
  return check::is_elementary(type) && !check::is_string_like(type);
}

}  // namespace rung::lint::semantic
