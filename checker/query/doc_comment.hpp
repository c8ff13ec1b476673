// The comment that documents a declaration, for hover and completion: the comment lines right
// above it, or the comment at the end of its line (`counter : INT; // parts made today`); for a
// POU also the comment on its header line or the lines right after the header (where CODESYS
// and TwinCAT users describe a block).
#pragma once

#include <string>

#include "checker/project_model.hpp"

namespace rung::check::query {

// The text of `symbol`'s doc comment without comment markers, lines joined with '\n' and their
// common indentation removed; "" when it has none. The text is taken from the FILE (the parsed
// text may differ inside comments). The stub libraries' `source:` lines (where in the manuals a
// fact comes from) are left out.
std::string doc_comment(const ProjectModel& model, const Symbol& symbol);

// The text inside one comment's delimiters (// ..., (* ... *), /* ... */), lines trimmed and
// their common indentation removed.
std::string comment_content(std::string_view comment);

}  // namespace rung::check::query
