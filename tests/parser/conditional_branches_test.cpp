#include "parser/conditional_branches.hpp"

#include <gtest/gtest.h>

#include <algorithm>

namespace rung {
namespace {

TEST(ConditionalBranches, KeepsTheFirstBranchOfEveryGroupIncludingNestedOnes) {
  std::string text =
      "{IF defined(A)}\na := 1;\n{IF defined(B)}\nb := 1;\n{ELSE}\nb := 2;\n{END_IF}\n{ELSIF defined(C)}\na := 2;\n"
      "{ELSE}\na := 3;\n{END_IF}\n";
  SyntaxTree tree = SyntaxTree::parse(text);
  std::string out = text;
  EXPECT_GT(keep_first_conditional_branches(tree, out), 0u);
  ASSERT_EQ(out.size(), text.size());
  EXPECT_NE(out.find("a := 1;"), std::string::npos);
  EXPECT_NE(out.find("b := 1;"), std::string::npos);
  EXPECT_EQ(out.find("b := 2;"), std::string::npos);
  EXPECT_EQ(out.find("a := 2;"), std::string::npos);
  EXPECT_EQ(out.find("a := 3;"), std::string::npos);
  EXPECT_EQ(std::count(out.begin(), out.end(), '\n'), std::count(text.begin(), text.end(), '\n'));
  EXPECT_NE(out.find("{END_IF}"), std::string::npos);  // closing pragmas stay
}

TEST(ConditionalBranches, NothingToDoWithoutElseBranches) {
  std::string text = "{IF defined(A)}\na := 1;\n{END_IF}\n";
  SyntaxTree tree = SyntaxTree::parse(text);
  std::string out = text;
  EXPECT_EQ(keep_first_conditional_branches(tree, out), 0u);
  EXPECT_EQ(out, text);
}

}  // namespace
}  // namespace rung
