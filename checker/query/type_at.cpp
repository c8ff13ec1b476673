#include "checker/query/type_at.hpp"

#include "checker/query/position.hpp"
#include "checker/query/resolve.hpp"
#include "checker/semantic/body_checker.hpp"

namespace rung::check::query {
namespace {

// Literals and operator expressions: the smallest expression node at or above `node`. A
// statement, declaration or body is no expression, and neither is anything above it.
SyntaxNode expression_around(SyntaxNode node) {
  for (; node; node = node.parent()) {
    const ast::ExpressionKind kind = ast::expression_kind(node);
    if (kind != ast::ExpressionKind::Unknown && kind != ast::ExpressionKind::Initializer) return node;
    const std::string_view syntax = node.kind();
    if (syntax.ends_with("statement") || syntax.ends_with("_declaration") || syntax == "statement_list" ||
        syntax == "var_block" || syntax == "source_file") {
      return {};
    }
  }
  return {};
}

}  // namespace

const Type* type_at(const Workspace& workspace, SourceId source, uint32_t file_offset) {
  const ProjectModel& model = workspace.model();
  const std::optional<QueryPoint> point = query_point(workspace, source, file_offset);
  if (!point || !point->scope) return nullptr;
  SyntaxNode expression;
  if (point->name) {
    const NameSite site = name_site(model, source, point->name);
    if (site.use != NameUse::Expression) {
      const Symbol* symbol = resolve_name(model, source, point->name, point->scope);
      return symbol ? model.type_of(symbol) : nullptr;
    }
    expression = site.expression;
  } else {
    expression = expression_around(point->node);
  }
  if (!expression) return nullptr;
  std::vector<Diagnostic> ignored;
  return BodyChecker(model, *point->scope, ignored).type_of(expression).type;
}

}  // namespace rung::check::query
