#include "checker/lint/lint.hpp"

#include <algorithm>

#include "checker/lint/suppression.hpp"
#include "checker/symbols/names.hpp"
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
    // Codes and names are unique, so this is find_rule(key) == &rule without a registry scan
    // (this runs for every rule of every file).
    if (!check::names_equal(key, rule.code) && !check::names_equal(key, rule.name)) continue;
    if (value == "off")
      level = std::nullopt;
    else if (value == "on")
      level = fallback;
    else if (value == "error")
      level = Severity::Error;
    else if (value == "warning")
      level = Severity::Warning;
    else if (value == "info")
      level = Severity::Info;
    else if (value == "hint")
      level = Severity::Hint;
  }
  return level;
}

namespace {

// A rule that runs, with the severity rung.toml gives it.
struct EnabledRule {
  const Rule* rule = nullptr;
  Severity severity = Severity::Warning;
};

std::vector<EnabledRule> enabled_rules(const project::LintSettings& settings) {
  std::vector<EnabledRule> enabled;
  for (const Rule& rule : all_rules()) {
    const std::optional<Severity> severity = rule_severity(rule, settings);
    if (severity && rule.check) enabled.push_back({&rule, *severity});
  }
  return enabled;
}

FileFindings lint_with(const check::Workspace& workspace, check::SourceId id, const project::LintSettings& settings,
                       const std::vector<EnabledRule>& rules, AnalysisCache& shared) {
  const check::ProjectModel& model = workspace.model();
  const check::Source& source = model.source(id);
  FileFindings result;
  result.source = id;
  result.path = source.document->path();
  if (!source.document->tree()) return result;
  FileShared file;  // the node list and POUs every rule of this file reads
  for (const EnabledRule& enabled : rules) {
    std::vector<Finding> found;
    LintContext context(model, id, settings, found, &shared, &file);
    enabled.rule->check(context);
    for (Finding& finding : found) {
      finding.diagnostic.severity = enabled.severity;
      result.findings.push_back(std::move(finding));
    }
  }
  shared.release_nodes(id);  // other files' analyses rarely need this file's nodes again
  // Suppression comments speak in tree coordinates, like the rules.
  const std::vector<Suppression> suppressions = read_suppressions(source.document->tree()->root());
  if (!suppressions.empty()) {
    std::erase_if(result.findings,
                  [&](const Finding& finding) { return is_suppressed(suppressions, finding.diagnostic); });
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
    if (a.diagnostic.range.begin != b.diagnostic.range.begin)
      return a.diagnostic.range.begin < b.diagnostic.range.begin;
    return a.diagnostic.code < b.diagnostic.code;
  });
  return result;
}

}  // namespace

FileFindings lint_source(const check::Workspace& workspace, check::SourceId id, const project::LintSettings& settings,
                         AnalysisCache* cache) {
  AnalysisCache own_cache;
  return lint_with(workspace, id, settings, enabled_rules(settings), cache ? *cache : own_cache);
}

std::vector<FileFindings> lint_all(const check::Workspace& workspace, const project::LintSettings& settings,
                                   unsigned threads) {
  std::vector<check::SourceId> ids;
  for (check::SourceId id = 0; id < workspace.model().source_count(); ++id) {
    if (!workspace.model().source(id).library) ids.push_back(id);
  }
  return lint_sources(workspace, ids, settings, threads);
}

std::vector<FileFindings> lint_sources(const check::Workspace& workspace, const std::vector<check::SourceId>& ids,
                                       const project::LintSettings& settings, unsigned threads) {
  std::vector<FileFindings> results(ids.size());
  AnalysisCache cache;  // one project-wide analysis serves every file
  const std::vector<EnabledRule> rules = enabled_rules(settings);
  parallel_for(ids.size(), threads,
               [&](size_t i) { results[i] = lint_with(workspace, ids[i], settings, rules, cache); });
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
