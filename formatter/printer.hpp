// The second pass of the formatter: turns the walked leaves into lines (the input's line breaks,
// the walk's indentation levels, the spacing rules, column alignment in declaration blocks) and
// prints them. Only whitespace is decided here: every token is copied from the input, keywords
// and elementary type names in the configured case.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "checker/project/format_settings.hpp"
#include "formatter/layout_walk.hpp"

namespace rung::format {

struct Line {
  uint32_t first = 0;  // its first leaf
  uint32_t last = 0;   // its last leaf
  int32_t level = 0;
  uint32_t width = 0;  // display columns, tabs counted as indent_width; up to a comment's first line break
  // The columns up to the end of the line's last token that is no comment or pragma: line
  // breaking looks at this, since breaking code cannot shorten a long trailing comment.
  uint32_t code_width = 0;
};

struct Layout {
  std::vector<uint32_t> spaces;   // per leaf: spaces before it when it does not start a line
  std::vector<uint32_t> line_of;  // per leaf: its line
  std::vector<Line> lines;
};

Layout lay_out(const WalkResult& walk, std::string_view text, const project::FormatSettings& settings);

std::string print(const WalkResult& walk, const Layout& layout, std::string_view text,
                  const project::FormatSettings& settings);

// Display columns of a token: code points, up to the first line break, without blanks at its end
// (only a comment can end in blanks, and it is printed without them).
uint32_t display_width(std::string_view token);

// The columns from the start of leaf `a` to the end of leaf `b` on one line.
uint32_t span_width(const WalkResult& walk, const Layout& layout, std::string_view text, uint32_t a, uint32_t b);

// Pads declarations and IL instructions so that their columns line up (align.cpp).
void align_rows(const WalkResult& walk, std::string_view text, const project::FormatSettings& settings, Layout& layout);

}  // namespace rung::format
