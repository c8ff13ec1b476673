#include "formatter/token_stream.hpp"

#include "formatter/keyword_case.hpp"
#include "formatter/syntax_kinds.hpp"

namespace rung::format {

// One walk over the node table with an explicit stack of parents: the parent of each leaf decides
// its case class.
TokenStream token_stream_of(CheckInput in, bool with_shape) {
  TokenStream s;
  SyntaxNode root = in.tree->root();
  if (!root) {
    s.has_error = true;
    return s;
  }
  s.has_error = root.has_error();
  struct Parent {
    NodeKind kind;
    uint32_t begin;
    uint32_t children;
    uint32_t subtree_end;
  };
  std::vector<Parent> parents{{symbol_info(root.symbol()).node, root.begin(), root.child_count(), root.subtree_end()}};
  const NodeTable* table = root.table();
  for (uint32_t i = root.index() + 1; i < root.subtree_end();) {
    const SyntaxNode node(table, i);
    while (parents.back().subtree_end <= i) parents.pop_back();
    const SymbolInfo& info = symbol_info(node.symbol());
    const bool leaf = node.subtree_end() == i + 1;
    const bool trivia = node.is_extra() && (info.node == NodeKind::Comment || info.node == NodeKind::Pragma);
    if (trivia) {
      s.trivia.push_back({in.text.substr(node.begin(), node.end() - node.begin()), node.begin(), false});
      i = node.subtree_end();
    } else if (leaf) {
      if (node.is_missing()) s.has_error = true;
      if (node.end() > node.begin()) {
        const std::string_view text = in.text.substr(node.begin(), node.end() - node.begin());
        const Parent& p = parents.back();
        const LeafPlace place{p.kind, node.begin() == p.begin, p.children == 1};
        s.tokens.push_back({text, node.begin(), case_class(info, place, text) != CaseClass::None});
      }
      if (with_shape && info.named) s.shape.emplace_back(node.symbol(), node.begin());
      ++i;
    } else {
      if (with_shape && info.named) s.shape.emplace_back(node.symbol(), node.begin());
      parents.push_back({info.node, node.begin(), node.child_count(), node.subtree_end()});
      ++i;
    }
  }
  return s;
}

}  // namespace rung::format
