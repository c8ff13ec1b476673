#include "checker/query/name_suggestions.hpp"

#include "checker/query/call_site.hpp"
#include "checker/query/location.hpp"
#include "checker/query/position.hpp"
#include "checker/query/resolve.hpp"
#include "checker/semantic/body_checker.hpp"

namespace rung::check::query {
namespace {

ExprInfo type_in(const ProjectModel& model, const Symbol& scope, SyntaxNode expression) {
  std::vector<Diagnostic> ignored;
  return BodyChecker(model, scope, ignored).type_of(expression);
}

// obj.member: the members of obj's type and of the blocks it extends (what E005 searches), or
// a global list's variables.
std::vector<std::string_view> member_candidates(const ProjectModel& model, const Symbol& scope, SyntaxNode object,
                                                std::string_view member) {
  const ExprInfo info = type_in(model, scope, object);
  // GVL.member: the list's variables (what E005 searches for a qualified_only list).
  if (info.names_namespace && info.symbol && info.symbol->kind == SymbolKind::GlobalList) {
    if (model.find_member(info.symbol, member)) return {};
    std::vector<std::string_view> names;
    names.reserve(info.symbol->ordered.size());
    for (const Symbol* variable : info.symbol->ordered) names.push_back(variable->name);
    return names;
  }
  if (info.names_type || info.names_namespace || !info.type) return {};
  const Type* type = underlying(info.type);
  if (type->kind == TypeKind::Reference && type->element) type = underlying(type->element);
  const Symbol* container = type->declaration;
  if (!container || model.find_member(container, member)) return {};
  std::vector<std::string_view> names;
  int depth = 0;
  for (const Symbol* c = container; c && depth < 32; c = c->base, ++depth) {  // bounded: EXTENDS may cycle
    for (const Symbol* m : c->ordered) names.push_back(m->name);
  }
  return names;
}

// fb(nam := 1): the parameters of the callee, when it has none of that name.
std::vector<std::string_view> parameter_candidates(const ProjectModel& model, const Symbol& scope, SyntaxNode argument,
                                                   std::string_view name) {
  SyntaxNode call = argument.parent() ? argument.parent().parent() : SyntaxNode();
  if (!call || call.kind() != "call_expression") return {};
  const Symbol* callee = callee_of(type_in(model, scope, call.child_by_field("function")));
  if (!callee || callee->has(kLibrary) || named_parameter(call_parameters(callee), name)) return {};
  std::vector<std::string_view> names;
  for (const Symbol* parameter : call_parameters(callee)) names.push_back(parameter->name);
  return names;
}

}  // namespace

std::optional<NameSuggestion> suggest_name(const Workspace& workspace, SourceId source, uint32_t file_offset) {
  const std::optional<QueryPoint> point = query_point(workspace, source, file_offset);
  if (!point || !point->name || !point->scope || point->name.kind() != "identifier") return std::nullopt;
  const ProjectModel& model = workspace.model();
  const SyntaxNode name = point->name;
  const SyntaxNode parent = name.parent();
  const std::string_view kind = parent ? parent.kind() : std::string_view();
  std::vector<std::string_view> candidates;
  if (kind == "member_expression" && parent.child_by_field("member") == name) {
    candidates = member_candidates(model, *point->scope, parent.child_by_field("object"), name.text());
  } else if ((kind == "argument" || kind == "output_argument") && parent.child_by_field("name") == name) {
    candidates = parameter_candidates(model, *point->scope, parent, name.text());
  } else if (name_site(model, source, name).use == NameUse::Expression && !model.lookup(point->scope, name.text())) {
    candidates = model.visible_names(point->scope);
  }
  const std::string_view closest = closest_name(name.text(), candidates);
  if (closest.empty() || closest == name.text()) return std::nullopt;
  return NameSuggestion{location_in_file(model, source, name.range()).range, std::string(closest)};
}

}  // namespace rung::check::query
