// Breaking of lines whose code (a trailing comment not counted: breaking code cannot shorten it)
// is longer than max_line_width: an IF/ELSIF/WHILE/UNTIL condition at its
// top-level OR (or XOR, or AND) with the operator starting each continuation line, else the
// outermost call on the line with one argument per line. Breaks are only added, never removed,
// and the layout rules indent the new lines like any line the user broke, so a broken layout
// formats to itself.
#pragma once

#include <string_view>
#include <vector>

#include "checker/project/format_settings.hpp"
#include "formatter/layout_walk.hpp"
#include "formatter/printer.hpp"

namespace rung::format {

// Adds to `breaks` (sorted leaf indices) the breaks for the lines of `layout` that are too long.
// Returns false when there is nothing more to break.
bool add_line_breaks(const WalkResult& walk, const Layout& layout, std::string_view text,
                     const project::FormatSettings& settings, std::vector<uint32_t>& breaks);

}  // namespace rung::format
