#include "parser/source/flat_comments.hpp"

#include <gtest/gtest.h>

namespace rung::source {
namespace {

TEST(FlatComments, InnerOpenersAreBlankedOnlyInsideComments) {
  std::string text = "(* a (* b *) x := '(*'; // (* line\n y := 1; (* c (* d *)";
  std::string original = text;
  EXPECT_EQ(read_comments_flat(text, 0, text.size()), 2u);
  EXPECT_EQ(text.size(), original.size());
  EXPECT_EQ(text, "(* a  * b *) x := '(*'; // (* line\n y := 1; (* c  * d *)");
}

TEST(FlatComments, RespectsTheRangeAndStringEscapes) {
  std::string text = "(* (* *) s := 'it$'s (* not a comment'; (* (* *)";
  EXPECT_EQ(read_comments_flat(text, 10, text.size()), 1u);
  EXPECT_EQ(text.substr(0, 8), "(* (* *)");  // before the range: untouched
  EXPECT_NE(text.find("'it$'s (* not a comment'"), std::string::npos);
}

}  // namespace
}  // namespace rung::source
