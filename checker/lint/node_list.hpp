// A file's syntax tree as one flat array of nodes in preorder, built with one tree-cursor walk.
//
// Every lint rule looks at the same trees: walking one with a tree cursor costs about 90 ns per
// node, and 44 rules walking 1.6 million nodes each spent seconds doing only that. The array is
// built once per file (LintContext::nodes()) and walked in a few nanoseconds per node: a node's
// subtree is the range [i, subtree_end(i)), so skipping it is one assignment. Nodes are named by
// index; node(i) gives the SyntaxNode for the questions the array does not answer.
#pragma once

#include <tree_sitter/api.h>

#include <cstdint>
#include <string_view>
#include <vector>

#include "parser/syntax_tree.hpp"

namespace rung::lint {

class NodeList {
 public:
  static constexpr uint32_t kNone = UINT32_MAX;

  NodeList() = default;  // no tree: no nodes
  // Every node of `root`'s tree below and including `root`, anonymous tokens and extras too (the
  // nodes walk_preorder visits, in its order).
  explicit NodeList(SyntaxNode root);

  uint32_t size() const { return static_cast<uint32_t>(entries_.size()); }
  bool empty() const { return entries_.empty(); }

  // The node itself (a null node for kNone).
  SyntaxNode node(uint32_t i) const { return i < size() ? SyntaxNode(entries_[i].raw, source_) : SyntaxNode(); }
  std::string_view kind(uint32_t i) const {
    const TSSymbol symbol = entries_[i].symbol;
    return symbol < names_size_ ? names_[symbol] : rare_kind(symbol);
  }
  uint32_t begin(uint32_t i) const { return entries_[i].begin; }
  uint32_t end(uint32_t i) const { return entries_[i].end; }
  TextRange range(uint32_t i) const { return {entries_[i].begin, entries_[i].end}; }
  std::string_view text(uint32_t i) const { return source_.substr(begin(i), end(i) - begin(i)); }

  bool is_named(uint32_t i) const { return entries_[i].flags & kNamed; }
  bool is_extra(uint32_t i) const { return entries_[i].flags & kExtra; }
  bool is_missing(uint32_t i) const { return entries_[i].flags & kMissing; }
  bool has_error(uint32_t i) const { return entries_[i].flags & kHasError; }
  bool is_error(uint32_t i) const { return entries_[i].symbol == static_cast<TSSymbol>(-1); }
  // Whether the node has children (SyntaxNode::child_count() > 0).
  bool has_children(uint32_t i) const { return entries_[i].subtree_end > i + 1; }

  // One past the node's last descendant: [i, subtree_end(i)) is its subtree.
  uint32_t subtree_end(uint32_t i) const { return entries_[i].subtree_end; }
  // The parent's index; kNone for the first node.
  uint32_t parent(uint32_t i) const { return entries_[i].parent; }
  // The field the node hangs under in its parent (0: none), as the tree cursor reports it.
  TSFieldId field(uint32_t i) const { return entries_[i].field; }

  // The index of `node`, a node of this tree; kNone when it is not in the list.
  uint32_t index_of(SyntaxNode node) const;
  // The first child of `i` under `field` (an id from field_id()); kNone if none.
  uint32_t child_by_field(uint32_t i, TSFieldId field) const {
    if (field == 0 || i >= size()) return kNone;
    for (uint32_t child = i + 1; child < entries_[i].subtree_end; child = entries_[child].subtree_end) {
      if (entries_[child].field == field) return child;
    }
    return kNone;
  }

  // The first named child of `i` of `kind`; kNone if none.
  uint32_t first_child_of_kind(uint32_t i, std::string_view kind) const {
    if (i >= size()) return kNone;
    for (uint32_t child = i + 1; child < entries_[i].subtree_end; child = entries_[child].subtree_end) {
      if (is_named(child) && this->kind(child) == kind) return child;
    }
    return kNone;
  }

  // The grammar's id of a field name ("condition"); 0 for an unknown name.
  static TSFieldId field_id(std::string_view name);

  // Calls visit(child) for each child of `i` in order.
  template <typename Visit>
  void for_each_child(uint32_t i, Visit&& visit) const {
    for (uint32_t child = i + 1; child < entries_[i].subtree_end; child = entries_[child].subtree_end) visit(child);
  }

  // Calls enter(i) for `from` and the nodes below it in preorder; enter returns whether to visit
  // the node's children (walk_preorder over the array).
  template <typename Enter>
  void walk(uint32_t from, Enter&& enter) const {
    if (from >= size()) return;
    const uint32_t stop = entries_[from].subtree_end;
    for (uint32_t i = from; i < stop;) i = enter(i) ? i + 1 : entries_[i].subtree_end;
  }

 private:
  enum Flag : uint8_t { kNamed = 1, kExtra = 2, kMissing = 4, kHasError = 8 };
  struct Entry {
    TSNode raw;
    uint32_t begin = 0;
    uint32_t end = 0;
    uint32_t subtree_end = 0;
    uint32_t parent = kNone;
    TSSymbol symbol = 0;
    TSFieldId field = 0;
    uint8_t flags = 0;
  };

  static std::string_view rare_kind(TSSymbol symbol);

  std::vector<Entry> entries_;
  std::string_view source_;
  const std::string_view* names_ = nullptr;  // kind names by symbol (the grammar's table)
  TSSymbol names_size_ = 0;
  bool sorted_ = true;  // begins never decrease in preorder (index_of may binary-search)
};

// The operator of the expression node `i` as written ("AND_THEN", "and", "<>"): its child under
// the field "operator", else its first anonymous token (ast::operator_of, not upper-cased and
// without building a string); empty when it has none.
std::string_view operator_text(const NodeList& nodes, uint32_t i);

}  // namespace rung::lint
