#include "checker/query/written_expression.hpp"

#include <string>

namespace rung::check::query {
namespace {

constexpr uint32_t kMaxExpressionLength = 4096;  // a qualifier longer than this is no qualifier

ExprInfo type_node(const ProjectModel& model, const Symbol& scope, SyntaxNode expression) {
  std::vector<Diagnostic> ignored;
  return BodyChecker(model, scope, ignored).type_of(expression);
}

// The expression node that spans exactly `range`, if error recovery kept one.
SyntaxNode expression_node(SyntaxNode root, TextRange range) {
  for (SyntaxNode node = root.named_descendant_for_range(range.begin, range.end); node; node = node.parent()) {
    if (node.begin() != range.begin || node.end() != range.end) break;
    if (!node.has_error() && ast::expression_kind(node) != ast::ExpressionKind::Unknown) return node;
  }
  return {};
}

}  // namespace

ExprInfo type_written_expression(const ProjectModel& model, SourceId source, const Symbol& scope, TextRange range) {
  ExprInfo unknown{.type = model.types().unknown()};
  if (source >= model.source_count() || range.end <= range.begin || range.end - range.begin > kMaxExpressionLength) {
    return unknown;
  }
  const SyntaxTree* tree = model.source(source).document->tree();
  if (!tree || tree->aborted() || range.end > tree->text().size()) return unknown;
  if (SyntaxNode node = expression_node(tree->root(), range)) return type_node(model, scope, node);
  // The text on its own, as the value of an assignment: the names in it are still looked up in
  // `scope`, which is all the typing needs.
  const std::string_view written = std::string_view(tree->text()).substr(range.begin, range.end - range.begin);
  const SyntaxTree alone = SyntaxTree::parse("PROGRAM rung_expression\nrung_expression := " + std::string(written) +
                                             ";\nEND_PROGRAM\n");
  if (alone.aborted()) return unknown;
  SyntaxNode statement = alone.root().first_child_of_kind("program_declaration");
  statement = statement ? statement.child_by_field("body") : SyntaxNode();
  statement = statement ? statement.first_child_of_kind("assignment_statement") : SyntaxNode();
  SyntaxNode value = statement ? statement.child_by_field("right") : SyntaxNode();
  if (!value || value.has_error()) return unknown;
  return type_node(model, scope, value);
}

}  // namespace rung::check::query
