#include "parser/syntax_tree.hpp"

#include <gtest/gtest.h>

#include <string>

#include "parser/tree_printer.hpp"

namespace rung {
namespace {

constexpr const char* kProgram = R"(PROGRAM Main
VAR
  x : INT := 1; (* counter *)
  {attribute 'hide'}
  y : BOOL;
END_VAR
x := x + 1; // step
IF x > 10 THEN y := TRUE; END_IF
END_PROGRAM
)";

TEST(SyntaxTree, ParsesProgramWithoutErrors) {
  SyntaxTree tree = SyntaxTree::parse(kProgram);
  ASSERT_FALSE(tree.aborted());
  EXPECT_EQ(tree.root().kind(), "source_file");
  EXPECT_FALSE(tree.root().has_error()) << print_sexp(tree.root());
  SyntaxNode program = tree.root().named_child(0);
  EXPECT_EQ(program.kind(), "program_declaration");
  EXPECT_EQ(program.child_by_field("name").text(), "Main");
}

TEST(SyntaxTree, TokensTileTheTextExactlyAndKeepTrivia) {
  SyntaxTree tree = SyntaxTree::parse(kProgram);
  std::string rebuilt;
  uint32_t expected_begin = 0;
  int comments = 0, pragmas = 0;
  tree.for_each_token([&](const Token& t) {
    EXPECT_EQ(t.range.begin, expected_begin);
    expected_begin = t.range.end;
    rebuilt += tree.text().substr(t.range.begin, t.range.end - t.range.begin);
    if (t.kind == Token::Kind::Comment) ++comments;
    if (t.kind == Token::Kind::Pragma) ++pragmas;
  });
  EXPECT_EQ(rebuilt, tree.text());
  EXPECT_EQ(comments, 2);
  EXPECT_EQ(pragmas, 1);
}

TEST(SyntaxTree, IncrementalEditMatchesFreshParse) {
  SyntaxTree::Options keep;
  keep.keep_parse_tree = true;
  for (const bool incremental : {true, false}) {
    SyntaxTree tree = SyntaxTree::parse(kProgram, incremental ? keep : SyntaxTree::Options{});
    EXPECT_EQ(tree.raw() != nullptr, incremental);
    std::string text = kProgram;
    size_t at = text.find("x + 1");
    ASSERT_NE(at, std::string::npos);
    auto changed = tree.apply_edit(static_cast<uint32_t>(at + 4), static_cast<uint32_t>(at + 5), "42");
    text.replace(at + 4, 1, "42");
    EXPECT_EQ(tree.text(), text);
    ASSERT_FALSE(changed.empty());
    if (incremental) {
      // Only the edited literal changed: tree-sitter compared the old and the new tree.
      EXPECT_LE(changed.front().begin, at + 4);
      EXPECT_LT(changed.back().end, text.size());
    } else {
      // Without the old tree the whole text counts as changed.
      EXPECT_EQ(changed.front().begin, 0u);
      EXPECT_EQ(changed.front().end, text.size());
    }
    SyntaxTree fresh = SyntaxTree::parse(text);
    EXPECT_EQ(print_sexp(tree.root()), print_sexp(fresh.root()));
    EXPECT_FALSE(tree.root().has_error());
  }
}

TEST(SyntaxTree, EditThatBreaksAndRepairsCode) {
  SyntaxTree tree = SyntaxTree::parse(kProgram);
  std::string text = kProgram;
  size_t at = text.find("END_IF");
  tree.apply_edit(static_cast<uint32_t>(at), static_cast<uint32_t>(at + 6), "");
  EXPECT_TRUE(tree.root().has_error());
  tree.apply_edit(static_cast<uint32_t>(at), static_cast<uint32_t>(at), "END_IF");
  EXPECT_EQ(tree.text(), text);
  EXPECT_FALSE(tree.root().has_error());
}

TEST(SyntaxTree, EditsAreClampedToTheText) {
  SyntaxTree tree = SyntaxTree::parse("x := 1;");
  tree.apply_edit(100, 200, " y := 2;");
  EXPECT_EQ(tree.text(), "x := 1; y := 2;");
  tree.apply_edit(5, 2, "");  // end before begin: treated as an insertion point
  EXPECT_EQ(tree.text(), "x := 1; y := 2;");
}

TEST(SyntaxTree, KeywordsAreCaseInsensitive) {
  SyntaxTree upper = SyntaxTree::parse("PROGRAM P VAR a : INT; END_VAR IF a = 1 THEN a := 2; END_IF END_PROGRAM");
  SyntaxTree lower = SyntaxTree::parse("program P var a : int; end_var if a = 1 then a := 2; end_if end_program");
  SyntaxTree mixed = SyntaxTree::parse("Program P Var a : Int; End_Var If a = 1 Then a := 2; End_If End_Program");
  EXPECT_FALSE(upper.root().has_error());
  EXPECT_EQ(print_sexp(upper.root()), print_sexp(lower.root()));
  EXPECT_EQ(print_sexp(upper.root()), print_sexp(mixed.root()));
}

TEST(TreePrinter, OutlineShowsFieldsAndText) {
  SyntaxTree tree = SyntaxTree::parse("PROGRAM Main\nEND_PROGRAM\n");
  std::string outline = print_outline(tree.root(), {});
  EXPECT_NE(outline.find("program_declaration"), std::string::npos) << outline;
  EXPECT_NE(outline.find("name: identifier"), std::string::npos) << outline;
  EXPECT_NE(outline.find("\"Main\""), std::string::npos) << outline;
}

}  // namespace
}  // namespace rung
