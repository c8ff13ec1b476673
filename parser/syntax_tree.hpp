// The concrete syntax tree: the nodes tree-sitter parsed from a text, kept as one flat array.
//
// The tree is lossless: every byte of the text is either inside a token (a leaf node, comments and
// pragmas included, which the grammar keeps as "extra" nodes) or whitespace between two tokens,
// which for_each_token() reports too.
//
// tree-sitter's own tree is read once, right after the parse, into a NodeTable and then freed
// (unless Options::keep_parse_tree). Why: that tree spends a heap node of 80-100 bytes on every
// hidden grammar rule between a statement and its names and walks them on every step, so it
// took ~900 MB for a 1M-line workspace and its cursor was the checker's largest cost. The table
// holds the visible nodes only, 20 bytes each, in preorder: a node's subtree is the index range
// [i, subtree_end), so walking, skipping a subtree and reading a field are array steps.
// SyntaxNode is a cheap value view (table, index) valid as long as its SyntaxTree lives and is
// not edited.
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

// The nodes of one parsed text in preorder, and the text. Built by SyntaxTree.
struct NodeTable {
  static constexpr uint32_t kNone = UINT32_MAX;
  static constexpr TSSymbol kErrorSymbol = static_cast<TSSymbol>(-1);  // tree-sitter's ERROR
  enum Flag : uint8_t { kNamed = 1, kExtra = 2, kMissing = 4, kHasError = 8 };

  struct Node {
    uint32_t begin = 0;
    uint32_t end = 0;
    uint32_t subtree_end = 0;  // one past the last descendant
    uint32_t parent = kNone;
    TSSymbol symbol = 0;  // public symbol (aliases resolved): the kind
    uint8_t field = 0;    // the field it hangs under in its parent, as a tree cursor reports it
    uint8_t flags = 0;
  };

  std::string text;
  std::vector<Node> nodes;
  bool sorted = true;  // begins never decrease in preorder (lookups by offset may binary-search)

  // The grammar's kind name of a symbol ("assignment", "ERROR").
  static std::string_view kind_name(TSSymbol symbol);
  // The grammar's id of a field name ("condition"), 0 for an unknown name; and back.
  static TSFieldId field_id(std::string_view name);
  static std::string_view field_name(TSFieldId id);
};

class SyntaxNode {
 public:
  SyntaxNode() = default;
  SyntaxNode(const NodeTable* table, uint32_t index) : table_(table), index_(index) {}

  bool is_null() const { return table_ == nullptr; }
  explicit operator bool() const { return !is_null(); }

  std::string_view kind() const { return NodeTable::kind_name(node().symbol); }
  TSSymbol symbol() const { return node().symbol; }
  bool is_named() const { return flag(NodeTable::kNamed); }
  bool is_error() const { return !is_null() && node().symbol == NodeTable::kErrorSymbol; }
  bool is_missing() const { return flag(NodeTable::kMissing); }
  bool is_extra() const { return flag(NodeTable::kExtra); }
  bool has_error() const { return flag(NodeTable::kHasError); }

  uint32_t begin() const { return is_null() ? 0 : node().begin; }
  uint32_t end() const { return is_null() ? 0 : node().end; }
  TextRange range() const { return {begin(), end()}; }
  std::string_view text() const;

  uint32_t child_count() const { return count_children(false); }
  SyntaxNode child(uint32_t index) const { return nth_child(index, false); }
  uint32_t named_child_count() const { return count_children(true); }
  SyntaxNode named_child(uint32_t index) const { return nth_child(index, true); }
  // The first / every child under `field` (e.g. "name").
  SyntaxNode child_by_field(std::string_view field) const { return child_by_field_id(NodeTable::field_id(field)); }
  SyntaxNode child_by_field_id(TSFieldId field) const;
  std::vector<SyntaxNode> children_by_field(std::string_view field) const;
  // The field name under which child `index` hangs in this node, or empty.
  std::string_view field_name_of_child(uint32_t index) const;
  // The field id under which this node hangs in its parent (0: none).
  TSFieldId field_id() const { return is_null() ? 0 : node().field; }
  // All named children with the given kind.
  std::vector<SyntaxNode> children_of_kind(std::string_view kind) const;
  // All named children in order.
  std::vector<SyntaxNode> named_children() const;
  SyntaxNode first_child_of_kind(std::string_view kind) const;

  SyntaxNode parent() const;
  SyntaxNode next_sibling() const;
  SyntaxNode prev_sibling() const;
  SyntaxNode next_named_sibling() const;

