// Code actions on the code under the cursor, with or without a finding there: add an ELSE to a
// CASE (the fix of lint rule L030, offered on any CASE without one, also when L030 is off), and
// the rewrites between formal and informal calls (checker/query/case_else, call_form).
#include <fmt/format.h>

#include "checker/query/call_form.hpp"
#include "checker/query/case_else.hpp"
#include "lsp/features/code_actions_support.hpp"

namespace rung::lsp {
namespace {

namespace query = check::query;

void add_case_else(ActionRequest& request) {
  const DocumentRef& document = request.document();
  const Document& file = document.document();
  const std::optional<uint32_t> at = file.tree_offset_of(request.range().begin);
  if (!at) return;
  const SyntaxNode statement = query::case_statement_at(file, *at);
  if (!statement) return;
  const std::optional<lint::TextEdit> edit = query::add_case_else(file, statement, document.settings().format);
  if (!edit) return;
  // The L030 finding is reported on `CASE <value>`.
  const SyntaxNode value = statement.child_by_field("value");
  const TextRange finding{file.file_offset_of(statement.begin()), file.file_end_offset_of(value.end())};
  request.add("Add ELSE to the CASE", kQuickFix, {*edit}, "L030", finding, true);
}

void add_call_rewrites(ActionRequest& request) {
  const DocumentRef& document = request.document();
  const uint32_t at = request.range().begin;
  if (const auto formal = query::to_formal_call(document.workspace(), document.source, at)) {
    request.add(fmt::format("Convert to a formal call of {} (name the arguments)", formal->callee), kRefactorRewrite,
                formal->edits);
  }
  if (const auto informal = query::to_informal_call(document.workspace(), document.source, at)) {
    request.add(fmt::format("Convert to an informal call of {} (arguments by position)", informal->callee),
                kRefactorRewrite, informal->edits);
  }
}

}  // namespace

void add_refactorings(ActionRequest& request) {
  if (request.wants(kQuickFix)) add_case_else(request);
  if (request.wants(kRefactorRewrite)) add_call_rewrites(request);
}

}  // namespace rung::lsp
