// SARIF 2.1.0 output (`--format sarif`) for code-scanning services: one run of the rung driver
// with every registered code as a rule and one result per diagnostic, with its fix when the
// linter offers one.
#pragma once

#include <nlohmann/json.hpp>
#include <vector>

#include "checker/lint/lint_rule.hpp"
#include "parser/document.hpp"

namespace rung::cli {

struct SarifFinding {
  const Document* document = nullptr;
  const Diagnostic* diagnostic = nullptr;  // FILE coordinates
  const lint::Fix* fix = nullptr;          // FILE coordinates; null without a fix
};

nlohmann::json sarif_report(const std::vector<SarifFinding>& findings);

// A FILE range as 1-based lines and columns: {"startLine", "startColumn", "endLine", "endColumn"}.
nlohmann::json sarif_region(const Document& document, TextRange range);

}  // namespace rung::cli
