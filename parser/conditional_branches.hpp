// Conditional compilation as the parser sees it. `{IF defined(X)} ... {ELSIF ...} ... {ELSE} ...
// {END_IF}` pragmas may split a control structure between branches (`{IF defined(DEBUG)} IF a THEN
// {ELSE} IF b THEN {END_IF} ... END_IF`); read as written, both branches together do not parse.
#pragma once

#include <cstddef>
#include <string>

#include "parser/syntax_tree.hpp"

namespace rung {

// Blanks (same length, line ends kept) every branch after the first of each conditional pragma
// group in `text`, which `tree` was parsed from, so that only the first branch is read. Returns
// how many bytes were blanked; 0 when the text has no {ELSIF}/{ELSE} branch.
size_t keep_first_conditional_branches(const SyntaxTree& tree, std::string& text);

}  // namespace rung
