// How diagnostics reach a person (file:line:col, code, message, source line with a caret, help)
// or a machine (JSON).
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "cli/terminal.hpp"
#include "parser/diagnostic.hpp"
#include "parser/document.hpp"

namespace rung::cli {

// `file:12:3: error[S003]: IF at 10:1 has no END_IF` followed by the source line, a caret under
// the range, secondary labels and the help line.
std::string render_human(const Document& doc, const Diagnostic& diagnostic, const Style& style);

// A diagnostic with 1-based line/column positions in the file the user sees.
nlohmann::json render_json(const Document& doc, const Diagnostic& diagnostic);

// Counts for the closing line, e.g. "2 errors, 1 warning in 14 files".
struct Tally {
  size_t files = 0;
  size_t errors = 0;
  size_t warnings = 0;
  void add(const Diagnostic& d);
  std::string summary() const;
};

}  // namespace rung::cli
