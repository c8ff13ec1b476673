#include "checker/lint/apply_fixes.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "checker/lint/lint.hpp"
#include "parser/diagnostic_codes.hpp"
#include "parser/source/encode.hpp"

namespace rung::lint {
namespace {

// Syntax errors, or bytes the decoder replaced (writing the text back would change them).
const Diagnostic* blocking_problem(const Document& document) {
  for (const Diagnostic& d : document.diagnostics()) {
    if (d.severity == Severity::Error || d.code == codes::kEncoding) return &d;
  }
  if (!document.tree()) return document.diagnostics().empty() ? nullptr : &document.diagnostics().front();
  return nullptr;
}

// Two edits touch: they overlap, or both insert at the same place (their order would be a guess).
bool touches(const TextEdit& a, const TextEdit& b) {
  if (a.range.begin == b.range.begin) return true;
  return a.range.begin < b.range.end && b.range.begin < a.range.end;
}

}  // namespace

FixedFile fix_file(const Document& document, const std::vector<Finding>& findings) {
  FixedFile result;
  std::vector<const Fix*> fixes;
  for (const Finding& finding : findings) {
    if (finding.fix && !finding.fix->edits.empty()) fixes.push_back(&*finding.fix);
  }
  if (fixes.empty()) return result;
  if (const Diagnostic* problem = blocking_problem(document)) {
    result.outcome = FixedFile::Outcome::NotFixed;
    result.problem = fmt::format("not fixed: the file has {}[{}] problems ({}); run 'rung check'",
                                 severity_name(problem->severity), problem->code, problem->message);
    return result;
  }
  // First come, first served, in text order: a fix that touches a chosen one waits for the next
  // round, when it is found again on the changed text.
  std::vector<TextEdit> chosen;
  for (const Fix* fix : fixes) {
    const bool clashes = std::any_of(fix->edits.begin(), fix->edits.end(), [&](const TextEdit& edit) {
      return std::any_of(chosen.begin(), chosen.end(), [&](const TextEdit& other) { return touches(edit, other); });
    });
    if (clashes) {
      ++result.deferred;
      continue;
    }
    chosen.insert(chosen.end(), fix->edits.begin(), fix->edits.end());
    ++result.applied;
  }
  size_t skipped = 0;
  const std::string text = apply_edits(document.file_text(), chosen, &skipped);
  if (skipped > 0) {
    result.outcome = FixedFile::Outcome::NotFixed;
    result.problem = "internal error: a fix edits text outside the file; nothing was changed";
    return result;
  }
  if (text == document.file_text()) {
    result.applied = 0;
    return result;
  }
  std::optional<std::string> bytes = source::encode(text, document.encoding(), document.had_bom());
  if (!bytes) {
    result.outcome = FixedFile::Outcome::NotFixed;
    result.problem =
        fmt::format("not fixed: the fixed text cannot be written in {}", source::encoding_name(document.encoding()));
    return result;
  }
  // The safety net: the fixed file must read as cleanly as the original did.
  const Document fixed = Document::from_bytes(document.path(), *bytes);
  if (const Diagnostic* problem = blocking_problem(fixed)) {
    result.outcome = FixedFile::Outcome::NotFixed;
    result.problem = fmt::format("internal error: the fixes would cause {}[{}] ({}); nothing was changed",
                                 severity_name(problem->severity), problem->code, problem->message);
    return result;
  }
  result.outcome = FixedFile::Outcome::Changed;
  result.bytes = std::move(*bytes);
  return result;
}

}  // namespace rung::lint