  // The smallest node that spans [begin, end).
  SyntaxNode descendant_for_range(uint32_t begin, uint32_t end) const { return descendant(begin, end, false); }
  // The smallest named node that spans [begin, end).
  SyntaxNode named_descendant_for_range(uint32_t begin, uint32_t end) const { return descendant(begin, end, true); }

  // The table and the node's index in it (preorder position).
  const NodeTable* table() const { return table_; }
  uint32_t index() const { return index_; }
  // One past the node's last descendant: [index(), subtree_end()) is its subtree.
  uint32_t subtree_end() const { return is_null() ? 0 : node().subtree_end; }
  // An address unique to this node among all live trees (a key for maps).
  const void* identity() const { return is_null() ? nullptr : &node(); }

  std::string_view source() const { return is_null() ? std::string_view() : std::string_view(table_->text); }
  bool operator==(const SyntaxNode& other) const { return table_ == other.table_ && index_ == other.index_; }

  // Calls visit(child) for each child in order (anonymous tokens and extras too).
  template <typename Visit>
  void for_each_child(Visit&& visit) const {
    if (is_null()) return;
    const auto& nodes = table_->nodes;
    for (uint32_t c = index_ + 1; c < nodes[index_].subtree_end; c = nodes[c].subtree_end) visit(SyntaxNode(table_, c));
  }

 private:
  const NodeTable::Node& node() const { return table_->nodes[index_]; }
  bool flag(uint8_t f) const { return !is_null() && (node().flags & f) != 0; }
  SyntaxNode at(uint32_t index) const { return index == NodeTable::kNone ? SyntaxNode() : SyntaxNode(table_, index); }
  SyntaxNode descendant(uint32_t begin, uint32_t end, bool named_only) const;
  uint32_t count_children(bool named_only) const;
  SyntaxNode nth_child(uint32_t index, bool named_only) const;

  const NodeTable* table_ = nullptr;
  uint32_t index_ = 0;
};

// Visits `root` and every node below it in document order (anonymous tokens and extras too).
// `enter(node)` returns whether to visit its children.
template <typename Enter>
void walk_preorder(SyntaxNode root, Enter&& enter) {
  if (!root) return;
  const NodeTable* table = root.table();
  const uint32_t stop = root.subtree_end();
  for (uint32_t i = root.index(); i < stop;) {
    i = enter(SyntaxNode(table, i)) ? i + 1 : table->nodes[i].subtree_end;
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
    // Keep tree-sitter's tree next to the node table: apply_edit() then re-parses incrementally
    // and raw() serves tree-sitter queries. Costs about 30 bytes of memory per byte of text.
    bool keep_parse_tree = false;
  };

  static SyntaxTree parse(std::string text, Options options);
  static SyntaxTree parse(std::string text) { return parse(std::move(text), Options{}); }

  SyntaxTree(SyntaxTree&&) noexcept;
  SyntaxTree& operator=(SyntaxTree&&) noexcept;
  ~SyntaxTree();

  // Replaces the bytes [begin, end) by `replacement` and re-parses (incrementally when the parse
  // tree is kept, reusing every subtree the edit did not touch). Returns the ranges (in the new
  // text) whose structure changed. Nodes of the tree before the edit are invalid afterwards.
  std::vector<TextRange> apply_edit(uint32_t begin, uint32_t end, std::string_view replacement);

  SyntaxNode root() const;
  const std::string& text() const { return table_->text; }
  bool aborted() const { return table_->nodes.empty(); }
  // tree-sitter's tree; null unless Options::keep_parse_tree.
  const TSTree* raw() const { return tree_; }
  // Number of nodes (visible nodes of the grammar, tokens and extras included).
  size_t node_count() const { return table_->nodes.size(); }

  // Walks every leaf and every whitespace gap in text order. The ranges tile the text exactly.
  void for_each_token(const std::function<void(const Token&)>& visit) const;

 private:
  SyntaxTree() = default;
  // Parses table_->text, reusing `old_tree` when given; null when the parse timed out.
  TSTree* parse_text(const TSTree* old_tree) const;
  // Keeps `parsed` as tree_ when Options::keep_parse_tree, else frees it.
  void keep_or_delete(TSTree* parsed);

  std::unique_ptr<NodeTable> table_;  // on the heap: nodes point at it, and trees move
  Options options_;
  TSTree* tree_ = nullptr;  // only with Options::keep_parse_tree
};

}  // namespace rung
