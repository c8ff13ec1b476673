// Turns tree-sitter's ERROR and MISSING nodes into diagnostics a PLC engineer understands:
// "missing ';' after statement", "IF at 12:3 has no END_IF", "unexpected 'ELSE IF' — did you
// mean ELSIF?". Never reports a bare "ERROR node".
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "parser/diagnostic.hpp"
#include "parser/syntax_tree.hpp"

namespace rung {

struct SyntaxDiagnosticOptions {
  // Renders a tree offset as "line:col" of the file the user sees (containers map positions).
  std::function<std::string(uint32_t offset)> describe_position;
  // After this many errors one S012 note ends the list: later errors are mostly echoes.
  size_t max_errors = 100;
};

std::vector<Diagnostic> collect_syntax_diagnostics(const SyntaxTree& tree, const SyntaxDiagnosticOptions& options);

}  // namespace rung
