#include "checker/query/call_site.hpp"

#include <algorithm>

#include "checker/query/resolve.hpp"
#include "checker/query/written_expression.hpp"

namespace rung::check::query {
namespace {

constexpr size_t kMaxInheritanceDepth = 32;  // EXTENDS may form a cycle in broken code

bool is_parameter(const Symbol& member) {
  return member.kind == SymbolKind::Variable &&
         (member.section == ast::VarSection::Input || member.section == ast::VarSection::Output ||
          member.section == ast::VarSection::InOut);
}

bool is_en_eno(std::string_view name) { return names_equal(name, "EN") || names_equal(name, "ENO"); }

// After a formal argument (`fbTimer(IN := x, |`) the next one is written formally too, so it gives
// the first input after the informal ones that no formal argument has named yet (PT), not the
// input at its position (IN again).
const Symbol* next_unnamed_parameter(const std::vector<const Symbol*>& positional, size_t informal,
                                     const std::vector<std::string_view>& given) {
  for (size_t i = informal; i < positional.size(); ++i) {
    const bool named = std::any_of(given.begin(), given.end(), [&](std::string_view name) {
      return named_parameter({positional[i]}, name) != nullptr;
    });
    if (!named) return positional[i];
  }
  return nullptr;
}

}  // namespace

std::vector<const Symbol*> call_parameters(const Symbol* callee) {
  std::vector<const Symbol*> chain;
  for (const Symbol* s = callee; s && chain.size() < kMaxInheritanceDepth; s = s->base) chain.push_back(s);
  std::vector<const Symbol*> parameters;
  for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
    for (const Symbol* member : (*it)->ordered) {
      if (is_parameter(*member)) parameters.push_back(member);
    }
  }
  return parameters;
}

std::vector<const Symbol*> positional_parameters(const Symbol* callee) {
  std::vector<const Symbol*> positional;
  for (const Symbol* parameter : call_parameters(callee)) {
    if (parameter->section != ast::VarSection::Output && !is_en_eno(parameter->name)) positional.push_back(parameter);
  }
  return positional;
}

const Symbol* positional_parameter(const std::vector<const Symbol*>& positional, size_t index) {
  if (index < positional.size()) return positional[index];
  if (!positional.empty() && positional.back()->has(kExtensible)) return positional.back();
  return nullptr;
}

const Symbol* named_parameter(const std::vector<const Symbol*>& parameters, std::string_view name) {
  for (const Symbol* parameter : parameters) {
    if (names_equal(parameter->name, name)) return parameter;
  }
  for (const Symbol* parameter : parameters) {
    const Attribute* alias = parameter->attribute("rung.alias");
    if (alias && names_equal(alias->value, name)) return parameter;
  }
  return nullptr;
}

std::optional<CallSite> call_site_of(const ProjectModel& model, SourceId source, const CursorContext& context) {
  if (!context.call || !context.scope) return std::nullopt;
  const ExprInfo function = type_written_expression(model, source, *context.scope, context.call->callee);
  const Symbol* callee = callee_of(function);
  if (!callee) return std::nullopt;
  CallSite site{.callee = callee, .call = *context.call};
  site.instance_call = callee != function.symbol;
  if (!site.call.named.empty()) {
    site.active = named_parameter(call_parameters(callee), site.call.named);
  } else {
    // Informal arguments before the cursor take the first inputs; formal ones do not move the position.
    const std::vector<const Symbol*> positional = positional_parameters(callee);
    const size_t informal = site.call.argument_index - std::min(site.call.argument_index, site.call.given.size());
    site.active = site.call.given.empty() ? positional_parameter(positional, informal)
                                          : next_unnamed_parameter(positional, informal, site.call.given);
  }
  return site;
}

std::optional<CallSite> call_site_at(const Workspace& workspace, SourceId source, uint32_t file_offset) {
  const ProjectModel& model = workspace.model();
  if (source >= model.source_count()) return std::nullopt;
  const std::optional<uint32_t> tree_offset = model.source(source).document->tree_offset_of(file_offset);
  if (!tree_offset) return std::nullopt;
  return call_site_of(model, source, cursor_context(model, source, *tree_offset));
}

}  // namespace rung::check::query
