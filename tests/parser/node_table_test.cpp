// The node table (parser/syntax_tree.hpp) says what tree-sitter's own tree says. Every SyntaxNode
// question is answered from the table after tree-sitter's tree is freed, so each answer is checked
// here against tree-sitter's node API on the same parse: kinds, ranges, flags, fields, parents,
// siblings, child counts, smallest-node lookups and the S-expression, on the seed corpus (broken
// examples included), the lint rule goldens and hand-made broken code.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <random>
#include <string>
#include <vector>

#include "parser/node_table_reader.hpp"
#include "parser/syntax_tree.hpp"
#include "parser/tree_printer.hpp"
#include "tests/support/test_paths.hpp"

namespace rung {
namespace {

// Whether the table node and the tree-sitter node are the same node (or both absent).
::testing::AssertionResult same(SyntaxNode node, TSNode raw) {
  if (ts_node_is_null(raw) || node.is_null()) {
    if (ts_node_is_null(raw) && node.is_null()) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << (node.is_null() ? "table: none" : "tree-sitter: none");
  }
  if (node.kind() == ts_node_type(raw) && node.begin() == ts_node_start_byte(raw) &&
      node.end() == ts_node_end_byte(raw)) {
    return ::testing::AssertionSuccess();
  }
  return ::testing::AssertionFailure() << "table " << node.kind() << " [" << node.begin() << "-" << node.end()
                                       << "] vs tree-sitter " << ts_node_type(raw) << " [" << ts_node_start_byte(raw)
                                       << "-" << ts_node_end_byte(raw) << "]";
}

// "(UNEXPECTED 'x')" becomes "(UNEXPECTED)": tree-sitter shows the character its lexer stopped at,
// which the tree does not keep (the table prints the error text's first character).
std::string without_unexpected_chars(std::string sexp) {
  const std::string marker = "(UNEXPECTED ";
  for (size_t at = sexp.find(marker); at != std::string::npos; at = sexp.find(marker, at + 1)) {
    const size_t from = at + marker.size() - 1;
    size_t to = from + 1;
    if (sexp.compare(to, 2, "'\\") == 0) {
      to += 4;  // '\n'
    } else if (sexp[to] == '\'') {
      to += 3;  // 'x'
    } else {
      to = sexp.find(')', to);  // a code point or INVALID
    }
    sexp.erase(from, to - from);
  }
  return sexp;
}

// Compares every node of `text`'s parse; returns how many nodes it compared.
size_t expect_table_matches_tree(const std::string& text, const std::string& name) {
  SyntaxTree::Options keep;
  keep.keep_parse_tree = true;
  const SyntaxTree tree = SyntaxTree::parse(text, keep);
  if (tree.aborted()) {
    ADD_FAILURE() << name << ": parse aborted";
    return 0;
  }
  const TSNode raw_root = ts_tree_root_node(tree.raw());
  const std::string expected_sexp = [&] {
    char* s = ts_node_string(raw_root);
    std::string out(s);
    free(s);  // NOLINT(cppcoreguidelines-no-malloc): tree-sitter allocates the string with malloc
    // ts_node_string also shows MISSING tokens of hidden rules (" (MISSING _il_newline)"), which
    // no node API reaches, the table included.
    for (size_t at = out.find(" (MISSING _"); at != std::string::npos; at = out.find(" (MISSING _", at)) {
      out.erase(at, out.find(')', at) + 1 - at);
    }
    return without_unexpected_chars(out);
  }();
  const std::string actual_sexp = without_unexpected_chars(print_sexp(tree.root()));
  if (actual_sexp != expected_sexp) {
    size_t at = 0;
    while (at < actual_sexp.size() && at < expected_sexp.size() && actual_sexp[at] == expected_sexp[at]) ++at;
    const size_t from = at > 80 ? at - 80 : 0;
    ADD_FAILURE() << name << ": S-expressions differ at " << at << "\n table:       ..."
                  << actual_sexp.substr(from, 160) << "\n tree-sitter: ..." << expected_sexp.substr(from, 160);
  }

  TSTreeCursor cursor = ts_tree_cursor_new(raw_root);
  uint32_t index = 0;
  const size_t count = tree.node_count();
  while (true) {
    const TSNode raw = ts_tree_cursor_current_node(&cursor);
    if (index >= count) {
      ADD_FAILURE() << name << ": the table has fewer nodes than the tree";
      break;
    }
    const SyntaxNode node(tree.root().table(), index);
    SCOPED_TRACE(name + " node " + std::to_string(index) + " " + std::string(node.kind()));
    EXPECT_TRUE(same(node, raw));
    EXPECT_EQ(node.symbol(), ts_node_symbol(raw));
    EXPECT_EQ(node.is_named(), ts_node_is_named(raw));
    EXPECT_EQ(node.is_extra(), ts_node_is_extra(raw));
    EXPECT_EQ(node.is_missing(), ts_node_is_missing(raw));
    EXPECT_EQ(node.has_error(), ts_node_has_error(raw));
    EXPECT_EQ(node.field_id(), index == 0 ? 0 : ts_tree_cursor_current_field_id(&cursor));
    EXPECT_EQ(node.child_count(), ts_node_child_count(raw));
    EXPECT_EQ(node.named_child_count(), ts_node_named_child_count(raw));
    // tree-sitter finds parents and siblings by descending from the root by byte range, which
    // cannot place a zero-width (MISSING) node; the table records the true parent.
    if (node.end() > node.begin()) {
      EXPECT_TRUE(same(node.parent(), ts_node_parent(raw)));
      EXPECT_TRUE(same(node.next_sibling(), ts_node_next_sibling(raw)));
      EXPECT_TRUE(same(node.prev_sibling(), ts_node_prev_sibling(raw)));
      EXPECT_TRUE(same(node.next_named_sibling(), ts_node_next_named_sibling(raw)));
    }
    if (ts_node_child_count(raw) > 0) {
      EXPECT_TRUE(same(node.child(0), ts_node_child(raw, 0)));
      EXPECT_TRUE(same(node.named_child(0), ts_node_named_child(raw, 0)));
    }
    // Smallest-node lookups from the root, for the node's range and its first byte.
    const uint32_t b = node.begin();
    const uint32_t e = node.end();
    EXPECT_TRUE(same(tree.root().descendant_for_range(b, e), ts_node_descendant_for_byte_range(raw_root, b, e)));
    EXPECT_TRUE(same(tree.root().named_descendant_for_range(b, b + 1),
                     ts_node_named_descendant_for_byte_range(raw_root, b, b + 1)));
    ++index;
    if (ts_tree_cursor_goto_first_child(&cursor)) continue;
    bool done = false;
    while (!ts_tree_cursor_goto_next_sibling(&cursor)) {
      if (!ts_tree_cursor_goto_parent(&cursor)) {
        done = true;
        break;
      }
    }
    if (done) break;
  }
  ts_tree_cursor_delete(&cursor);
  EXPECT_EQ(index, count) << name << ": node counts differ";
  return index;
}

TEST(NodeTable, MatchesTreeSitterOnTheSeedCorpus) {
  size_t files = 0;
  size_t nodes = 0;
  size_t broken = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(test::shared_dir() / "corpus/seeds")) {
    if (!entry.is_regular_file()) continue;
    const std::string text = test::read_file(entry.path());
    nodes += expect_table_matches_tree(text, entry.path().filename().string());
    broken += SyntaxTree::parse(text).root().has_error() ? 1 : 0;
    ++files;
  }
  EXPECT_GT(files, 500u);
  EXPECT_GT(nodes, 30000u);
  EXPECT_GT(broken, 50u) << "the corpus's broken examples exercise ERROR and MISSING nodes";
}

TEST(NodeTable, MatchesTreeSitterOnTheLintGoldens) {
  size_t files = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(test::source_dir() / "tests/lint/rules")) {
    if (entry.path().extension() != ".st") continue;
    expect_table_matches_tree(test::read_file(entry.path()), entry.path().string());
    ++files;
  }
  EXPECT_GT(files, 80u);
}

