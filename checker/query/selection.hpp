// Expand selection: from the name under the cursor outwards through the syntax tree — the name,
// the expression around it, the statement, the statement list, the block, the POU, the file.
#pragma once

#include <cstdint>
#include <vector>

#include "parser/document.hpp"

namespace rung::check::query {

// The ranges (FILE coordinates) that hold `file_offset`, innermost first, each strictly larger
// than the one before. A cursor right after a name counts as on it. Empty where the file has no
// parsed text (XML markup of a container, an unparsed file).
std::vector<TextRange> selection_ranges(const Document& document, uint32_t file_offset);

}  // namespace rung::check::query
