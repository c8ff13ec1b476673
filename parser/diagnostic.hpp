// Diagnostics: the one shape every stage (parser, checker, linter) reports problems in.
// Ranges are byte offsets in the text that was parsed; front ends turn them into
// line/column of the file the user sees (see Document::file_position).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace rung {

enum class Severity { Error, Warning, Info, Hint };

std::string_view severity_name(Severity severity);

struct TextRange {
  uint32_t begin = 0;
  uint32_t end = 0;
};

// A secondary location, e.g. "IF opened here".
struct DiagnosticLabel {
  TextRange range;
  std::string message;
};

struct Diagnostic {
  std::string code;  // stable code from the registry, e.g. "S003"
  Severity severity = Severity::Error;
  std::string message;
  TextRange range;
  std::vector<DiagnosticLabel> labels;
  std::string help;  // how to fix it, one sentence; may be empty
};

// Orders diagnostics by position, then code, so output never depends on discovery order.
void sort_diagnostics(std::vector<Diagnostic>& diagnostics);

}  // namespace rung
