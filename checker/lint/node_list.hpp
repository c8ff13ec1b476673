// A file's syntax tree as the lint rules read it: the tree's node table (parser/syntax_tree.hpp),
// addressed by index.
//
// The nodes are in preorder and a node's subtree is the range [i, subtree_end(i)), so walking is
// a loop over indices and skipping a subtree one assignment; 44 rules walk every file. Nodes are
// named by index; node(i) gives the SyntaxNode for the questions the index API does not answer.
#pragma once

#include <tree_sitter/api.h>

#include <cstdint>
#include <string_view>
#include <vector>

#include "parser/syntax_tree.hpp"

namespace rung::lint {

class NodeList {
 public:
  static constexpr uint32_t kNone = NodeTable::kNone;

  NodeList() = default;  // no tree: no nodes
  // Every node of the tree `root` is the root of (anonymous tokens and extras too), in the order
  // walk_preorder visits them. The list reads the tree's table: it must not outlive the tree.
  explicit NodeList(SyntaxNode root) : table_(root ? root.table() : nullptr) {}

  uint32_t size() const { return table_ ? static_cast<uint32_t>(table_->nodes.size()) : 0; }
  bool empty() const { return size() == 0; }

  // The node itself (a null node for kNone).
  SyntaxNode node(uint32_t i) const { return i < size() ? SyntaxNode(table_, i) : SyntaxNode(); }
  std::string_view kind(uint32_t i) const { return NodeTable::kind_name(at(i).symbol); }
  uint32_t begin(uint32_t i) const { return at(i).begin; }
  uint32_t end(uint32_t i) const { return at(i).end; }
  TextRange range(uint32_t i) const { return {at(i).begin, at(i).end}; }
  std::string_view text(uint32_t i) const { return std::string_view(table_->text).substr(begin(i), end(i) - begin(i)); }

  bool is_named(uint32_t i) const { return (at(i).flags & NodeTable::kNamed) != 0; }
  bool is_extra(uint32_t i) const { return (at(i).flags & NodeTable::kExtra) != 0; }
  bool is_missing(uint32_t i) const { return (at(i).flags & NodeTable::kMissing) != 0; }
  bool has_error(uint32_t i) const { return (at(i).flags & NodeTable::kHasError) != 0; }
  bool is_error(uint32_t i) const { return at(i).symbol == NodeTable::kErrorSymbol; }
  // Whether the node has children (SyntaxNode::child_count() > 0).
  bool has_children(uint32_t i) const { return at(i).subtree_end > i + 1; }

  // One past the node's last descendant: [i, subtree_end(i)) is its subtree.
  uint32_t subtree_end(uint32_t i) const { return at(i).subtree_end; }
  // The parent's index; kNone for the first node.
  uint32_t parent(uint32_t i) const { return at(i).parent; }
  // The field the node hangs under in its parent (0: none), as the tree cursor reports it.
  TSFieldId field(uint32_t i) const { return at(i).field; }

  // The index of `node`, a node of this tree; kNone when it is not in the list.
  uint32_t index_of(SyntaxNode node) const { return node && node.table() == table_ ? node.index() : kNone; }
  // The first child of `i` under `field` (an id from field_id()); kNone if none.
  uint32_t child_by_field(uint32_t i, TSFieldId field) const { return index_of(node(i).child_by_field_id(field)); }

  // The first named child of `i` of `kind`; kNone if none.
  uint32_t first_child_of_kind(uint32_t i, std::string_view kind) const {
    return index_of(node(i).first_child_of_kind(kind));
  }

  // The grammar's id of a field name ("condition"); 0 for an unknown name.
  static TSFieldId field_id(std::string_view name) { return NodeTable::field_id(name); }

  // Calls visit(child) for each child of `i` in order.
  template <typename Visit>
  void for_each_child(uint32_t i, Visit&& visit) const {
    node(i).for_each_child([&](SyntaxNode child) { visit(child.index()); });
  }

  // Calls enter(i) for `from` and the nodes below it in preorder; enter returns whether to visit
  // the node's children (walk_preorder by index).
  template <typename Enter>
  void walk(uint32_t from, Enter&& enter) const {
    walk_preorder(node(from), [&](SyntaxNode n) { return enter(n.index()); });
  }

 private:
  const NodeTable::Node& at(uint32_t i) const { return table_->nodes[i]; }

  const NodeTable* table_ = nullptr;
};

// The operator of the expression node `i` as written ("AND_THEN", "and", "<>"): its child under
// the field "operator", else its first anonymous token (ast::operator_of, not upper-cased and
// without building a string); empty when it has none.
std::string_view operator_text(const NodeList& nodes, uint32_t i);

}  // namespace rung::lint