TEST(NodeTable, MatchesTreeSitterOnBrokenCode) {
  for (const char* text : {
           "PROGRAM P\nVAR x : INT; END_VAR\nIF x > THEN x := 1;\n y := ) 2;\nEND_PROGRAM\n(* open",
           "x := ;",
           "x + 1;",
           "FUNCTION_BLOCK FB VAR_INPUT a : ; END_VAR",
           "\xEF\xBB\xBFPROGRAM P x := 'unterminated\nEND_PROGRAM",
           "PROGRAM P\n\xC3\xA4 := \xE2\x82\xAC;\nEND_PROGRAM",
           "",
           "   \n\t",
       }) {
    expect_table_matches_tree(text, std::string("broken: ") + text);
  }
}

TEST(NodeTable, NodesAreTwentyBytesAndTheParseTreeIsFreed) {
  const SyntaxTree tree = SyntaxTree::parse("PROGRAM P\nVAR x : INT; END_VAR\nx := x + 1;\nEND_PROGRAM\n");
  EXPECT_EQ(tree.raw(), nullptr) << "without keep_parse_tree only the table stays";
  EXPECT_GT(tree.node_count(), 10u);
  EXPECT_EQ(sizeof(NodeTable::Node), 20u);
  // Walking, skipping and identity work on the table alone.
  size_t assignments = 0;
  walk_preorder(tree.root(), [&](SyntaxNode node) {
    assignments += node.kind() == "assignment_statement" ? 1 : 0;
    return node.kind() != "var_block";
  });
  EXPECT_EQ(assignments, 1u);
  EXPECT_NE(tree.root().identity(), tree.root().child(0).identity());
}

}  // namespace
}  // namespace rung

