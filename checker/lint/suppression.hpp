// Suppression comments: the places where a file says "do not report this here".
//
//   x := x;  // rung-lint: ignore L035            this line
//   (* rung-lint: ignore L030, unused-variable *)  alone on its line: the next line with code
//   (* rung-lint: ignore-pou L070 *)               the POU that follows, or the one around it
//   {attribute 'rung-lint' := 'ignore L070'}       the POU (or the declaration line) that follows
//   // rung-lint: ignore-file L061                 the whole file
//
// Codes are rule codes or names, separated by commas or blanks; none means every rule. A reason
// may follow after "--". Tokens that name no rule are skipped (they never widen a suppression to
// every rule).
#pragma once

#include <span>
#include <string>
#include <vector>

#include "parser/diagnostic.hpp"
#include "parser/syntax_tree.hpp"

namespace rung::lint {

struct Suppression {
  TextRange scope;                 // TREE coordinates: findings that start inside are dropped
  std::vector<std::string> codes;  // rule codes ("L030"); empty: every rule
};

// The suppressions written in the comments and pragmas below `root` (tree coordinates).
std::vector<Suppression> read_suppressions(SyntaxNode root);

// Whether a finding (range in TREE coordinates) is suppressed.
bool is_suppressed(std::span<const Suppression> suppressions, const Diagnostic& finding);

}  // namespace rung::lint
