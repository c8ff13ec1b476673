// The keyword knowledge behind the syntax checks: which words are reserved, and which keyword a
// misspelled word stands for (and which names are no misspelling at all).
#include "parser/keywords.hpp"

#include <gtest/gtest.h>

namespace rung::keywords {
namespace {

TEST(Keywords, ReservedWordsIgnoreCase) {
  EXPECT_TRUE(is_reserved("While"));
  EXPECT_TRUE(is_reserved("program"));
  EXPECT_TRUE(is_reserved("END_VAR"));
  EXPECT_TRUE(is_reserved("Retain"));
  EXPECT_TRUE(is_reserved("real"));
  // Contextual words real code uses as names, IL operators and SFC qualifiers are not reserved.
  EXPECT_FALSE(is_reserved("Step"));
  EXPECT_FALSE(is_reserved("Method"));
  EXPECT_FALSE(is_reserved("Type"));
  EXPECT_FALSE(is_reserved("Q"));
  EXPECT_FALSE(is_reserved("S"));
  EXPECT_FALSE(is_reserved("N"));
  EXPECT_FALSE(is_reserved("Program1"));
}

TEST(Keywords, IlOperatorsAndFunctionsThatAreKeywords) {
  EXPECT_TRUE(is_il_operator("ld"));
  EXPECT_TRUE(is_il_operator("JMPCN"));
  EXPECT_TRUE(is_il_operator("AND"));
  EXPECT_FALSE(is_il_operator("END_VAR"));
  EXPECT_FALSE(is_il_operator("MAX"));  // a function, called like an operator
  EXPECT_TRUE(is_type_name("time"));
  EXPECT_FALSE(is_type_name("END_TYPE"));
  EXPECT_TRUE(is_operator_word("Mod"));
  EXPECT_FALSE(is_operator_word("ADD"));
}

TEST(Keywords, ClosingWordsUpToTwoLettersOff) {
  EXPECT_EQ(misspelled("ENDIF", false), "END_IF");
  EXPECT_EQ(misspelled("END_IFF", false), "END_IF");
  EXPECT_EQ(misspelled("end_functionblock", false), "END_FUNCTION_BLOCK");
  EXPECT_EQ(misspelled("ELSEIF", false), "ELSIF");
  EXPECT_EQ(misspelled("END_IF", false), "");
  EXPECT_EQ(misspelled("Endless", false), "");
}

TEST(Keywords, OpenersOnlyWhereADeclarationMayStart) {
  EXPECT_EQ(misspelled("VAR_GLOBAS", true), "VAR_GLOBAL");
  EXPECT_EQ(misspelled("PROGRAMM", true), "PROGRAM");
  EXPECT_EQ(misspelled("Functon", true), "FUNCTION");
  EXPECT_EQ(misspelled("PROGRAMM", false), "");
  // Numbered names and short words are names, not typing mistakes.
  EXPECT_EQ(misspelled("Program1", true), "");
  EXPECT_EQ(misspelled("Struct2", true), "");
  EXPECT_EQ(misspelled("END_IF2", true), "");
  EXPECT_EQ(misspelled("VARS", true), "");
  EXPECT_EQ(misspelled("Method", true), "");
}

TEST(Keywords, ClosersOfOpeners) {
  EXPECT_EQ(closer_of("var_global"), "END_VAR");
  EXPECT_EQ(closer_of("PROGRAM"), "END_PROGRAM");
  EXPECT_EQ(closer_of("IF"), "");
}

TEST(Keywords, EditDistance) {
  EXPECT_EQ(edit_distance("VAR_GLOBAS", "VAR_GLOBAL"), 1u);
  EXPECT_EQ(edit_distance("", "ABC"), 3u);
  EXPECT_EQ(edit_distance("KITTEN", "SITTING"), 3u);
}

}  // namespace
}  // namespace rung::keywords
