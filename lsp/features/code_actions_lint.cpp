// Code actions from the linter: the fix of each lint finding under the cursor (the fixes
// `rung lint --fix` applies, checker/lint), "fix all findings of this rule" and "fix everything
// fixable" for the whole file. Fixes of several findings are chosen and checked the way
// `rung lint --fix` does (lint::fix_file): a file whose fixes would not parse gets none.
#include <fmt/format.h>

#include <algorithm>
#include <map>

#include "checker/lint/apply_fixes.hpp"
#include "checker/lint/lint.hpp"
#include "checker/query/source_edits.hpp"
#include "lsp/features/code_actions_support.hpp"

namespace rung::lsp {
namespace {

// A fix the file can take as it is (container files: only inside the ST they store).
bool writable(const Document& document, const lint::Fix& fix) {
  return !fix.edits.empty() && std::all_of(fix.edits.begin(), fix.edits.end(), [&](const lint::TextEdit& edit) {
    return check::query::writable_in_file(document, edit);
  });
}

std::string sentence(std::string text) {
  if (!text.empty() && text[0] >= 'a' && text[0] <= 'z') text[0] = static_cast<char>(text[0] - 32);
  return text;
}

// The edits of `findings` that `rung lint --fix` would apply in one round; empty when that round
// would not be written (syntax errors, a result that does not parse).
std::vector<lint::TextEdit> fix_all_edits(const Document& document, const std::vector<lint::Finding>& findings) {
  const lint::FixedFile fixed = lint::fix_file(document, findings);
  if (fixed.outcome != lint::FixedFile::Outcome::Changed) return {};
  // fix_file takes fixes first come, first served in text order, leaving out any that touches
  // one already taken; the same choice gives its edits.
  std::vector<lint::TextEdit> chosen;
  const auto clashes = [&](const lint::TextEdit& edit) {
    return std::any_of(chosen.begin(), chosen.end(), [&](const lint::TextEdit& other) {
      return edit.range.begin == other.range.begin ||
             (edit.range.begin < other.range.end && other.range.begin < edit.range.end);
    });
  };
  for (const lint::Finding& finding : findings) {
    if (std::any_of(finding.fix->edits.begin(), finding.fix->edits.end(), clashes)) continue;
    chosen.insert(chosen.end(), finding.fix->edits.begin(), finding.fix->edits.end());
  }
  return chosen;
}

}  // namespace

void add_lint_actions(ActionRequest& request) {
  const DocumentRef& document = request.document();
  const lint::FileFindings lint = document.project->lint(document.source);
  const Document& file = document.document();
  std::vector<lint::Finding> fixable;
  for (const lint::Finding& finding : lint.findings) {
    if (finding.fix && writable(file, *finding.fix)) fixable.push_back(finding);
  }
  if (fixable.empty()) return;
  // Rules with a finding under the cursor, in code order.
  std::map<std::string, std::vector<lint::Finding>> by_rule;
  std::vector<std::string> touched;
  for (const lint::Finding& finding : fixable) {
    const Diagnostic& d = finding.diagnostic;
    by_rule[d.code].push_back(finding);
    if (!request.touches(d.range)) continue;
    request.add(sentence(finding.fix->description), kQuickFix, finding.fix->edits, d.code, d.range, true);
    if (std::find(touched.begin(), touched.end(), d.code) == touched.end()) touched.push_back(d.code);
  }
  for (const auto& [code, findings] : by_rule) {
    const bool here = std::find(touched.begin(), touched.end(), code) != touched.end();
    if (!here && !request.asks_for(kFixRule)) continue;
    if (findings.size() < 2 && !request.asks_for(kFixRule)) continue;  // the quick fix is the same edit
    const lint::Rule* rule = lint::find_rule(code);
    request.add(fmt::format("Fix all '{}' findings in this file ({})", rule ? rule->name : std::string_view(code), code),
                kFixRule, fix_all_edits(file, findings));
    if (request.session().cancelled()) return;
  }
  if (!touched.empty() || request.asks_for(kFixAll)) {
    request.add("Fix all auto-fixable lint findings in this file", kFixAll, fix_all_edits(file, fixable));
  }
}

}  // namespace rung::lsp
