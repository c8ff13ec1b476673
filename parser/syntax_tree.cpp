#include "parser/syntax_tree.hpp"

#include <algorithm>
#include <cstring>
#include <unordered_map>
#include <utility>

namespace rung {

std::string_view SyntaxNode::text() const {
  if (is_null()) return {};
  uint32_t b = std::min<uint32_t>(begin(), static_cast<uint32_t>(source_.size()));
  uint32_t e = std::min<uint32_t>(end(), static_cast<uint32_t>(source_.size()));
  return source_.substr(b, e - b);
}

namespace {

// Walks the children with a cursor: ts_node_child(i) restarts from the first child in the
// tree-sitter 0.20 runtime, so index loops over a node's children are quadratic.
template <typename Visit>
void for_each_child(TSNode node, Visit visit) {
  TSTreeCursor cursor = ts_tree_cursor_new(node);
  if (ts_tree_cursor_goto_first_child(&cursor)) {
    do {
      if (!visit(cursor)) break;
    } while (ts_tree_cursor_goto_next_sibling(&cursor));
  }
  ts_tree_cursor_delete(&cursor);
}

// The grammar's id of a field name, 0 if it has no such field. Children are matched by id: the
// name compare (a strlen per child) showed up in profiles of the symbol pass.
TSFieldId field_id(std::string_view field) {
  static const std::unordered_map<std::string_view, TSFieldId> ids = [] {
    std::unordered_map<std::string_view, TSFieldId> out;
    const TSLanguage* language = tree_sitter_iec61131();
    const uint32_t count = ts_language_field_count(language);
    for (uint32_t id = 1; id <= count; ++id) {
      if (const char* name = ts_language_field_name_for_id(language, static_cast<TSFieldId>(id))) {
        out.emplace(name, static_cast<TSFieldId>(id));
      }
    }
    return out;
  }();
  const auto found = ids.find(field);
  return found == ids.end() ? TSFieldId{0} : found->second;
}

}  // namespace

SyntaxNode SyntaxNode::child_by_field(std::string_view field) const {
  SyntaxNode found;
  const TSFieldId id = field_id(field);
  if (id == 0) return found;
  for_each_child(node_, [&](const TSTreeCursor& cursor) {
    if (ts_tree_cursor_current_field_id(&cursor) == id) found = wrap(ts_tree_cursor_current_node(&cursor));
    return !found;
  });
  return found;
}

// Field names come from a tree cursor: ts_node_field_name_for_child of the tree-sitter 0.20
// runtime (Debian 12) misattributes fields when hidden or extra nodes precede a child.
std::string_view SyntaxNode::field_name_of_child(uint32_t index) const {
  TSTreeCursor cursor = ts_tree_cursor_new(node_);
  std::string_view name;
  if (ts_tree_cursor_goto_first_child(&cursor)) {
    for (uint32_t i = 0; i < index; ++i) {
      if (!ts_tree_cursor_goto_next_sibling(&cursor)) {
        ts_tree_cursor_delete(&cursor);
        return {};
      }
    }
    const char* field = ts_tree_cursor_current_field_name(&cursor);
    if (field) name = field;
  }
  ts_tree_cursor_delete(&cursor);
  return name;
}

std::vector<SyntaxNode> SyntaxNode::children_by_field(std::string_view field) const {
  std::vector<SyntaxNode> out;
  const TSFieldId id = field_id(field);
  if (id == 0) return out;
  for_each_child(node_, [&](const TSTreeCursor& cursor) {
    if (ts_tree_cursor_current_field_id(&cursor) == id) out.push_back(wrap(ts_tree_cursor_current_node(&cursor)));
    return true;
  });
  return out;
}

std::vector<SyntaxNode> SyntaxNode::children_of_kind(std::string_view kind) const {
  std::vector<SyntaxNode> out;
  for_each_child(node_, [&](const TSTreeCursor& cursor) {
    TSNode child = ts_tree_cursor_current_node(&cursor);
    if (ts_node_is_named(child) && kind == ts_node_type(child)) out.push_back(wrap(child));
    return true;
  });
  return out;
}

std::vector<SyntaxNode> SyntaxNode::named_children() const {
  std::vector<SyntaxNode> out;
  for_each_child(node_, [&](const TSTreeCursor& cursor) {
    TSNode child = ts_tree_cursor_current_node(&cursor);
    if (ts_node_is_named(child)) out.push_back(wrap(child));
    return true;
  });
  return out;
}

SyntaxNode SyntaxNode::first_child_of_kind(std::string_view kind) const {
  SyntaxNode found;
  for_each_child(node_, [&](const TSTreeCursor& cursor) {
    TSNode child = ts_tree_cursor_current_node(&cursor);
    if (ts_node_is_named(child) && kind == ts_node_type(child)) found = wrap(child);
    return !found;
  });
  return found;
}

namespace {

// Row/column point of a byte offset, as tree-sitter wants it for edits (columns in bytes).
TSPoint point_at(std::string_view text, uint32_t offset) {
  offset = std::min<uint32_t>(offset, static_cast<uint32_t>(text.size()));
  uint32_t row = 0;
  uint32_t line_start = 0;
  const char* base = text.data();
  const char* p = base;
  const char* stop = base + offset;
  while (p < stop) {
    const void* nl = std::memchr(p, '\n', static_cast<size_t>(stop - p));
    if (!nl) break;
    ++row;
    p = static_cast<const char*>(nl) + 1;
    line_start = static_cast<uint32_t>(p - base);
  }
  return TSPoint{row, offset - line_start};
}

// Points after inserting `inserted` at `start`.
TSPoint advance_point(TSPoint start, std::string_view inserted) {
  TSPoint p = start;
  for (char c : inserted) {
    if (c == '\n') {
      ++p.row;
      p.column = 0;
    } else {
      ++p.column;
    }
  }
  return p;
}

}  // namespace

SyntaxTree SyntaxTree::parse(std::string text, Options options) {
  SyntaxTree tree;
  tree.text_ = std::move(text);
  tree.options_ = options;
  tree.parser_ = ts_parser_new();
  ts_parser_set_language(tree.parser_, tree_sitter_iec61131());
  tree.reparse(nullptr);
  return tree;
}

void SyntaxTree::reparse(const TSTree* old_tree) {
  uint64_t timeout = options_.timeout_micros;
  if (timeout == 0) {
    // Generous: a healthy parse runs at tens of MB/s; this budget only stops pathological cases.
    timeout = 2'000'000 + static_cast<uint64_t>(text_.size()) * 2;
  }
  ts_parser_set_timeout_micros(parser_, timeout);
  ts_parser_reset(parser_);
  TSTree* fresh = ts_parser_parse_string(parser_, old_tree, text_.data(), static_cast<uint32_t>(text_.size()));
  if (tree_ && tree_ != fresh) ts_tree_delete(tree_);
  tree_ = fresh;
}

SyntaxTree::SyntaxTree(SyntaxTree&& other) noexcept
    : text_(std::move(other.text_)),
      options_(other.options_),
      parser_(std::exchange(other.parser_, nullptr)),
      tree_(std::exchange(other.tree_, nullptr)) {}

SyntaxTree& SyntaxTree::operator=(SyntaxTree&& other) noexcept {
  if (this != &other) {
    if (tree_) ts_tree_delete(tree_);
    if (parser_) ts_parser_delete(parser_);
    text_ = std::move(other.text_);
    options_ = other.options_;
    parser_ = std::exchange(other.parser_, nullptr);
    tree_ = std::exchange(other.tree_, nullptr);
  }
  return *this;
}

SyntaxTree::~SyntaxTree() {
  if (tree_) ts_tree_delete(tree_);
  if (parser_) ts_parser_delete(parser_);
}

SyntaxNode SyntaxTree::root() const {
  if (!tree_) return {};
  return SyntaxNode(ts_tree_root_node(tree_), text_);
}

std::vector<TextRange> SyntaxTree::apply_edit(uint32_t begin, uint32_t end, std::string_view replacement) {
  uint32_t size = static_cast<uint32_t>(text_.size());
  begin = std::min(begin, size);
  end = std::clamp(end, begin, size);

  TSInputEdit edit{};
  edit.start_byte = begin;
  edit.old_end_byte = end;
  edit.new_end_byte = begin + static_cast<uint32_t>(replacement.size());
  edit.start_point = point_at(text_, begin);
  edit.old_end_point = point_at(text_, end);
  edit.new_end_point = advance_point(edit.start_point, replacement);

  text_.replace(begin, end - begin, replacement);

  std::vector<TextRange> changed;
  if (!tree_) {
    reparse(nullptr);
    if (tree_) changed.push_back({0, static_cast<uint32_t>(text_.size())});
    return changed;
  }
  TSTree* old_tree = tree_;
  ts_tree_edit(old_tree, &edit);
  tree_ = nullptr;
  reparse(old_tree);
  if (tree_) {
    uint32_t count = 0;
    TSRange* ranges = ts_tree_get_changed_ranges(old_tree, tree_, &count);
    for (uint32_t i = 0; i < count; ++i) changed.push_back({ranges[i].start_byte, ranges[i].end_byte});
    free(ranges);
    // An edit inside one token changes no structure; the token's own range still changed.
    if (changed.empty()) changed.push_back({begin, edit.new_end_byte});
  }
  ts_tree_delete(old_tree);
  return changed;
}

void SyntaxTree::for_each_token(const std::function<void(const Token&)>& visit) const {
  uint32_t cursor_offset = 0;
  const uint32_t size = static_cast<uint32_t>(text_.size());
  auto is_blank = [&](uint32_t from, uint32_t to) {
    for (uint32_t i = from; i < to; ++i) {
      char c = text_[i];
      if (c != ' ' && c != '\t' && c != '\r' && c != '\n' && c != '\f' && c != '\v') return false;
    }
    return true;
  };
  // Bytes no leaf covers are whitespace, or text an ERROR node skipped without making tokens.
  auto emit_gap = [&](uint32_t upto) {
    if (upto > cursor_offset) {
      Token::Kind k = is_blank(cursor_offset, upto) ? Token::Kind::Whitespace : Token::Kind::Error;
      visit(Token{k, {cursor_offset, upto}, {}});
      cursor_offset = upto;
    }
  };
  if (tree_) {
    TSTreeCursor cursor = ts_tree_cursor_new(ts_tree_root_node(tree_));
    // Iterative pre-order walk: deep trees (thousands of nested parentheses) must not recurse.
    bool descending = true;
    while (true) {
      TSNode node = ts_tree_cursor_current_node(&cursor);
      if (descending) {
        bool leaf = ts_node_child_count(node) == 0;
        std::string_view kind = ts_node_type(node);
        bool trivia_leaf = ts_node_is_extra(node) &&
                           (kind == "comment" || kind == "pragma" || kind == "line_comment" || kind == "block_comment");
        if (leaf || trivia_leaf) {
          uint32_t b = std::min(ts_node_start_byte(node), size);
          uint32_t e = std::min(ts_node_end_byte(node), size);
          if (e > b && b >= cursor_offset) {
            emit_gap(b);
            Token::Kind k = Token::Kind::Token;
            if (ts_node_is_extra(node) && kind.find("comment") != std::string_view::npos)
              k = Token::Kind::Comment;
            else if (ts_node_is_extra(node) && kind.find("pragma") != std::string_view::npos)
              k = Token::Kind::Pragma;
            else if (ts_node_symbol(node) == static_cast<TSSymbol>(-1))
              k = Token::Kind::Error;
            visit(Token{k, {b, e}, kind});
            cursor_offset = e;
          }
          descending = false;
          continue;
        }
        if (ts_tree_cursor_goto_first_child(&cursor)) continue;
        descending = false;
        continue;
      }
      if (ts_tree_cursor_goto_next_sibling(&cursor)) {
        descending = true;
        continue;
      }
      if (!ts_tree_cursor_goto_parent(&cursor)) break;
    }
    ts_tree_cursor_delete(&cursor);
  }
  emit_gap(size);
}

}  // namespace rung
