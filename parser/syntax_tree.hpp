// The concrete syntax tree: a tree-sitter tree plus the text it was parsed from.
//
// The tree is lossless: every byte of the text is either inside a token (a leaf node, comments and
// pragmas included, which the grammar keeps as "extra" nodes) or whitespace between two tokens,
// which for_each_token() reports too. Nodes are cheap value views (SyntaxNode) that are valid as
// long as their SyntaxTree lives and is not edited.
#pragma once

#include <tree_sitter/api.h>

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "parser/diagnostic.hpp"

extern "C" const TSLanguage* tree_sitter_iec61131(void);

namespace rung {

class SyntaxNode {
 public:
  SyntaxNode() = default;
  SyntaxNode(TSNode node, std::string_view source) : node_(node), source_(source) {}

  bool is_null() const { return ts_node_is_null(node_); }
  explicit operator bool() const { return !is_null(); }

  std::string_view kind() const { return ts_node_type(node_); }
  TSSymbol symbol() const { return ts_node_symbol(node_); }
  bool is_named() const { return ts_node_is_named(node_); }
  bool is_error() const { return !is_null() && ts_node_symbol(node_) == static_cast<TSSymbol>(-1); }
  bool is_missing() const { return ts_node_is_missing(node_); }
  bool is_extra() const { return ts_node_is_extra(node_); }
  bool has_error() const { return ts_node_has_error(node_); }

  uint32_t begin() const { return ts_node_start_byte(node_); }
  uint32_t end() const { return ts_node_end_byte(node_); }
  TextRange range() const { return {begin(), end()}; }
  std::string_view text() const;

  uint32_t child_count() const { return ts_node_child_count(node_); }
  SyntaxNode child(uint32_t index) const { return wrap(ts_node_child(node_, index)); }
  uint32_t named_child_count() const { return ts_node_named_child_count(node_); }
  SyntaxNode named_child(uint32_t index) const { return wrap(ts_node_named_child(node_, index)); }
  // The first / every child under `field` (e.g. "name"). Cursor-based, see syntax_tree.cpp.
  SyntaxNode child_by_field(std::string_view field) const;
  std::vector<SyntaxNode> children_by_field(std::string_view field) const;
  // The field name under which child `index` hangs in this node, or empty.
  std::string_view field_name_of_child(uint32_t index) const;
  // All named children with the given kind.
  std::vector<SyntaxNode> children_of_kind(std::string_view kind) const;
  // All named children in order, in one pass (named_child(i) in a loop is quadratic).
  std::vector<SyntaxNode> named_children() const;
  SyntaxNode first_child_of_kind(std::string_view kind) const;

  SyntaxNode parent() const { return wrap(ts_node_parent(node_)); }
  SyntaxNode next_sibling() const { return wrap(ts_node_next_sibling(node_)); }
  SyntaxNode prev_sibling() const { return wrap(ts_node_prev_sibling(node_)); }
  SyntaxNode next_named_sibling() const { return wrap(ts_node_next_named_sibling(node_)); }

  // The smallest node that spans [begin, end).
  SyntaxNode descendant_for_range(uint32_t begin, uint32_t end) const {
    return wrap(ts_node_descendant_for_byte_range(node_, begin, end));
  }

  // The smallest named node that spans [begin, end).
  SyntaxNode named_descendant_for_range(uint32_t begin, uint32_t end) const {
    return wrap(ts_node_named_descendant_for_byte_range(node_, begin, end));
  }

  TSNode raw() const { return node_; }
  std::string_view source() const { return source_; }
  bool operator==(const SyntaxNode& other) const { return ts_node_eq(node_, other.node_); }

 private:
  SyntaxNode wrap(TSNode node) const { return SyntaxNode(node, source_); }
  TSNode node_{};
  std::string_view source_;
};

// Visits `root` and every node below it in document order (anonymous tokens and extras too), with
// one tree cursor: child(i) of the tree-sitter 0.20 runtime starts over from the first child, so
// index loops over children are quadratic. `enter(node)` returns whether to visit its children.
template <typename Enter>
void walk_preorder(SyntaxNode root, Enter&& enter) {
  if (!root) return;
  TSTreeCursor cursor = ts_tree_cursor_new(root.raw());
  bool descend = enter(SyntaxNode(ts_tree_cursor_current_node(&cursor), root.source()));
  while (true) {
    if (!(descend && ts_tree_cursor_goto_first_child(&cursor))) {
      // No children to visit: the next sibling of this node or of the nearest ancestor.
      while (!ts_tree_cursor_goto_next_sibling(&cursor)) {
        if (!ts_tree_cursor_goto_parent(&cursor)) {
          ts_tree_cursor_delete(&cursor);
          return;
        }
      }
    }
    descend = enter(SyntaxNode(ts_tree_cursor_current_node(&cursor), root.source()));
  }
}

// Every pragma node of the tree ({attribute ...}, {IF ...}, {warning ...}), in text order. Pragmas
// are extras that may hang anywhere, but each starts with '{': the text says where to look, so a
// file with a few pragmas costs a few lookups, not a walk over the whole tree.
template <typename Visit>
void for_each_pragma(SyntaxNode root, Visit&& visit) {
  const std::string_view text = root.source();
  for (size_t at = text.find('{', root.begin()); at != std::string_view::npos && at < root.end();
       at = text.find('{', at + 1)) {
    SyntaxNode node = root.named_descendant_for_range(static_cast<uint32_t>(at), static_cast<uint32_t>(at + 1));
    // A '{' inside a comment or a string finds that comment or string instead.
    if (node.begin() != at || node.kind() != "pragma") continue;
    visit(node);
    at = node.end() - 1;
  }
}

// One piece of the lossless token stream.
struct Token {
  enum class Kind { Token, Comment, Pragma, Whitespace, Error };
  Kind kind;
  TextRange range;
  std::string_view node_kind;  // grammar kind of the leaf; empty for whitespace
};

class SyntaxTree {
 public:
  struct Options {
    // Upper bound on parse time; past it the parse is abandoned and aborted() is true.
    // 0 picks a budget proportional to the text size.
    uint64_t timeout_micros = 0;
  };

  static SyntaxTree parse(std::string text, Options options);
  static SyntaxTree parse(std::string text) { return parse(std::move(text), Options{}); }

  SyntaxTree(SyntaxTree&&) noexcept;
  SyntaxTree& operator=(SyntaxTree&&) noexcept;
  ~SyntaxTree();

  // Replaces the bytes [begin, end) by `replacement` and re-parses incrementally, reusing every
  // subtree the edit did not touch. Returns the ranges (in the new text) whose structure changed.
  std::vector<TextRange> apply_edit(uint32_t begin, uint32_t end, std::string_view replacement);

  SyntaxNode root() const;
  const std::string& text() const { return text_; }
  bool aborted() const { return tree_ == nullptr; }
  const TSTree* raw() const { return tree_; }

  // Walks every leaf and every whitespace gap in text order. The ranges tile the text exactly.
  void for_each_token(const std::function<void(const Token&)>& visit) const;

 private:
  SyntaxTree() = default;
  void reparse(const TSTree* old_tree);

  std::string text_;
  Options options_;
  TSParser* parser_ = nullptr;
  TSTree* tree_ = nullptr;
};

}  // namespace rung
