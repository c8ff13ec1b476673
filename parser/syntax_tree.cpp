#include "parser/syntax_tree.hpp"

#include <algorithm>
#include <cstring>
#include <unordered_map>
#include <utility>

#include "parser/node_table_reader.hpp"

namespace rung {

std::string_view SyntaxNode::text() const {
  if (is_null()) return {};
  const std::string_view source = table_->text;
  const uint32_t size = static_cast<uint32_t>(source.size());
  const uint32_t b = std::min(node().begin, size);
  const uint32_t e = std::min(node().end, size);
  return source.substr(b, e > b ? e - b : 0);
}

std::string_view NodeTable::kind_name(TSSymbol symbol) {
  static const std::vector<std::string_view> names = [] {
    const TSLanguage* language = tree_sitter_iec61131();
    std::vector<std::string_view> table(ts_language_symbol_count(language));
    for (uint32_t id = 0; id < table.size(); ++id) {
      const char* name = ts_language_symbol_name(language, static_cast<TSSymbol>(id));
      table[id] = name ? std::string_view(name) : std::string_view();
    }
    return table;
  }();
  if (symbol < names.size()) return names[symbol];
  // ERROR and the runtime's other built-in symbols are not in the grammar's table.
  const char* name = ts_language_symbol_name(tree_sitter_iec61131(), symbol);
  return name ? std::string_view(name) : std::string_view();
}

// Fields are matched by id, and the name lookup is one hash: it runs on every child_by_field().
TSFieldId NodeTable::field_id(std::string_view name) {
  static const std::unordered_map<std::string_view, TSFieldId> ids = [] {
    std::unordered_map<std::string_view, TSFieldId> out;
    const TSLanguage* language = tree_sitter_iec61131();
    const uint32_t count = ts_language_field_count(language);
    for (uint32_t id = 1; id <= count; ++id) {
      if (const char* field = ts_language_field_name_for_id(language, static_cast<TSFieldId>(id))) {
        out.emplace(field, static_cast<TSFieldId>(id));
      }
    }
    return out;
  }();
  const auto found = ids.find(name);
  return found == ids.end() ? TSFieldId{0} : found->second;
}

std::string_view NodeTable::field_name(TSFieldId id) {
  if (id == 0) return {};
  const char* name = ts_language_field_name_for_id(tree_sitter_iec61131(), id);
  return name ? std::string_view(name) : std::string_view();
}

uint32_t SyntaxNode::count_children(bool named_only) const {
  uint32_t count = 0;
  for_each_child([&](SyntaxNode child) { count += !named_only || child.is_named() ? 1 : 0; });
  return count;
}

SyntaxNode SyntaxNode::nth_child(uint32_t index, bool named_only) const {
  if (is_null()) return {};
  const auto& nodes = table_->nodes;
  uint32_t seen = 0;
  for (uint32_t c = index_ + 1; c < nodes[index_].subtree_end; c = nodes[c].subtree_end) {
    if ((!named_only || (nodes[c].flags & NodeTable::kNamed) != 0) && seen++ == index) return at(c);
  }
  return {};
}

SyntaxNode SyntaxNode::child_by_field_id(TSFieldId field) const {
  if (is_null() || field == 0) return {};
  const auto& nodes = table_->nodes;
  for (uint32_t c = index_ + 1; c < nodes[index_].subtree_end; c = nodes[c].subtree_end) {
    if (nodes[c].field == field) return at(c);
  }
  return {};
}

std::vector<SyntaxNode> SyntaxNode::children_by_field(std::string_view field) const {
  std::vector<SyntaxNode> out;
  const TSFieldId id = NodeTable::field_id(field);
  if (id == 0) return out;
  for_each_child([&](SyntaxNode child) {
    if (child.node().field == id) out.push_back(child);
  });
  return out;
}

std::string_view SyntaxNode::field_name_of_child(uint32_t index) const {
  return NodeTable::field_name(child(index).field_id());
}

std::vector<SyntaxNode> SyntaxNode::children_of_kind(std::string_view kind) const {
  std::vector<SyntaxNode> out;
  for_each_child([&](SyntaxNode child) {
    if (child.is_named() && child.kind() == kind) out.push_back(child);
  });
  return out;
}

std::vector<SyntaxNode> SyntaxNode::named_children() const {
  std::vector<SyntaxNode> out;
  for_each_child([&](SyntaxNode child) {
    if (child.is_named()) out.push_back(child);
  });
  return out;
}

SyntaxNode SyntaxNode::first_child_of_kind(std::string_view kind) const {
  if (is_null()) return {};
  const auto& nodes = table_->nodes;
  for (uint32_t c = index_ + 1; c < nodes[index_].subtree_end; c = nodes[c].subtree_end) {
    if ((nodes[c].flags & NodeTable::kNamed) != 0 && NodeTable::kind_name(nodes[c].symbol) == kind) return at(c);
  }
  return {};
}

SyntaxNode SyntaxNode::parent() const {
  return is_null() ? SyntaxNode() : at(node().parent);
}

SyntaxNode SyntaxNode::next_sibling() const {
  if (is_null() || node().parent == NodeTable::kNone) return {};
  const uint32_t next = node().subtree_end;
  return next < table_->nodes[node().parent].subtree_end ? at(next) : SyntaxNode();
}

SyntaxNode SyntaxNode::prev_sibling() const {
  if (is_null() || node().parent == NodeTable::kNone) return {};
  const auto& nodes = table_->nodes;
  uint32_t previous = NodeTable::kNone;
  for (uint32_t c = node().parent + 1; c < index_; c = nodes[c].subtree_end) previous = c;
  return at(previous);
}

SyntaxNode SyntaxNode::next_named_sibling() const {
  SyntaxNode next = next_sibling();
  while (next && !next.is_named()) next = next.next_sibling();
  return next;
}

// The descent of tree-sitter's ts_node_descendant_for_byte_range, over the visible nodes: take the
// first child that reaches past the range's end (and past its start) and starts at or before its
// start; the answer is the deepest such node (named, when asked).
SyntaxNode SyntaxNode::descendant(uint32_t range_begin, uint32_t range_end, bool named_only) const {
  if (is_null()) return {};
  const auto& nodes = table_->nodes;
  uint32_t current = index_;
  uint32_t answer = index_;
  for (bool descended = true; descended;) {
    descended = false;
    for (uint32_t c = current + 1; c < nodes[current].subtree_end; c = nodes[c].subtree_end) {
      if (nodes[c].end < range_end || nodes[c].end <= range_begin) continue;
      if (range_begin < nodes[c].begin) break;
      current = c;
      if (!named_only || (nodes[c].flags & NodeTable::kNamed) != 0) answer = c;
      descended = true;
      break;
    }
  }
  return at(answer);
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

// One parser per thread, reused for every parse: a parser owns stacks and a lexer of its own.
TSParser* thread_parser() {
  struct Owner {
    TSParser* parser = ts_parser_new();
    Owner() { ts_parser_set_language(parser, tree_sitter_iec61131()); }
    ~Owner() { ts_parser_delete(parser); }
    Owner(const Owner&) = delete;
    Owner& operator=(const Owner&) = delete;
  };
  thread_local Owner owner;
  return owner.parser;
}

}  // namespace

SyntaxTree SyntaxTree::parse(std::string text, Options options) {
  static_assert(sizeof(NodeTable::Node) == 20, "a node table entry is 20 bytes");
  SyntaxTree tree;
  tree.table_ = std::make_unique<NodeTable>();
  tree.table_->text = std::move(text);
  tree.options_ = options;
  TSTree* parsed = tree.parse_text(nullptr);
  if (parsed) read_node_table(parsed, *tree.table_);
  tree.keep_or_delete(parsed);
  return tree;
}

TSTree* SyntaxTree::parse_text(const TSTree* old_tree) const {
  const std::string& text = table_->text;
  uint64_t timeout = options_.timeout_micros;
  if (timeout == 0) {
    // Generous: a healthy parse runs at several MB/s; this budget only stops pathological cases.
    timeout = 2'000'000 + static_cast<uint64_t>(text.size()) * 2;
  }
  TSParser* parser = thread_parser();
  ts_parser_set_timeout_micros(parser, timeout);
  ts_parser_reset(parser);
  TSTree* parsed = ts_parser_parse_string(parser, old_tree, text.data(), static_cast<uint32_t>(text.size()));
  ts_parser_reset(parser);  // a timed-out parse must not resume on the next text
  return parsed;
}

void SyntaxTree::keep_or_delete(TSTree* parsed) {
  if (parsed && options_.keep_parse_tree) {
    tree_ = parsed;
  } else if (parsed) {
    ts_tree_delete(parsed);
  }
}

SyntaxTree::SyntaxTree(SyntaxTree&& other) noexcept
    : table_(std::move(other.table_)), options_(other.options_), tree_(std::exchange(other.tree_, nullptr)) {
  other.table_ = std::make_unique<NodeTable>();
}

SyntaxTree& SyntaxTree::operator=(SyntaxTree&& other) noexcept {
  if (this != &other) {
    if (tree_) ts_tree_delete(tree_);
    table_ = std::exchange(other.table_, std::make_unique<NodeTable>());
    options_ = other.options_;
    tree_ = std::exchange(other.tree_, nullptr);
  }
  return *this;
}

SyntaxTree::~SyntaxTree() {
  if (tree_) ts_tree_delete(tree_);
}

SyntaxNode SyntaxTree::root() const {
  if (aborted()) return {};
  return SyntaxNode(table_.get(), 0);
}

std::vector<TextRange> SyntaxTree::apply_edit(uint32_t begin, uint32_t end, std::string_view replacement) {
  std::string& text = table_->text;
  const uint32_t size = static_cast<uint32_t>(text.size());
  begin = std::min(begin, size);
  end = std::clamp(end, begin, size);

  TSInputEdit edit{};
  edit.start_byte = begin;
  edit.old_end_byte = end;
  edit.new_end_byte = begin + static_cast<uint32_t>(replacement.size());
  edit.start_point = point_at(text, begin);
  edit.old_end_point = point_at(text, end);
  edit.new_end_point = advance_point(edit.start_point, replacement);

  text.replace(begin, end - begin, replacement);

  std::vector<TextRange> changed;
  TSTree* old_tree = std::exchange(tree_, nullptr);
  if (old_tree) ts_tree_edit(old_tree, &edit);
  TSTree* parsed = parse_text(old_tree);
  if (!parsed) {
    table_->nodes.clear();  // timed out: no tree, and nothing to compare with
  } else if (old_tree) {
    uint32_t count = 0;
    TSRange* ranges = ts_tree_get_changed_ranges(old_tree, parsed, &count);
    for (uint32_t i = 0; i < count; ++i) changed.push_back({ranges[i].start_byte, ranges[i].end_byte});
    free(ranges);  // NOLINT(cppcoreguidelines-no-malloc): tree-sitter allocates the ranges with malloc
    if (!splice_node_table(*table_, parsed, edit, changed)) read_node_table(parsed, *table_);
    // An edit inside one token changes no structure; the token's own range still changed.
    if (changed.empty()) changed.push_back({begin, edit.new_end_byte});
  } else {
    read_node_table(parsed, *table_);
    changed.push_back({0, static_cast<uint32_t>(text.size())});  // no old tree to compare with
  }
  keep_or_delete(parsed);
  if (old_tree) ts_tree_delete(old_tree);
  return changed;
}

void SyntaxTree::for_each_token(const std::function<void(const Token&)>& visit) const {
  const std::string& text = table_->text;
  const uint32_t size = static_cast<uint32_t>(text.size());
  uint32_t cursor_offset = 0;
  auto is_blank = [&](uint32_t from, uint32_t to) {
    for (uint32_t i = from; i < to; ++i) {
      const char c = text[i];
      if (c != ' ' && c != '\t' && c != '\r' && c != '\n' && c != '\f' && c != '\v') return false;
    }
    return true;
  };
  // Bytes no leaf covers are whitespace, or text an ERROR node skipped without making tokens.
  auto emit_gap = [&](uint32_t upto) {
    if (upto > cursor_offset) {
      const Token::Kind k = is_blank(cursor_offset, upto) ? Token::Kind::Whitespace : Token::Kind::Error;
      visit(Token{k, {cursor_offset, upto}, {}});
      cursor_offset = upto;
    }
  };
  const auto& nodes = table_->nodes;
  for (uint32_t i = 0; i < nodes.size();) {
    const NodeTable::Node& node = nodes[i];
    const bool leaf = node.subtree_end == i + 1;
    const bool extra = (node.flags & NodeTable::kExtra) != 0;
    const std::string_view kind = NodeTable::kind_name(node.symbol);
    const bool trivia_leaf =
        extra && (kind == "comment" || kind == "pragma" || kind == "line_comment" || kind == "block_comment");
    if (!leaf && !trivia_leaf) {
      ++i;
      continue;
    }
    const uint32_t b = std::min(node.begin, size);
    const uint32_t e = std::min(node.end, size);
    if (e > b && b >= cursor_offset) {
      emit_gap(b);
      Token::Kind k = Token::Kind::Token;
      if (extra && kind.find("comment") != std::string_view::npos) {
        k = Token::Kind::Comment;
      } else if (extra && kind.find("pragma") != std::string_view::npos) {
        k = Token::Kind::Pragma;
      } else if (node.symbol == NodeTable::kErrorSymbol) {
        k = Token::Kind::Error;
      }
      visit(Token{k, {b, e}, kind});
      cursor_offset = e;
    }
    i = node.subtree_end;
  }
  emit_gap(size);
}

}  // namespace rung
