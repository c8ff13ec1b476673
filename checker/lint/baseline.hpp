// The lint baseline: the findings a legacy project already had when it adopted `rung lint`
// (written by `rung lint --write-baseline`), so that only new findings are reported.
//
// An entry names a finding without its line number, which changes whenever code above it does:
// file (relative to the project root), rule code, enclosing POU and a fingerprint of the text of
// the finding's line (blanks removed, case ignored). Identical entries count: two identical
// findings with one entry leave one reported.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "checker/check.hpp"
#include "checker/lint/lint.hpp"

namespace rung::lint {

struct BaselineEntry {
  std::string path;         // relative to the project root, '/' separators
  std::string code;         // "L030"
  std::string pou;          // "FB_Motor.Start"; empty outside POUs
  std::string fingerprint;  // 16 hex digits
  std::string message;      // for the people who read the file; not compared
};

// The entry describing `finding` of `file` (FILE coordinates) in a project rooted at `root`.
BaselineEntry baseline_entry(const check::Workspace& workspace, const FileFindings& file, const Finding& finding,
                             const std::filesystem::path& root);

// The baseline file: JSON, entries sorted, so that rewriting an unchanged baseline changes no byte.
std::string baseline_json(std::vector<BaselineEntry> entries);
// nullopt and `error` set when the text is not a baseline file.
std::optional<std::vector<BaselineEntry>> parse_baseline(std::string_view json, std::string* error);

struct BaselineResult {
  size_t matched = 0;    // findings dropped
  size_t unmatched = 0;  // entries of the linted files that matched no finding (fixed since)
};

// Drops the findings the baseline lists from `files`. Only entries of files in `files` count as
// unmatched (linting one file does not make the other files' entries stale).
BaselineResult apply_baseline(const std::vector<BaselineEntry>& baseline, const check::Workspace& workspace,
                              std::vector<FileFindings>& files, const std::filesystem::path& root);

// The path as baseline entries write it.
std::string baseline_path(const std::string& file, const std::filesystem::path& root);

}  // namespace rung::lint
