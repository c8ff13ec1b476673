// Column alignment in VAR blocks, STRUCTs and UNIONs: within a run of consecutive one-line
// declarations (a blank line, a comment line or a declaration over several lines ends the run),
// the ':' before the types line up (align_types), then the ':=' of the initial values
// (align_initial_values), then the trailing comments (align_comments). IL is aligned the same
// way: the operands of a run of instructions (align_types) and their trailing comments
// (align_comments). Only the spaces before those tokens grow, so alignment never changes a token.
#include <algorithm>

#include "formatter/printer.hpp"

namespace rung::format {
namespace {

class Aligner {
 public:
  Aligner(const WalkResult& walk, std::string_view text, const project::FormatSettings& settings, Layout& layout)
      : walk_(walk), text_(text), settings_(settings), layout_(layout) {}

  void run() {
    const std::vector<AlignedRow>& rows = walk_.rows;
    size_t i = 0;
    while (i < rows.size()) {
      if (!one_line(rows[i])) {
        ++i;
        continue;
      }
      size_t j = i + 1;
      while (j < rows.size() && one_line(rows[j]) && rows[j].group == rows[i].group &&
             layout_.line_of[rows[j].first] == layout_.line_of[rows[j - 1].first] + 1 &&
             walk_.leaves[rows[j].first].newlines == 1) {
        ++j;
      }
      if (j - i >= 2) align_run(i, j);
      i = j;
    }
  }

 private:
  bool starts_line(uint32_t leaf) const { return layout_.lines[layout_.line_of[leaf]].first == leaf; }

  // A row alone on its line (trailing comments allowed) that starts the line.
  bool one_line(const AlignedRow& d) const {
    if (d.first == kNoLeaf || d.last == kNoLeaf || d.last < d.first) return false;
    if (!starts_line(d.first) || layout_.line_of[d.first] != layout_.line_of[d.last]) return false;
    for (uint32_t m = d.first; m <= d.last; ++m)
      if (walk_.leaves[m].multiline) return false;
    for (uint32_t m = d.last + 1; m < walk_.leaves.size() && !starts_line(m); ++m)
      if (!walk_.leaves[m].trivia()) return false;
    return true;
  }

  // The trailing comment of a row, or kNoLeaf.
  uint32_t trailing_comment(const AlignedRow& d) const {
    const uint32_t next = d.last + 1;
    if (next < walk_.leaves.size() && !starts_line(next) && walk_.leaves[next].trivia()) return next;
    return kNoLeaf;
  }

  // Pads the spaces before token `pick(d)` of every row of the run so that all of them
  // start in the same column; `base` is the space the widest one keeps.
  template <typename Pick>
  void align_column(size_t from, size_t to, Pick pick) {
    uint32_t widest = 0;
    uint32_t base = UINT32_MAX;
    for (size_t k = from; k < to; ++k) {
      const AlignedRow& d = walk_.rows[k];
      const uint32_t token = pick(d);
      if (token == kNoLeaf || token <= d.first) continue;
      widest = std::max(widest, span_width(walk_, layout_, text_, d.first, token - 1));
      base = std::min(base, layout_.spaces[token]);
    }
    if (base == UINT32_MAX) return;
    for (size_t k = from; k < to; ++k) {
      const AlignedRow& d = walk_.rows[k];
      const uint32_t token = pick(d);
      if (token == kNoLeaf || token <= d.first) continue;
      layout_.spaces[token] = widest + base - span_width(walk_, layout_, text_, d.first, token - 1);
    }
  }

  void align_run(size_t from, size_t to) {
    if (settings_.align_types) align_column(from, to, [](const AlignedRow& d) { return d.column; });
    if (settings_.align_initial_values) align_column(from, to, [](const AlignedRow& d) { return d.assign; });
    if (settings_.align_comments) {
      align_column(from, to, [this](const AlignedRow& d) { return trailing_comment(d); });
    }
  }

  const WalkResult& walk_;
  std::string_view text_;
  const project::FormatSettings& settings_;
  Layout& layout_;
};

}  // namespace

void align_rows(const WalkResult& walk, std::string_view text, const project::FormatSettings& settings,
                Layout& layout) {
  if (!settings.align_types && !settings.align_initial_values && !settings.align_comments) return;
  Aligner(walk, text, settings, layout).run();
}

}  // namespace rung::format
