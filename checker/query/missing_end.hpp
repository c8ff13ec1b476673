// The fix of S003 (a block that is never closed): where its END_* keyword belongs. The parser
// knows which keyword opened the block (the diagnostic's label); the place is read from the
// layout the author already gave the code: a statement block (IF, CASE, FOR, WHILE, REPEAT) or a
// VAR/STRUCT block ends after the last line indented deeper than its opening line (ELSIF, ELSE
// and UNTIL lines still belong to it), and never after the point where the parser found that it
// must have ended; a POU or TYPE ends there.
#pragma once

#include <string>
#include <vector>

#include "checker/lint/lint_rule.hpp"
#include "checker/project/format_settings.hpp"
#include "parser/document.hpp"

namespace rung::check::query {

struct ClosingInsertion {
  Diagnostic diagnostic;  // the S003 it fixes (FILE coordinates, as Document::diagnostics)
  std::string keyword;    // "END_IF", in the project's keyword case
  lint::TextEdit edit;    // FILE coordinates
};

// One insertion for each S003 of `document` whose opening keyword is known and whose closing
// keyword can be written in the file (container files: only inside the ST the file stores).
// END_IF and the other statement closers get a ';' when rung.toml [format] asks for one.
std::vector<ClosingInsertion> missing_end_insertions(const Document& document,
                                                     const project::FormatSettings& settings);

}  // namespace rung::check::query
