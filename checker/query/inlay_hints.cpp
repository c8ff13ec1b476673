#include "checker/query/inlay_hints.hpp"

#include <algorithm>

#include "checker/query/call_site.hpp"
#include "checker/query/resolve.hpp"
#include "checker/semantic/body_checker.hpp"

namespace rung::check::query {
namespace {

// IN, IN1, IN2 ...: the standard functions' inputs that have no meaning of their own.
bool is_anonymous_input(std::string_view name) {
  if (name.size() < 2 || !names_equal(name.substr(0, 2), "IN")) return false;
  for (char c : name.substr(2)) {
    if (c < '0' || c > '9') return false;
  }
  return true;
}

bool is_string_kind(const Type* type) {
  return type->kind == TypeKind::String || type->kind == TypeKind::WString || type->kind == TypeKind::Char ||
         type->kind == TypeKind::WChar;
}

// Visits every node of every body of `source` that meets `file_range`, with a checker for the
// POU the body belongs to.
template <typename Visit>
void for_each_body_node(const ProjectModel& model, SourceId source, TextRange file_range, Visit&& visit) {
  if (source >= model.source_count()) return;
  const Document& document = *model.source(source).document;
  const SyntaxTree* tree = document.tree();
  if (!tree || tree->aborted()) return;
  auto meets = [&](SyntaxNode node) {
    return document.file_end_offset_of(node.end()) >= file_range.begin &&
           document.file_offset_of(node.begin()) <= file_range.end;
  };
  for (const Symbol* pou : pous_of(model.source(source).symbols)) {
    const SyntaxNode body = pou->node && pou->node.kind() != "source_file" ? pou->node.child_by_field("body") : SyntaxNode();
    if (!body || !meets(body)) continue;
    std::vector<Diagnostic> ignored;
    BodyChecker checker(model, *pou, ignored);
    walk_preorder(body, [&](SyntaxNode node) {
      if (!meets(node)) return false;
      visit(checker, node);
      return true;
    });
  }
}

// The parameter each argument of `call` gives, by name or position (nullptr when unknown).
std::vector<std::pair<CallArgument, const Symbol*>> bound_arguments(BodyChecker& checker, SyntaxNode call) {
  std::vector<std::pair<CallArgument, const Symbol*>> bound;
  const Symbol* callee = callee_of(checker.type_of(call.child_by_field("function")));
  if (!callee) return bound;
  const std::vector<const Symbol*> parameters = call_parameters(callee);
  const std::vector<const Symbol*> positional = positional_parameters(callee);
  size_t index = 0;
  for (const CallArgument& argument : call_arguments(call.child_by_field("arguments"))) {
    const Symbol* parameter = argument.name ? named_parameter(parameters, argument.name.text())
                                            : positional_parameter(positional, index++);
    bound.emplace_back(argument, parameter);
  }
  return bound;
}

}  // namespace

std::vector<ParameterHint> parameter_hints(const Workspace& workspace, SourceId source, TextRange file_range) {
  std::vector<ParameterHint> hints;
  const ProjectModel& model = workspace.model();
  for_each_body_node(model, source, file_range, [&](BodyChecker& checker, SyntaxNode node) {
    if (node.kind() != "call_expression") return;
    for (const auto& [argument, parameter] : bound_arguments(checker, node)) {
      if (argument.name || argument.output || !argument.value || !parameter) continue;
      if (parameter->has(kLibrary) && is_anonymous_input(parameter->name)) continue;
      if (names_equal(argument.value.text(), parameter->name)) continue;
      const uint32_t offset = model.source(source).document->file_offset_of(argument.value.begin());
      if (offset >= file_range.begin && offset <= file_range.end) hints.push_back({offset, parameter});
    }
  });
  std::stable_sort(hints.begin(), hints.end(), [](const auto& a, const auto& b) { return a.offset < b.offset; });
  return hints;
}

std::vector<ConversionHint> conversion_hints(const Workspace& workspace, SourceId source, TextRange file_range) {
  std::vector<ConversionHint> hints;
  const ProjectModel& model = workspace.model();
  auto add = [&](const ExprInfo& value, const Type* target, SyntaxNode where) {
    if (value.untyped_literal || !value.type || !target) return;
    const Type* from = underlying(value.type);
    const Type* to = underlying(target);
    if (from->is_unknown() || to->is_unknown() || from == to || !is_elementary(from) || !is_elementary(to)) return;
    if (is_string_kind(from) || is_string_kind(to) || to->kind == TypeKind::Generic) return;
    if (convertibility(from, to, model.profile()) != Convertibility::Implicit) return;
    const uint32_t offset = model.source(source).document->file_offset_of(where.begin());
    if (offset >= file_range.begin && offset <= file_range.end) hints.push_back({offset, from, to});
  };
  for_each_body_node(model, source, file_range, [&](BodyChecker& checker, SyntaxNode node) {
    const std::string_view kind = node.kind();
    if (kind == "assignment_statement") {
      const SyntaxNode left = node.child_by_field("left");
      const SyntaxNode right = node.child_by_field("right");
      if (left && right) add(checker.type_of(right), checker.type_of(left).type, right);
    } else if (kind == "call_expression") {
      for (const auto& [argument, parameter] : bound_arguments(checker, node)) {
        if (argument.output || !argument.value || !parameter) continue;
        add(checker.type_of(argument.value), model.type_of(parameter), argument.value);
      }
    }
  });
  std::stable_sort(hints.begin(), hints.end(), [](const auto& a, const auto& b) { return a.offset < b.offset; });
  return hints;
}

}  // namespace rung::check::query
