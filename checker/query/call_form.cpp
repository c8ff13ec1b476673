#include "checker/query/call_form.hpp"

#include "checker/query/call_site.hpp"
#include "checker/query/position.hpp"
#include "checker/query/resolve.hpp"
#include "checker/query/source_edits.hpp"
#include "checker/semantic/body_checker.hpp"

namespace rung::check::query {
namespace {

// A call whose arguments can be read with certainty: the call around the cursor, its callee and
// its arguments.
struct WrittenCall {
  SyntaxNode call;
  const Symbol* callee = nullptr;
  std::vector<CallArgument> arguments;
};

// OpenPCS writes outputs after '|' as `actual := formal`: neither form of the rewrite applies.
bool has_output_bar(SyntaxNode argument_list) {
  for (uint32_t i = 0; i < argument_list.child_count(); ++i) {
    if (!argument_list.child(i).is_named() && argument_list.child(i).text() == "|") return true;
  }
  return false;
}

std::optional<WrittenCall> written_call_at(const Workspace& workspace, SourceId source, uint32_t file_offset) {
  const std::optional<QueryPoint> point = query_point(workspace, source, file_offset);
  if (!point || !point->scope) return std::nullopt;
  SyntaxNode call = point->node;
  while (call && call.kind() != "call_expression") call = call.parent();
  if (!call || call.has_error()) return std::nullopt;
  const SyntaxNode function = call.child_by_field("function");
  const SyntaxNode argument_list = call.child_by_field("arguments");
  if (!function || !argument_list || has_output_bar(argument_list)) return std::nullopt;
  std::vector<Diagnostic> ignored;
  const Symbol* callee = callee_of(BodyChecker(workspace.model(), *point->scope, ignored).type_of(function));
  if (!callee) return std::nullopt;
  WrittenCall site{call, callee, call_arguments(argument_list)};
  if (site.arguments.empty()) return std::nullopt;
  return site;
}

std::optional<CallRewrite> rewrite(const Workspace& workspace, SourceId source, const WrittenCall& site,
                                   const std::vector<lint::TextEdit>& tree_edits) {
  std::optional<std::vector<lint::TextEdit>> edits =
      file_edits_of(*workspace.model().source(source).document, tree_edits);
  if (!edits) return std::nullopt;
  return CallRewrite{std::string(site.callee->name), std::move(*edits)};
}

}  // namespace

std::optional<CallRewrite> to_formal_call(const Workspace& workspace, SourceId source, uint32_t file_offset) {
  const std::optional<WrittenCall> site = written_call_at(workspace, source, file_offset);
  if (!site) return std::nullopt;
  const std::vector<const Symbol*> inputs = positional_parameters(site->callee);
  if (site->arguments.size() > inputs.size()) return std::nullopt;  // extensible, or too many: no names to give
  std::vector<lint::TextEdit> edits;
  for (size_t i = 0; i < site->arguments.size(); ++i) {
    const CallArgument& argument = site->arguments[i];
    if (argument.name || argument.output || !argument.value) return std::nullopt;
    const uint32_t at = argument.value.begin();
    edits.push_back(lint::TextEdit{{at, at}, std::string(inputs[i]->name) + " := "});
  }
  return rewrite(workspace, source, *site, edits);
}

std::optional<CallRewrite> to_informal_call(const Workspace& workspace, SourceId source, uint32_t file_offset) {
  const std::optional<WrittenCall> site = written_call_at(workspace, source, file_offset);
  if (!site) return std::nullopt;
  if (site->callee->kind != SymbolKind::Function && site->callee->kind != SymbolKind::Method) return std::nullopt;
  const std::vector<const Symbol*> inputs = positional_parameters(site->callee);
  if (site->arguments.size() > inputs.size()) return std::nullopt;
  std::vector<lint::TextEdit> edits;
  for (size_t i = 0; i < site->arguments.size(); ++i) {
    const CallArgument& argument = site->arguments[i];
    if (!argument.name || argument.output || !argument.value || argument.value.kind() == "il_expression") {
      return std::nullopt;
    }
    if (named_parameter(call_parameters(site->callee), argument.name.text()) != inputs[i]) return std::nullopt;
    edits.push_back(lint::TextEdit{{argument.name.begin(), argument.value.begin()}, ""});
  }
  return rewrite(workspace, source, *site, edits);
}

}  // namespace rung::check::query
