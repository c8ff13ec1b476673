// How the formatter writes a comment: as typed, but without the spaces and tabs that end its lines
// (trailing blanks inside a comment are invisible in every editor and only make diffs noisy).
// The printer writes comments this way, and both safety checks accept exactly this change.
#pragma once

#include <string>
#include <string_view>

namespace rung::format {

// (* ... *), /* ... */ or // ... (a pragma is not a comment).
bool is_comment(std::string_view trivia);

// Appends the comment as printed: blanks before each line end inside it, and at its end, removed.
void append_printed_comment(std::string& out, std::string_view comment);

// The comment as printed (append_printed_comment into a new string).
std::string printed_comment(std::string_view comment);

}  // namespace rung::format
