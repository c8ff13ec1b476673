// Which lines of a file an editor may fold: POUs and their members, VAR blocks, types, the
// branches and bodies of IF/CASE/FOR/WHILE/REPEAT, SFC steps and transitions, block comments and
// runs of line comments, {region} ... {endregion} pragmas. Read from the syntax tree alone.
#pragma once

#include <cstdint>
#include <vector>

#include "parser/document.hpp"

namespace rung::check::query {

enum class FoldKind : uint8_t { Code, Comment, Region };

struct Fold {
  uint32_t first_line = 0;  // 0-based lines of the FILE (a container's own lines)
  uint32_t last_line = 0;   // the last line folded away with it (> first_line)
  FoldKind kind = FoldKind::Code;
  bool operator==(const Fold&) const = default;
};

// The folds of `document`, ordered by first line, at most one per first line. A block that ends
// with END_xxx on a line of its own stops on the line before it, so the closing keyword stays
// visible under the folded opening line. An IF with ELSIF/ELSE folds branch by branch.
std::vector<Fold> folding_ranges(const Document& document);

}  // namespace rung::check::query
