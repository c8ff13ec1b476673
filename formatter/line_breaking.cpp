#include "formatter/line_breaking.hpp"

#include <algorithm>

#include "formatter/keyword_case.hpp"
#include "formatter/syntax_kinds.hpp"

namespace rung::format {
namespace {

// Precedence class of a boolean operator a condition may be broken at (0: none).
int boolean_class(std::string_view op) {
  if (equal_ignoring_case(op, "OR_ELSE")) return 1;
  if (equal_ignoring_case(op, "OR")) return 2;
  if (equal_ignoring_case(op, "XOR")) return 3;
  if (equal_ignoring_case(op, "AND_THEN")) return 4;
  if (equal_ignoring_case(op, "AND") || op == "&") return 5;
  return 0;
}

// Words the grammar's scanner reads as a declaration header at the start of a line: an argument
// that starts with one must not be moved to a line of its own.
bool is_header_word(std::string_view word) {
  for (std::string_view header : {"METHOD", "PROPERTY", "ACTION", "INTERFACE", "CLASS", "NAMESPACE"})
    if (equal_ignoring_case(word, header)) return true;
  return false;
}

class Breaker {
 public:
  Breaker(const WalkResult& walk, const Layout& layout, std::string_view text, const project::FormatSettings& settings)
      : walk_(walk), layout_(layout), text_(text), settings_(settings), handled_(layout.lines.size(), false) {}

  std::vector<uint32_t> run() {
    for (const SyntaxNode& condition : walk_.conditions) break_condition(condition);
    for (const SyntaxNode& arguments : walk_.argument_lists) break_arguments(arguments);
    return std::move(added_);
  }

 private:
  // The leaf that starts at `offset` (or the first one after it).
  uint32_t leaf_at(uint32_t offset) const {
    auto it = std::lower_bound(walk_.leaves.begin(), walk_.leaves.end(), offset,
                               [](const Leaf& leaf, uint32_t at) { return leaf.begin < at; });
    return static_cast<uint32_t>(it - walk_.leaves.begin());
  }

  bool starts_line(uint32_t leaf) const { return layout_.lines[layout_.line_of[leaf]].first == leaf; }

  bool too_long(uint32_t line) const {
    return !handled_[line] && layout_.lines[line].code_width > settings_.max_line_width;
  }

  void break_condition(SyntaxNode condition) {
    SyntaxNode node = condition;
    while (node.kind() == "parenthesized_expression" && node.named_child_count() == 1) node = node.named_child(0);
    if (node.kind() != "binary_expression") return;
    const int cls = boolean_class(node.child_by_field("operator").text());
    if (cls == 0) return;
    // The chain a OR b OR c is ((a OR b) OR c): its operators hang down the left side.
    std::vector<uint32_t> operators;
    while (node.kind() == "binary_expression") {
      SyntaxNode op = node.child_by_field("operator");
      if (boolean_class(op.text()) != cls) break;
      operators.push_back(leaf_at(op.begin()));
      node = node.child_by_field("left");
    }
    std::vector<uint32_t> lines;
    for (uint32_t op : operators) {
      if (op >= walk_.leaves.size() || starts_line(op)) continue;
      const uint32_t line = layout_.line_of[op];
      if (!too_long(line)) continue;
      added_.push_back(op);
      lines.push_back(line);
    }
    for (uint32_t line : lines) handled_[line] = true;
  }

  void break_arguments(SyntaxNode arguments) {
    const uint32_t open = leaf_at(arguments.begin());
    if (open >= walk_.leaves.size()) return;
    const uint32_t line = layout_.line_of[open];
    if (!too_long(line)) return;
    const std::vector<SyntaxNode> items = arguments.named_children();
    std::vector<uint32_t> breaks;
    size_t count = 0;
    for (const SyntaxNode& item : items) {
      if (item.is_extra()) continue;
      ++count;
      const uint32_t first = leaf_at(item.begin());
      if (first >= walk_.leaves.size()) return;
      const std::string_view word =
          text_.substr(walk_.leaves[first].begin, walk_.leaves[first].end - walk_.leaves[first].begin);
      if (is_header_word(word)) return;
      // A comment right before the argument moves with it (a // comment ends its line anyway).
      uint32_t at = first;
      while (at > open + 1 && !starts_line(at) && walk_.leaves[at - 1].trivia() && !walk_.leaves[at - 1].line_comment)
        --at;
      if (!starts_line(at)) breaks.push_back(at);
    }
    if (count < 2 || breaks.empty()) return;
    added_.insert(added_.end(), breaks.begin(), breaks.end());
    handled_[line] = true;
  }

  const WalkResult& walk_;
  const Layout& layout_;
  std::string_view text_;
  const project::FormatSettings& settings_;
  std::vector<bool> handled_;  // lines already broken in this round
  std::vector<uint32_t> added_;
};

}  // namespace

bool add_line_breaks(const WalkResult& walk, const Layout& layout, std::string_view text,
                     const project::FormatSettings& settings, std::vector<uint32_t>& breaks) {
  if (settings.max_line_width == 0) return false;
  std::vector<uint32_t> added = Breaker(walk, layout, text, settings).run();
  if (added.empty()) return false;
  breaks.insert(breaks.end(), added.begin(), added.end());
  std::sort(breaks.begin(), breaks.end());
  breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());
  return true;
}

}  // namespace rung::format
