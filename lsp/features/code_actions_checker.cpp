// Code actions for rung check's findings where the fix is certain: declare an undeclared variable
// (E001, the type read from its use), the name the checker's "did you mean" names (E001, E002,
// E005, E301), the END_* a block lacks (S003), the members an interface asks for (E204). The
// decisions are checker/query's (declare_variable, name_suggestions, missing_end,
// interface_members); this file names the actions.
#include <fmt/format.h>

#include <algorithm>

#include "checker/query/declare_variable.hpp"
#include "checker/query/interface_members.hpp"
#include "checker/query/missing_end.hpp"
#include "checker/query/name_suggestions.hpp"
#include "checker/query/position.hpp"
#include "lsp/features/code_actions_support.hpp"
#include "parser/diagnostic_codes.hpp"

namespace rung::lsp {
namespace {

namespace query = check::query;

// `preferred`: no likelier fix exists (a "did you mean" is: most undeclared names are typos).
void declare_variable(ActionRequest& request, const Diagnostic& diagnostic, bool preferred) {
  const DocumentRef& document = request.document();
  const std::optional<query::UndeclaredVariable> variable =
      query::undeclared_variable_at(document.workspace(), document.source, diagnostic.range.begin);
  if (!variable) return;
  const project::FormatSettings& format = document.settings().format;
  // Local first: an undeclared name is most often a forgotten local.
  for (const ast::VarSection section : {ast::VarSection::Var, ast::VarSection::Input, ast::VarSection::Output}) {
    const std::optional<lint::TextEdit> edit = query::declare_variable(document.workspace(), *variable, section, format);
    if (!edit) continue;
    request.add(fmt::format("Declare '{} : {}' in {}", variable->name, variable->type, ast::var_section_name(section)),
                kQuickFix, {*edit}, diagnostic.code, diagnostic.range, preferred && section == ast::VarSection::Var);
  }
}

// Whether a replacement was offered.
bool suggest_name(ActionRequest& request, const Diagnostic& diagnostic) {
  const DocumentRef& document = request.document();
  const std::optional<query::NameSuggestion> suggestion =
      query::suggest_name(document.workspace(), document.source, diagnostic.range.begin);
  if (!suggestion) return false;
  const std::string_view text = document.document().file_text();
  const std::string_view written =
      text.substr(suggestion->range.begin, suggestion->range.end - suggestion->range.begin);
  request.add(fmt::format("Change '{}' to '{}'", written, suggestion->replacement), kQuickFix,
              {lint::TextEdit{suggestion->range, suggestion->replacement}}, diagnostic.code, diagnostic.range, true);
  return true;
}

void implement_interface(ActionRequest& request, const Diagnostic& diagnostic) {
  const DocumentRef& document = request.document();
  const std::optional<uint32_t> at = document.document().tree_offset_of(diagnostic.range.begin);
  const check::Symbol* block = at ? query::scope_at(document.model(), document.source, *at) : nullptr;
  if (!block || (block->kind != check::SymbolKind::FunctionBlock && block->kind != check::SymbolKind::Class)) return;
  const std::string_view named = document.document().file_text().substr(
      diagnostic.range.begin, diagnostic.range.end - diagnostic.range.begin);
  for (const query::MissingMembers& missing : query::missing_interface_members(document.model(), *block)) {
    if (!check::names_equal(missing.interface->name, named)) continue;
    const std::optional<lint::TextEdit> edit =
        query::implement_members(document.workspace(), *block, missing.members, document.settings().format);
    if (!edit) continue;
    std::string names;
    for (const check::Symbol* member : missing.members) names += (names.empty() ? "" : ", ") + std::string(member->name);
    request.add(fmt::format("Implement the missing members of {} ({})", missing.interface->name, names), kQuickFix,
                {*edit}, diagnostic.code, diagnostic.range, true);
  }
}

}  // namespace

void add_checker_actions(ActionRequest& request) {
  if (!request.wants(kQuickFix)) return;
  const DocumentRef& document = request.document();
  for (const query::ClosingInsertion& insertion :
       query::missing_end_insertions(document.document(), document.settings().format)) {
    const Diagnostic& d = insertion.diagnostic;
    if (!request.touches(d.range) && !request.touches(d.labels.front().range)) continue;
    request.add(fmt::format("Insert {}", insertion.keyword), kQuickFix, {insertion.edit}, d.code, d.range, true);
  }
  const check::FileDiagnostics checked = document.workspace().check_source(document.source);
  std::vector<uint32_t> interfaces_done;  // E204 comes once per missing member, on the same name
  for (const Diagnostic& diagnostic : checked.diagnostics) {
    if (!request.touches(diagnostic.range) || request.session().cancelled()) continue;
    const std::string_view code = diagnostic.code;
    bool suggested = false;
    if (code == codes::kUndeclaredName || code == codes::kUnknownLibraryName || code == codes::kUnknownMember ||
        code == codes::kUnknownParameter) {
      suggested = suggest_name(request, diagnostic);
    }
    if (code == codes::kUndeclaredName) declare_variable(request, diagnostic, !suggested);
    if (code == codes::kMissingInterfaceMember &&
        std::find(interfaces_done.begin(), interfaces_done.end(), diagnostic.range.begin) == interfaces_done.end()) {
      interfaces_done.push_back(diagnostic.range.begin);
      implement_interface(request, diagnostic);
    }
  }
}

}  // namespace rung::lsp
