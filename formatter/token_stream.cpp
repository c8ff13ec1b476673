#include "formatter/token_stream.hpp"

#include "formatter/keyword_case.hpp"
#include "formatter/syntax_kinds.hpp"

namespace rung::format {

// An explicit frame stack (the parent of each leaf decides its case class), in one cursor walk.
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
  };
  std::vector<Parent> parents{{symbol_info(root.symbol()).node, root.begin(), root.child_count()}};
  TSTreeCursor cursor = ts_tree_cursor_new(root.raw());
  if (ts_tree_cursor_goto_first_child(&cursor)) {
    while (true) {
      TSNode raw = ts_tree_cursor_current_node(&cursor);
      SyntaxNode node(raw, root.source());
      const SymbolInfo& info = symbol_info(node.symbol());
      const uint32_t children = ts_node_child_count(raw);
      const bool extra = ts_node_is_extra(raw);
      const bool trivia = extra && (info.node == NodeKind::Comment || info.node == NodeKind::Pragma);
      bool descended = false;
      if (trivia) {
        s.trivia.push_back({in.text.substr(node.begin(), node.end() - node.begin()), node.begin(), false});
      } else if (children == 0) {
        if (node.is_missing()) s.has_error = true;
        if (node.end() > node.begin()) {
          const std::string_view text = in.text.substr(node.begin(), node.end() - node.begin());
          const Parent& p = parents.back();
          const LeafPlace place{p.kind, node.begin() == p.begin, p.children == 1};
          s.tokens.push_back({text, node.begin(), case_class(info, place, text) != CaseClass::None});
        }
        if (with_shape && info.named) s.shape.emplace_back(node.symbol(), node.begin());
      } else {
        if (with_shape && info.named) s.shape.emplace_back(node.symbol(), node.begin());
        parents.push_back({info.node, node.begin(), children});
        descended = ts_tree_cursor_goto_first_child(&cursor);
        if (!descended) parents.pop_back();
      }
      if (descended) continue;
      bool moved = false;
      while (!(moved = ts_tree_cursor_goto_next_sibling(&cursor))) {
        if (!ts_tree_cursor_goto_parent(&cursor)) break;
        parents.pop_back();
        if (parents.empty()) break;
      }
      if (!moved) break;
    }
  }
  ts_tree_cursor_delete(&cursor);
  return s;
}

}  // namespace rung::format
