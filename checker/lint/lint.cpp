#include "checker/lint/lint.hpp"

#include <algorithm>

#include "parser/diagnostic_codes.hpp"
#include "parser/parallel_for.hpp"

namespace rung::lint {

std::optional<Severity> rule_severity(const Rule& rule, const project::LintSettings& settings) {
  const DiagnosticCodeInfo* info = find_diagnostic_code(rule.code);
  const Severity fallback = info ? info->default_severity : Severity::Warning;
  std::optional<Severity> level = rule.enabled_by_default ? std::optional<Severity>(fallback) : std::nullopt;
  // A setting by code and one by name may both be present; the last in key order wins, which is
  // deterministic (the map is sorted).
  for (const auto& [key, value] : settings.rules) {
    if (find_rule(key) != &rule) continue;
    if (value == "off") level = std::nullopt;
    else if (value == "on") level = fallback;
    else if (value == "error") level = Severity::Error;
    else if (value == "warning") level = Severity::Warning;
    else if (value == "info") level = Severity::Info;
    else if (value == "hint") level = Severity::Hint;
  }
  return level;
}

FileFindings lint_source(const check::Workspace& workspace, check::SourceId id, const project::LintSettings& settings) {
  const check::ProjectModel& model = workspace.model();
  const check::Source& source = model.source(id);
  FileFindings result;
  result.source = id;
  result.path = source.document->path();
  if (!source.document->tree()) return result;
  for (const Rule& rule : all_rules()) {
    const std::optional<Severity> severity = rule_severity(rule, settings);
    if (!severity || !rule.check) continue;
    std::vector<Finding> found;
    LintContext context(model, id, settings, found);
    rule.check(context);
    for (Finding& finding : found) {
      finding.diagnostic.severity = *severity;
      result.findings.push_back(std::move(finding));
    }
  }
  // Rules report in tree coordinates; a container file's user sees the container's offsets.
  const Document& document = *source.document;
  for (Finding& finding : result.findings) {
    Diagnostic& d = finding.diagnostic;
    d.range = {document.file_offset_of(d.range.begin), document.file_end_offset_of(d.range.end)};
    for (DiagnosticLabel& label : d.labels) {
      label.range = {document.file_offset_of(label.range.begin), document.file_end_offset_of(label.range.end)};
    }
    if (finding.fix) {
      for (TextEdit& edit : finding.fix->edits) {
        edit.range = {document.file_offset_of(edit.range.begin), document.file_end_offset_of(edit.range.end)};
      }
    }
  }
  std::stable_sort(result.findings.begin(), result.findings.end(), [](const Finding& a, const Finding& b) {
    if (a.diagnostic.range.begin != b.diagnostic.range.begin) return a.diagnostic.range.begin < b.diagnostic.range.begin;
    return a.diagnostic.code < b.diagnostic.code;
  });
  return result;
}

std::vector<FileFindings> lint_all(const check::Workspace& workspace, const project::LintSettings& settings,
                                   unsigned threads) {
  std::vector<check::SourceId> ids;
  for (check::SourceId id = 0; id < workspace.model().source_count(); ++id) {
    if (!workspace.model().source(id).library) ids.push_back(id);
  }
  std::vector<FileFindings> results(ids.size());
  parallel_for(ids.size(), threads, [&](size_t i) { results[i] = lint_source(workspace, ids[i], settings); });
  return results;
}

std::string apply_edits(std::string_view text, std::vector<TextEdit> edits, size_t* skipped) {
  std::stable_sort(edits.begin(), edits.end(),
                   [](const TextEdit& a, const TextEdit& b) { return a.range.begin < b.range.begin; });
  std::string out;
  out.reserve(text.size());
  uint32_t at = 0;
  size_t dropped = 0;
  for (const TextEdit& edit : edits) {
    if (edit.range.begin < at || edit.range.end < edit.range.begin || edit.range.end > text.size()) {
      ++dropped;
      continue;
    }
    out.append(text.substr(at, edit.range.begin - at));
    out.append(edit.replacement);
    at = edit.range.end;
  }
  out.append(text.substr(at));
  if (skipped) *skipped = dropped;
  return out;
}

}  // namespace rung::lint
