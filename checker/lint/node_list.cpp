#include "checker/lint/node_list.hpp"

#include <algorithm>

namespace rung::lint {
namespace {

// The grammar's kind names by public symbol: ts_node_symbol() gives the public symbol of a node
// (aliases resolved), whose name is the node's kind.
const std::vector<std::string_view>& kind_names() {
  static const std::vector<std::string_view> names = [] {
    const TSLanguage* language = tree_sitter_iec61131();
    std::vector<std::string_view> table(ts_language_symbol_count(language));
    for (uint32_t symbol = 0; symbol < table.size(); ++symbol) {
      const char* name = ts_language_symbol_name(language, static_cast<TSSymbol>(symbol));
      table[symbol] = name ? std::string_view(name) : std::string_view();
    }
    return table;
  }();
  return names;
}

}  // namespace

NodeList::NodeList(SyntaxNode root) : source_(root.source()) {
  const std::vector<std::string_view>& names = kind_names();
  names_ = names.data();
  names_size_ = static_cast<TSSymbol>(names.size());
  if (!root) return;
  entries_.reserve(source_.size() / 2 + 64);  // ST has about one node per 3.5 bytes: no reallocation
  TSTreeCursor cursor = ts_tree_cursor_new(root.raw());
  const auto add = [&](uint32_t parent) {
    const TSNode node = ts_tree_cursor_current_node(&cursor);
    Entry entry;
    entry.raw = node;
    entry.begin = ts_node_start_byte(node);
    entry.end = ts_node_end_byte(node);
    entry.parent = parent;
    entry.symbol = ts_node_symbol(node);
    entry.field = ts_tree_cursor_current_field_id(&cursor);
    entry.flags =
        static_cast<uint8_t>((ts_node_is_named(node) ? kNamed : 0) | (ts_node_is_extra(node) ? kExtra : 0) |
                             (ts_node_is_missing(node) ? kMissing : 0) | (ts_node_has_error(node) ? kHasError : 0));
    if (!entries_.empty() && entry.begin < entries_.back().begin) sorted_ = false;
    entries_.push_back(entry);
    return static_cast<uint32_t>(entries_.size() - 1);
  };
  uint32_t current = add(kNone);
  while (true) {
    if (ts_tree_cursor_goto_first_child(&cursor)) {
      current = add(current);
      continue;
    }
    // `current` has no children: close it, and the ancestors whose last child it is.
    while (true) {
      entries_[current].subtree_end = size();
      if (ts_tree_cursor_goto_next_sibling(&cursor)) {
        current = add(entries_[current].parent);
        break;
      }
      if (!ts_tree_cursor_goto_parent(&cursor)) {
        ts_tree_cursor_delete(&cursor);
        return;
      }
      current = entries_[current].parent;
    }
  }
}

uint32_t NodeList::index_of(SyntaxNode node) const {
  if (!node || entries_.empty()) return kNone;
  const uint32_t at = node.begin();
  uint32_t i = 0;
  if (sorted_) {
    i = static_cast<uint32_t>(
        std::lower_bound(entries_.begin(), entries_.end(), at, [](const Entry& e, uint32_t b) { return e.begin < b; }) -
        entries_.begin());
  }
  for (; i < size() && (!sorted_ || entries_[i].begin == at); ++i) {
    if (ts_node_eq(entries_[i].raw, node.raw())) return i;
  }
  return kNone;
}

TSFieldId NodeList::field_id(std::string_view name) {
  return ts_language_field_id_for_name(tree_sitter_iec61131(), name.data(), static_cast<uint32_t>(name.size()));
}

std::string_view NodeList::rare_kind(TSSymbol symbol) {
  // ERROR and the runtime's other built-in symbols are not in the grammar's table.
  const char* name = ts_language_symbol_name(tree_sitter_iec61131(), symbol);
  return name ? std::string_view(name) : std::string_view();
}

std::string_view operator_text(const NodeList& nodes, uint32_t i) {
  static const TSFieldId kOperator = NodeList::field_id("operator");
  if (const uint32_t op = nodes.child_by_field(i, kOperator); op != NodeList::kNone) return nodes.text(op);
  std::string_view found;
  bool done = false;
  nodes.for_each_child(i, [&](uint32_t child) {
    if (done || nodes.is_named(child) || nodes.is_extra(child)) return;
    found = nodes.text(child);
    done = true;
  });
  return found;
}

}  // namespace rung::lint
