#include "checker/query/selection.hpp"

#include "checker/query/position.hpp"

namespace rung::check::query {

std::vector<TextRange> selection_ranges(const Document& document, uint32_t file_offset) {
  std::vector<TextRange> ranges;
  const SyntaxTree* tree = document.tree();
  if (!tree || tree->aborted()) return ranges;
  const std::optional<uint32_t> tree_offset = document.tree_offset_of(file_offset);
  if (!tree_offset) return ranges;
  const SyntaxNode root = tree->root();
  SyntaxNode node = name_at(root, *tree_offset);
  if (!node) node = root.descendant_for_range(*tree_offset, *tree_offset + 1);
  for (; node; node = node.parent()) {
    const TextRange range{document.file_offset_of(node.begin()), document.file_end_offset_of(node.end())};
    if (range.end < range.begin) continue;
    if (!ranges.empty()) {
      const TextRange& inner = ranges.back();
      const bool contains = range.begin <= inner.begin && inner.end <= range.end;
      if (!contains || (range.begin == inner.begin && range.end == inner.end)) continue;
    }
    ranges.push_back(range);
  }
  return ranges;
}

}  // namespace rung::check::query
