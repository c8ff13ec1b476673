// The skeletons completion offers (IF ... END_IF, a FUNCTION_BLOCK with its VAR blocks ...), in the
// project's keyword case and indentation: as LSP snippets with tab stops when the client takes
// snippets, as plain text otherwise.
#pragma once

#include <string>
#include <string_view>

#include "checker/project/format_settings.hpp"

namespace rung::lsp {

// The word a keyword is written as under `settings` (query::keyword_in_case: "preserve" follows
// the case of what the user typed, upper case when nothing is typed yet). `elementary_type`:
// INT, TIME ... (they follow the keyword case only with elementary_types_follow_keyword_case).
std::string keyword_in_case(std::string_view keyword, const project::FormatSettings& settings, std::string_view typed,
                            bool elementary_type = false);

struct Snippet {
  std::string label;   // what the list shows: "IF", "TYPE STRUCT"
  std::string detail;  // its shape in one line: "IF … THEN … END_IF"
  std::string text;    // what is inserted
};

// The skeleton called `name` (query::CandidateKind::Snippet words); empty text for an unknown name.
Snippet snippet(std::string_view name, const project::FormatSettings& settings, std::string_view typed,
                bool snippet_support);

}  // namespace rung::lsp
