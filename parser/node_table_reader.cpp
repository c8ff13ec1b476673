#include "parser/node_table_reader.hpp"

#include <algorithm>
#include <utility>

namespace rung {
namespace {

using Node = NodeTable::Node;

uint8_t flags_of(TSNode node) {
  return static_cast<uint8_t>(
      (ts_node_is_named(node) ? NodeTable::kNamed : 0) | (ts_node_is_extra(node) ? NodeTable::kExtra : 0) |
      (ts_node_is_missing(node) ? NodeTable::kMissing : 0) | (ts_node_has_error(node) ? NodeTable::kHasError : 0));
}

// Appends the visible nodes of the subtree at `start` to `out` in preorder. `start` hangs under
// `field` in the node at index `parent`; the first appended node gets index `base`.
void append_subtree(TSNode start, TSFieldId field, uint32_t parent, uint32_t base, std::vector<Node>& out) {
  const auto first = static_cast<uint32_t>(out.size());
  const auto global = [&](size_t local) { return base + static_cast<uint32_t>(local - first); };
  const auto local = [&](uint32_t global_index) { return first + (global_index - base); };
  TSTreeCursor cursor = ts_tree_cursor_new(start);
  // The first node is `start` itself, not the cursor's view of it: a cursor that starts at a node
  // does not know the alias its parent gives it (il_operator is an alias of several tokens).
  bool at_start = true;
  const auto add = [&](uint32_t parent_index, TSFieldId field_id) {
    const TSNode node = at_start ? start : ts_tree_cursor_current_node(&cursor);
    at_start = false;
    Node entry;
    entry.begin = ts_node_start_byte(node);
    entry.end = ts_node_end_byte(node);
    entry.parent = parent_index;
    entry.symbol = ts_node_symbol(node);
    entry.field = static_cast<uint8_t>(field_id);
    entry.flags = flags_of(node);
    out.push_back(entry);
    return global(out.size() - 1);
  };
  uint32_t current = add(parent, field);
  bool done = false;
  while (!done) {
    if (ts_tree_cursor_goto_first_child(&cursor)) {
      current = add(current, ts_tree_cursor_current_field_id(&cursor));
      continue;
    }
    // `current` has no children: close it, and the ancestors whose last child it is.
    while (true) {
      out[local(current)].subtree_end = global(out.size());
      if (current == base) {
        done = true;  // back at `start`: its siblings are not ours
        break;
      }
      if (ts_tree_cursor_goto_next_sibling(&cursor)) {
        current = add(out[local(current)].parent, ts_tree_cursor_current_field_id(&cursor));
        break;
      }
      ts_tree_cursor_goto_parent(&cursor);
      current = out[local(current)].parent;
    }
  }
  ts_tree_cursor_delete(&cursor);
}

bool begins_in_order(const std::vector<Node>& nodes) {
  for (size_t i = 1; i < nodes.size(); ++i) {
    if (nodes[i].begin < nodes[i - 1].begin) return false;
  }
  return true;
}

// The children of a new-tree node with the fields they hang under.
std::vector<std::pair<TSNode, TSFieldId>> children_of(TSNode node) {
  std::vector<std::pair<TSNode, TSFieldId>> out;
  TSTreeCursor cursor = ts_tree_cursor_new(node);
  for (bool more = ts_tree_cursor_goto_first_child(&cursor); more; more = ts_tree_cursor_goto_next_sibling(&cursor)) {
    out.emplace_back(ts_tree_cursor_current_node(&cursor), ts_tree_cursor_current_field_id(&cursor));
  }
  ts_tree_cursor_delete(&cursor);
  return out;
}

}  // namespace

void read_node_table(const TSTree* tree, NodeTable& table) {
  // Built in a scratch vector reused across parses, then copied once at its exact size: the
  // tables of a whole workspace stay in memory, so they must not carry growth slack.
  thread_local std::vector<Node> scratch;
  scratch.clear();
  append_subtree(ts_tree_root_node(tree), 0, NodeTable::kNone, 0, scratch);
  table.nodes.assign(scratch.begin(), scratch.end());
  table.sorted = begins_in_order(table.nodes);
  if (scratch.capacity() > (size_t{1} << 22)) std::vector<Node>().swap(scratch);  // a huge file's
}

bool splice_node_table(NodeTable& table, const TSTree* tree, const TSInputEdit& edit,
                       const std::vector<TextRange>& changed) {
  std::vector<Node>& nodes = table.nodes;
  if (nodes.empty()) return false;
  const int64_t byte_delta = static_cast<int64_t>(edit.new_end_byte) - static_cast<int64_t>(edit.old_end_byte);
  // A new-tree node is dirty when it touches a changed range or the edited text (ends included),
  // or holds a syntax error: inside error recovery tree-sitter may regroup nodes far from the
  // edit without reporting a changed range (seen on the seed corpus).
  const auto dirty = [&](TSNode node) {
    if (ts_node_has_error(node)) return true;
    const uint32_t b = ts_node_start_byte(node);
    const uint32_t e = ts_node_end_byte(node);
    if (b <= edit.new_end_byte && edit.start_byte <= e) return true;
    return std::any_of(changed.begin(), changed.end(), [&](TextRange r) { return b <= r.end && r.begin <= e; });
  };
  // An old node outside the edit, where it lies in the new text.
  const auto moved = [&](uint32_t offset) {
    return offset < edit.start_byte ? offset : static_cast<uint32_t>(static_cast<int64_t>(offset) + byte_delta);
  };
  const auto same = [&](uint32_t old_index, TSNode node, TSFieldId field) {
    const Node& old = nodes[old_index];
    return old.symbol == ts_node_symbol(node) && old.field == field && old.flags == flags_of(node) &&
           moved(old.begin) == ts_node_start_byte(node) && moved(old.end) == ts_node_end_byte(node);
  };

  // Descend while exactly one child changed and it is the same kind of node in both trees.
  std::vector<std::pair<uint32_t, TSNode>> path;  // matched ancestors: old index, new node
  uint32_t old_node = 0;
  TSNode new_node = ts_tree_root_node(tree);
  if (nodes[0].symbol != ts_node_symbol(new_node)) return false;
  uint32_t span_begin = 0;
  uint32_t span_end = 0;
  std::vector<std::pair<TSNode, TSFieldId>> fresh_children;
  while (true) {
    path.emplace_back(old_node, new_node);
    const std::vector<std::pair<TSNode, TSFieldId>> kids = children_of(new_node);
    std::vector<uint32_t> old_kids;
    for (uint32_t c = old_node + 1; c < nodes[old_node].subtree_end; c = nodes[c].subtree_end) old_kids.push_back(c);
    size_t first_dirty = kids.size();
    size_t last_dirty = 0;
    for (size_t k = 0; k < kids.size(); ++k) {
      if (!dirty(kids[k].first)) continue;
      first_dirty = std::min(first_dirty, k);
      last_dirty = k;
    }
    if (first_dirty == kids.size()) return false;  // nothing here touches the edit: read it all
    const size_t suffix = kids.size() - 1 - last_dirty;
    if (first_dirty + suffix > old_kids.size()) return false;
    for (size_t k = 0; k < first_dirty; ++k) {
      if (!same(old_kids[k], kids[k].first, kids[k].second)) return false;
    }
    for (size_t k = 0; k < suffix; ++k) {
      const auto& kid = kids[kids.size() - 1 - k];
      if (!same(old_kids[old_kids.size() - 1 - k], kid.first, kid.second)) return false;
    }
    const size_t old_dirty = old_kids.size() - suffix - first_dirty;  // old children replaced
    if (first_dirty == last_dirty && old_dirty == 1) {
      const uint32_t old_child = old_kids[first_dirty];
      const TSNode new_child = kids[first_dirty].first;
      if (nodes[old_child].symbol == ts_node_symbol(new_child) && nodes[old_child].field == kids[first_dirty].second &&
          nodes[old_child].subtree_end > old_child + 1 && ts_node_child_count(new_child) > 0) {
        old_node = old_child;
        new_node = new_child;
        continue;
      }
    }
    span_begin = first_dirty < old_kids.size() ? old_kids[first_dirty] : nodes[old_node].subtree_end;
    span_end = old_dirty > 0 ? nodes[old_kids[first_dirty + old_dirty - 1]].subtree_end : span_begin;
    fresh_children.assign(kids.begin() + static_cast<std::ptrdiff_t>(first_dirty),
                          kids.begin() + static_cast<std::ptrdiff_t>(last_dirty) + 1);
    break;
  }

  std::vector<Node> fresh;
  for (const auto& [child, field] : fresh_children) {
    append_subtree(child, field, old_node, span_begin + static_cast<uint32_t>(fresh.size()), fresh);
  }
  const int64_t count_delta = static_cast<int64_t>(fresh.size()) - static_cast<int64_t>(span_end - span_begin);
  const auto shift_index = [&](uint32_t index) {
    return static_cast<uint32_t>(static_cast<int64_t>(index) + count_delta);
  };
  // Every node outside the span lies wholly before or wholly after the edit (a node touching it
  // is dirty, or an ancestor): those after it move by the edit's length. Clean siblings before
  // the first dirty one may lie after the edit too, when the edit only touched whitespace.
  for (size_t i = 0; i < span_begin; ++i) {
    nodes[i].begin = moved(nodes[i].begin);
    nodes[i].end = moved(nodes[i].end);
  }
  // The nodes after the span also move in the table by the change in node count (their parents
  // too, unless the parent is an ancestor before the span).
  for (size_t i = span_end; i < nodes.size(); ++i) {
    Node& node = nodes[i];
    node.begin = moved(node.begin);
    node.end = moved(node.end);
    if (node.parent != NodeTable::kNone && node.parent >= span_end) node.parent = shift_index(node.parent);
    node.subtree_end = shift_index(node.subtree_end);
  }
  // The ancestors: their ranges and error flags as the new tree has them.
  for (const auto& [index, raw] : path) {
    Node& node = nodes[index];
    node.begin = ts_node_start_byte(raw);
    node.end = ts_node_end_byte(raw);
    node.flags = flags_of(raw);
    node.subtree_end = shift_index(node.subtree_end);
  }
  const auto at = nodes.begin() + span_begin;
  if (count_delta == 0) {
    std::copy(fresh.begin(), fresh.end(), at);
  } else {
    nodes.erase(at, nodes.begin() + span_end);
    nodes.insert(nodes.begin() + span_begin, fresh.begin(), fresh.end());
  }
  table.sorted = begins_in_order(nodes);
  return true;
}

}  // namespace rung
