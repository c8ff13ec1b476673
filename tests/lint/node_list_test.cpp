// The index API the lint rules walk (checker/lint/node_list.hpp) says what the SyntaxNode API
// says: every node walk_preorder visits, in its order, with the same kind, range, flags, parent
// and field, on the golden rule files and on broken code (ERROR and missing nodes). Both read the
// tree's node table; tests/parser/node_table_test.cpp checks the table against tree-sitter.
#include "checker/lint/node_list.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "checker/symbols/names.hpp"
#include "parser/ast.hpp"
#include "tests/support/test_paths.hpp"

namespace rung::lint {
namespace {

std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// The field name a cursor reports for each child of `parent`, in order (SyntaxNode asks the same
// way in child_by_field).
std::vector<std::string_view> child_fields(SyntaxNode parent) {
  std::vector<std::string_view> fields;
  for (uint32_t i = 0; i < parent.child_count(); ++i) fields.push_back(parent.field_name_of_child(i));
  return fields;
}

// Compares the list with the tree node by node; returns how many nodes it compared.
size_t expect_same_as_tree(const SyntaxTree& tree, const std::string& name) {
  const NodeList nodes(tree.root());
  std::vector<SyntaxNode> walked;
  walk_preorder(tree.root(), [&](SyntaxNode node) {
    walked.push_back(node);
    return true;
  });
  EXPECT_EQ(nodes.size(), walked.size()) << name;
  for (uint32_t i = 0; i < nodes.size() && i < walked.size(); ++i) {
    const SyntaxNode node = walked[i];
    SCOPED_TRACE(name + " node " + std::to_string(i) + " " + std::string(node.kind()));
    EXPECT_TRUE(nodes.node(i) == node);
    EXPECT_EQ(nodes.kind(i), node.kind());
    EXPECT_EQ(nodes.begin(i), node.begin());
    EXPECT_EQ(nodes.end(i), node.end());
    EXPECT_EQ(nodes.text(i), node.text());
    EXPECT_EQ(nodes.is_named(i), node.is_named());
    EXPECT_EQ(nodes.is_extra(i), node.is_extra());
    EXPECT_EQ(nodes.is_missing(i), node.is_missing());
    EXPECT_EQ(nodes.has_error(i), node.has_error());
    EXPECT_EQ(nodes.is_error(i), node.is_error());
    EXPECT_EQ(nodes.has_children(i), node.child_count() > 0);
    EXPECT_EQ(nodes.index_of(node), i);
    const SyntaxNode parent = node.parent();
    if (i == 0) {
      EXPECT_EQ(nodes.parent(i), NodeList::kNone);
      continue;
    }
    if (nodes.parent(i) == NodeList::kNone) {
      ADD_FAILURE() << "no parent";
      continue;
    }
    EXPECT_TRUE(nodes.node(nodes.parent(i)) == parent);
    // In preorder a node's subtree is the run of nodes after it whose parents lie in the run.
    const uint32_t end = nodes.subtree_end(i);
    EXPECT_GT(end, i);
    for (uint32_t inside = i + 1; inside < end; ++inside) {
      EXPECT_GE(nodes.parent(inside), i) << "node " << inside << " is in the subtree but not below the node";
    }
    if (end < nodes.size()) {
      EXPECT_LT(nodes.parent(end), i) << "the subtree ends too early";
    }
  }
  // Fields: the list's children of each node carry the names a cursor reports.
  for (uint32_t i = 0; i < nodes.size(); ++i) {
    const std::vector<std::string_view> expected = child_fields(nodes.node(i));
    size_t child = 0;
    nodes.for_each_child(i, [&](uint32_t c) {
      ASSERT_LT(child, expected.size()) << name;
      const std::string_view field = expected[child++];
      EXPECT_EQ(nodes.field(c), field.empty() ? 0 : NodeList::field_id(field)) << name << " node " << c;
    });
    EXPECT_EQ(child, expected.size()) << name << " node " << i;
  }
  return nodes.size();
}

TEST(NodeList, MatchesTheTreeOnEveryGoldenRuleFile) {
  const std::filesystem::path rules = rung::test::source_dir() / "tests/lint/rules";
  size_t files = 0;
  size_t compared = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(rules)) {
    if (entry.path().extension() != ".st") continue;
    const SyntaxTree tree = SyntaxTree::parse(read_file(entry.path()));
    ASSERT_FALSE(tree.aborted()) << entry.path();
    compared += expect_same_as_tree(tree, entry.path().string());
    ++files;
  }
  EXPECT_GT(files, 80u);
  EXPECT_GT(compared, 10000u);
}

TEST(NodeList, MatchesTheTreeOnBrokenCode) {
  // A missing END_IF, a stray token, an unterminated comment: ERROR and missing nodes.
  const SyntaxTree tree =
      SyntaxTree::parse("PROGRAM P\nVAR x : INT; END_VAR\nIF x > THEN x := 1;\n y := ) 2;\nEND_PROGRAM\n(* open");
  ASSERT_TRUE(tree.root().has_error());
  expect_same_as_tree(tree, "broken");
}

TEST(NodeList, AnswersFieldAndOperatorQuestionsLikeTheTree) {
  const SyntaxTree tree = SyntaxTree::parse(
      "PROGRAM P\nVAR a, b : BOOL; i : INT; END_VAR\n"
      "IF a AND_THEN b THEN i := -1; END_IF\nWHILE NOT a DO a := TRUE; END_WHILE\nEND_PROGRAM\n");
  const NodeList nodes(tree.root());
  size_t operators = 0;
  for (uint32_t i = 0; i < nodes.size(); ++i) {
    const SyntaxNode node = nodes.node(i);
    for (std::string_view field : {"condition", "body", "left", "right", "operand", "operator"}) {
      const uint32_t child = nodes.child_by_field(i, NodeList::field_id(field));
      const SyntaxNode expected = node.child_by_field(field);
      EXPECT_EQ(child, expected ? nodes.index_of(expected) : NodeList::kNone) << node.kind() << " " << field;
    }
    if (nodes.kind(i) == "binary_expression" || nodes.kind(i) == "unary_expression") {
      EXPECT_EQ(check::upper_name(operator_text(nodes, i)), ast::operator_of(node));
      ++operators;
    }
  }
  EXPECT_EQ(operators, 3u);
  EXPECT_EQ(NodeList::field_id("no_such_field"), 0);
  EXPECT_TRUE(NodeList().empty());
}

}  // namespace
}  // namespace rung::lint
