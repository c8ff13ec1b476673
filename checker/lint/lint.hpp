// The linter's front door: run the enabled lint rules over files of a checked Workspace. Used by
// `rung lint`, the language server and the tests.
#pragma once

#include <string>
#include <vector>

#include "checker/check.hpp"
#include "checker/lint/lint_rule.hpp"

namespace rung::lint {

struct FileFindings {
  check::SourceId source = check::kNoSource;
  std::string path;
  std::vector<Finding> findings;  // FILE coordinates, sorted; severities as rung.toml sets them
};

// The severity a rule runs with under `settings` ([lint.rules] by code or name), nullopt when it
// is off.
std::optional<Severity> rule_severity(const Rule& rule, const project::LintSettings& settings);

// Findings of one project file: every enabled rule, rung.toml severities, suppression comments.
// `cache` shares analyses across files (lint_all passes one); without it the call has its own.
FileFindings lint_source(const check::Workspace& workspace, check::SourceId source,
                         const project::LintSettings& settings, AnalysisCache* cache = nullptr);
// Every project file (not the stub libraries), in the workspace's file order.
std::vector<FileFindings> lint_all(const check::Workspace& workspace, const project::LintSettings& settings,
                                   unsigned threads = 0);
// The given files (e.g. the ones a command names), in the order given.
std::vector<FileFindings> lint_sources(const check::Workspace& workspace, const std::vector<check::SourceId>& ids,
                                       const project::LintSettings& settings, unsigned threads = 0);

// `text` with the edits applied (ranges in `text`; edits that overlap an earlier one are skipped
// and counted in *skipped).
std::string apply_edits(std::string_view text, std::vector<TextEdit> edits, size_t* skipped = nullptr);

}  // namespace rung::lint
