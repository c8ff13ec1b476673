// How the formatter writes a comment: as typed, but without the spaces and tabs that end its lines
// (trailing blanks inside a comment are invisible in every editor and only make diffs noisy).
// The printer writes comments this way, and both safety checks accept exactly this change.
#pragma once

#include <string>
#include <string_view>

namespace rung::format {

// (* ... *), /* ... */ or // ... (a pragma is not a comment).
bool is_comment(std::string_view trivia);

// The comment as printed: blanks before each line end inside it, and at its end, removed.
std::string printed_comment(std::string_view comment);

// Whether printed_comment() differs from the comment (most comments: no, and no copy is needed).
bool has_line_end_blanks(std::string_view comment);

}  // namespace rung::format
