// The formatter's safety check, fed deliberately wrong "formatted" texts: it must name the first
// difference, and accept only whitespace, letter case of keywords and elementary type names, and
// the rewrites it can validate on the input's tree.
#include "formatter/token_check.hpp"

#include <gtest/gtest.h>

#include "formatter/format.hpp"
#include "formatter/rewrites.hpp"
#include "tests/formatter/check_samples.hpp"

namespace rung::format {
namespace {

std::optional<std::string> check(const std::string& input, const std::string& output,
                                 const std::vector<Rewrite>& rewrites = {}) {
  const SyntaxTree in = SyntaxTree::parse(input);
  const SyntaxTree out = SyntaxTree::parse(output);
  return check_tokens({&in, input}, {&out, output}, rewrites);
}

using test_samples::kProgram;

TEST(TokenCheck, AcceptsWhitespaceAndKeywordCase) {
  const std::string output =
      "program Main\nvar\n\tx:int;// counter\n\ts : string := 'abc';\nend_var\n(* body *)\n"
      "if x>0 then x:=x-1; end_if\nend_program\n";
  EXPECT_EQ(check(kProgram, output), std::nullopt);
}

TEST(TokenCheck, NamesAChangedIdentifierWithItsInputLine) {
  std::string output = kProgram;
  output.replace(output.find("x := x - 1"), 10, "x := y - 1");
  const auto problem = check(kProgram, output);
  ASSERT_TRUE(problem);
  EXPECT_EQ(*problem, "line 8: the formatter changed 'x' into 'y'");
}

TEST(TokenCheck, IdentifierCaseIsNotKeywordCase) {
  std::string output = kProgram;
  output.replace(output.find("Main"), 4, "MAIN");
  const auto problem = check(kProgram, output);
  ASSERT_TRUE(problem);
  EXPECT_NE(problem->find("'Main' into 'MAIN'"), std::string::npos) << *problem;
}

TEST(TokenCheck, StringsKeepTheirCase) {
  std::string output = kProgram;
  output.replace(output.find("'abc'"), 5, "'ABC'");
  const auto problem = check(kProgram, output);
  ASSERT_TRUE(problem);
  EXPECT_EQ(problem->rfind("line 4:", 0), 0u) << *problem;
}

TEST(TokenCheck, CatchesALostToken) {
  std::string output = kProgram;
  output.erase(output.find(" - 1"), 4);
  const auto problem = check(kProgram, output);
  ASSERT_TRUE(problem);
  EXPECT_EQ(problem->rfind("line 8:", 0), 0u) << *problem;
}

TEST(TokenCheck, CatchesAChangedOrMovedComment) {
  std::string changed = kProgram;
  changed.replace(changed.find("// counter"), 10, "//  counter");
  auto problem = check(kProgram, changed);
  ASSERT_TRUE(problem);
  EXPECT_EQ(*problem, "line 3: the formatter changed the comment '// counter'");

  // The same comments, in another order.
  std::string swapped = kProgram;
  swapped.replace(swapped.find("// counter"), 10, "(* body *)");
  swapped.replace(swapped.find("(* body *)\nIF"), 10, "// counter");
  problem = check(kProgram, swapped);
  ASSERT_TRUE(problem);
  EXPECT_EQ(problem->rfind("line 3:", 0), 0u) << *problem;

  std::string lost = kProgram;
  lost.erase(lost.find("(* body *)"), 10);
  problem = check(kProgram, lost);
  ASSERT_TRUE(problem);
  EXPECT_NE(problem->find("lost a comment"), std::string::npos) << *problem;
}

TEST(TokenCheck, AcceptsACommentWithoutBlanksAtItsLineEndsAndNothingElse) {
  const std::string input = "PROGRAM P\n// note \t\n(* one  \r\n   two\t*)\nEND_PROGRAM\n";
  EXPECT_EQ(check(input, "PROGRAM P\n// note\n(* one\r\n   two\t*)\nEND_PROGRAM\n"), std::nullopt);
  // Blanks inside a line, or the line break itself, are the comment's own.
  EXPECT_TRUE(check(input, "PROGRAM P\n// note\n(* one\r\n two\t*)\nEND_PROGRAM\n"));
  EXPECT_TRUE(check(input, "PROGRAM P\n// note\n(* one\n   two\t*)\nEND_PROGRAM\n"));
  EXPECT_TRUE(check(input, "PROGRAM P\n// note\n(* one\r\n   two*)\nEND_PROGRAM\n"));
}

TEST(TokenCheck, RefusesAnOutputThatDoesNotParse) {
  std::string output = kProgram;
  output.replace(output.find("END_IF"), 6, "END_FI");
  const auto problem = check(kProgram, output);
  ASSERT_TRUE(problem);
  EXPECT_NE(problem->find("does not parse"), std::string::npos) << *problem;
}

TEST(TokenCheck, JoinedWordsAreCaught) {
  // "x > 0 THEN" printed as "x > 0THEN" would still lex, but not as the same tokens.
  const std::string input = "IF a OR b THEN x := 1; END_IF\n";
  const auto problem = check(input, "IF aOR b THEN x := 1; END_IF\n");
  ASSERT_TRUE(problem);
}

TEST(TokenCheck, ValidatesEachSemicolonRewrite) {
  const std::string input = "IF a THEN x := 1; END_IF\ny := 2;\n";
  const uint32_t end_if = static_cast<uint32_t>(input.find("END_IF"));
  const std::string added = "IF a THEN x := 1; END_IF;\ny := 2;\n";
  EXPECT_EQ(check(input, added, {{Rewrite::Kind::AddSemicolon, end_if}}), std::nullopt);
  // Without the rewrite the same output is a changed token stream.
  EXPECT_TRUE(check(input, added));
  // A ';' "added" after a token that is no END_ keyword is refused.
  const uint32_t then = static_cast<uint32_t>(input.find("THEN"));
  const auto problem = check(input, "IF a THEN; x := 1; END_IF\ny := 2;\n", {{Rewrite::Kind::AddSemicolon, then}});
  ASSERT_TRUE(problem);
  EXPECT_NE(problem->find("does not end a statement"), std::string::npos) << *problem;

  const std::string with = "IF a THEN x := 1; END_IF;\n";
  const uint32_t semicolon = static_cast<uint32_t>(with.rfind(';'));
  EXPECT_EQ(check(with, "IF a THEN x := 1; END_IF\n", {{Rewrite::Kind::RemoveSemicolon, semicolon}}), std::nullopt);
  // The ';' of an assignment is no END_ ';'.
  const uint32_t assignment_end = static_cast<uint32_t>(with.find(';'));
  EXPECT_TRUE(check(with, "IF a THEN x := 1 END_IF;\n", {{Rewrite::Kind::RemoveSemicolon, assignment_end}}));
}

TEST(TokenCheck, ValidatesElseIfMerges) {
  const std::string input = "IF a THEN x := 1; ELSE IF b THEN x := 2; END_IF; END_IF\n";
  const uint32_t at = static_cast<uint32_t>(input.find("ELSE"));
  EXPECT_EQ(check(input, "IF a THEN x := 1; ELSIF b THEN x := 2; END_IF\n", {{Rewrite::Kind::MergeElseIf, at}}),
            std::nullopt);
  // A second statement in the ELSE branch: merging would change the program.
  const std::string two = "IF a THEN x := 1; ELSE IF b THEN x := 2; END_IF; y := 3; END_IF\n";
  const auto problem = check(two, "IF a THEN x := 1; ELSIF b THEN x := 2; y := 3; END_IF\n",
                             {{Rewrite::Kind::MergeElseIf, static_cast<uint32_t>(two.find("ELSE"))}});
  ASSERT_TRUE(problem);
  EXPECT_NE(problem->find("not safe"), std::string::npos) << *problem;
}

TEST(FormatText, RefusesAFileThatEndsInAnOpenComment) {
  const FormatResult result = format_text("x := 1;\n(* never closed\n\n", project::FormatSettings{});
  EXPECT_EQ(result.status, Status::SyntaxErrors);
  EXPECT_EQ(result.message, "line 2: comment opened here is never closed");
}

TEST(FormatText, FlatCommentsKeepTheCommentBytes) {
  // Read flat, "(* a (* b *)" is one comment followed by code.
  FormatRequest flat;
  flat.flat_comments = true;
  const FormatResult result = format_text("(* a (* b *)\nx:=1;\n", project::FormatSettings{}, flat);
  ASSERT_EQ(result.status, Status::Formatted) << result.message;
  EXPECT_EQ(result.text, "(* a (* b *)\nx := 1;\n");
}

}  // namespace
}  // namespace rung::format