namespace rung {
namespace {

// After every incremental edit the spliced table equals a full read of the new parse tree.
size_t expect_edits_keep_table_exact(const std::string& text, const std::string& name, uint32_t seed) {
  SyntaxTree::Options keep;
  keep.keep_parse_tree = true;
  SyntaxTree tree = SyntaxTree::parse(text, keep);
  std::mt19937 random(seed);
  const std::vector<std::string> insertions = {"",    ";",   "x",  " IF a THEN ",   "END_IF;",    "(*", "*)", "\n", "'",
                                               "1.5", "VAR", ":=", "b := c + 1;\n", "END_PROGRAM"};
  size_t spliced = 0;
  for (int round = 0; round < 40 && !tree.aborted(); ++round) {
    const auto size = static_cast<uint32_t>(tree.text().size());
    const uint32_t begin = size == 0 ? 0 : random() % (size + 1);
    const uint32_t end = std::min(size, begin + static_cast<uint32_t>(random() % 6));
    const std::string& insert = insertions[random() % insertions.size()];
    const std::vector<TextRange> changed = tree.apply_edit(begin, end, insert);
    if (tree.aborted()) break;
    EXPECT_FALSE(changed.empty());
    NodeTable full;
    read_node_table(tree.raw(), full);
    const std::vector<NodeTable::Node>& nodes = tree.root().table()->nodes;
    // RUNG_SPLICE_DUMP=1 prints both tables of a failing edit.
    const auto dump = [&] {
      if (std::getenv("RUNG_SPLICE_DUMP")) {
        std::cerr << "edit " << begin << "-" << end << " '" << insert << "'\n";
        for (const auto& r : changed) std::cerr << "changed " << r.begin << "-" << r.end << "\n";
        for (size_t i = 0; i < std::max(nodes.size(), full.nodes.size()); ++i) {
          if (i < nodes.size())
            std::cerr << i << " " << NodeTable::kind_name(nodes[i].symbol) << " [" << nodes[i].begin << "-"
                      << nodes[i].end << "] p" << nodes[i].parent << " e" << nodes[i].subtree_end << "    ";
          if (i < full.nodes.size())
            std::cerr << NodeTable::kind_name(full.nodes[i].symbol) << " [" << full.nodes[i].begin << "-"
                      << full.nodes[i].end << "] p" << full.nodes[i].parent << " e" << full.nodes[i].subtree_end;
          std::cerr << "\n";
        }
        std::cerr << tree.text() << "\n";
      }
    };
    if (nodes.size() != full.nodes.size()) {
      ADD_FAILURE() << name << " round " << round << ": " << nodes.size() << " nodes, a full read has "
                    << full.nodes.size();
      dump();
      return spliced;
    }
    for (size_t i = 0; i < nodes.size(); ++i) {
      const NodeTable::Node& a = nodes[i];
      const NodeTable::Node& b = full.nodes[i];
      if (!(a.begin == b.begin && a.end == b.end && a.subtree_end == b.subtree_end && a.parent == b.parent &&
            a.symbol == b.symbol && a.field == b.field && a.flags == b.flags)) {
        ADD_FAILURE() << name << " round " << round << " node " << i << " " << NodeTable::kind_name(b.symbol)
                      << ": spliced [" << a.begin << "-" << a.end << "] end " << a.subtree_end << " parent " << a.parent
                      << " field " << int{a.field} << " flags " << int{a.flags} << "; read [" << b.begin << "-" << b.end
                      << "] end " << b.subtree_end << " parent " << b.parent << " field " << int{b.field} << " flags "
                      << int{b.flags};
        dump();
        return spliced;
      }
    }
    EXPECT_EQ(tree.root().table()->sorted, full.sorted);
    ++spliced;
  }
  return spliced;
}

TEST(NodeTable, IncrementalEditsSpliceTheTableExactly) {
  const char* every_env = std::getenv("RUNG_SPLICE_EVERY");  // 1: every seed (slow; default every 8th)
  const size_t every = every_env ? std::max(1, std::atoi(every_env)) : 8;
  const char* seed_env = std::getenv("RUNG_SPLICE_SEED");  // other random edits
  size_t files = 0;
  size_t edits = 0;
  uint32_t seed = seed_env ? static_cast<uint32_t>(std::atoi(seed_env)) * 1000 + 1 : 1;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(test::shared_dir() / "corpus/seeds")) {
    if (!entry.is_regular_file() || ++files % every != 0) continue;
    edits += expect_edits_keep_table_exact(test::read_file(entry.path()), entry.path().filename().string(), seed++);
  }
  EXPECT_GT(edits, 2000u);
}

}  // namespace
}  // namespace rung
