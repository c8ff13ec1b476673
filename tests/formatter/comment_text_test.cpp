// How a comment is printed: blanks before its line ends go, everything else stays.
#include "formatter/comment_text.hpp"

#include <gtest/gtest.h>

namespace rung::format {
namespace {

TEST(CommentText, KnowsCommentsFromPragmas) {
  EXPECT_TRUE(is_comment("// x"));
  EXPECT_TRUE(is_comment("(* x *)"));
  EXPECT_TRUE(is_comment("/* x */"));
  EXPECT_FALSE(is_comment("{attribute 'x'}"));
  EXPECT_FALSE(is_comment("("));
}

TEST(CommentText, DropsBlanksBeforeLineEndsOnly) {
  EXPECT_EQ(printed_comment("// clean"), "// clean");
  EXPECT_EQ(printed_comment("(* a  b *)"), "(* a  b *)");
  EXPECT_EQ(printed_comment("// trailing \t "), "// trailing");
  // Inside a block comment: LF and CRLF lines, indentation and inner blanks kept.
  EXPECT_EQ(printed_comment("(* one \n\t two  \r\n three *)"), "(* one\n\t two\r\n three *)");
  // A blank-only line becomes empty; a bare carriage return is no line end of its own.
  EXPECT_EQ(printed_comment("(*\n   \n*)"), "(*\n\n*)");
  EXPECT_EQ(printed_comment("(* a \r b *)"), "(* a \r b *)");
}

TEST(CommentText, AppendsAfterWhatIsThere) {
  std::string out = "x := 1; ";
  append_printed_comment(out, "// note  ");
  EXPECT_EQ(out, "x := 1; // note");
}

}  // namespace
}  // namespace rung::format
