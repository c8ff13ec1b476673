// Conditional compilation as a pure function: text, defines and answers about declarations in,
// text with the inactive branches blanked and E606 findings out.
#include "checker/project/conditional_compilation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

namespace rung::project {
namespace {

bool contains(const std::string& text, std::string_view part) {
  return text.find(part) != std::string::npos;
}

size_t lines_of(std::string_view text) {
  return static_cast<size_t>(std::count(text.begin(), text.end(), '\n'));
}

ConditionalResult run(std::string_view text, const Defines& defines = {}, const DeclarationOracle& oracle = {}) {
  ConditionalResult result = apply_conditional_compilation(text, defines, oracle);
  // Blanking never moves anything: same length, same line ends.
  EXPECT_EQ(result.text.size(), text.size());
  EXPECT_EQ(lines_of(result.text), lines_of(text));
  return result;
}

std::vector<std::string> messages(const ConditionalResult& result) {
  std::vector<std::string> out;
  for (const Diagnostic& d : result.diagnostics) {
    EXPECT_EQ(d.code, "E606");
    out.push_back(d.message);
  }
  return out;
}

constexpr std::string_view kIfElse = "{IF defined(SIM)}\na := 1;\n{ELSE}\na := 2;\n{END_IF}\nb := 3;\n";

TEST(ConditionalCompilation, ElseBranchWhenTheNameIsNotDefined) {
  ConditionalResult result = run(kIfElse);
  EXPECT_FALSE(contains(result.text, "a := 1;"));
  EXPECT_TRUE(contains(result.text, "a := 2;"));
  EXPECT_TRUE(contains(result.text, "b := 3;"));
  // The pragmas themselves stay, so their structure can still be checked on the rewritten text.
  EXPECT_TRUE(contains(result.text, "{IF defined(SIM)}"));
  EXPECT_TRUE(contains(result.text, "{ELSE}"));
  ASSERT_EQ(result.inactive.size(), 1u);
  EXPECT_EQ(result.inactive[0].begin, kIfElse.find("}\n") + 1);
  EXPECT_TRUE(result.diagnostics.empty());
}

TEST(ConditionalCompilation, FirstBranchWhenRungTomlDefinesTheName) {
  ConditionalResult result = run(kIfElse, {{"SIM", ""}});
  EXPECT_TRUE(contains(result.text, "a := 1;"));
  EXPECT_FALSE(contains(result.text, "a := 2;"));
  EXPECT_TRUE(result.diagnostics.empty());
}

TEST(ConditionalCompilation, NamesAndDirectivesIgnoreCase) {
  ConditionalResult result = run("{if DEFINED (sim)}\nx := 1;\n{else}\nx := 2;\n{end_if}\n", {{"Sim", ""}});
  EXPECT_TRUE(contains(result.text, "x := 1;"));
  EXPECT_FALSE(contains(result.text, "x := 2;"));
}

TEST(ConditionalCompilation, NothingCompiledWithoutATrueBranchOrElse) {
  ConditionalResult result = run("{IF defined(A)}\nx := 1;\n{ELSIF defined(B)}\nx := 2;\n{END_IF}\ny := 0;\n");
  EXPECT_FALSE(contains(result.text, "x := 1;"));
  EXPECT_FALSE(contains(result.text, "x := 2;"));
  EXPECT_TRUE(contains(result.text, "y := 0;"));
}

TEST(ConditionalCompilation, OnlyTheFirstTrueBranchOfAGroup) {
  ConditionalResult result = run(
      "{IF defined(A)}\nx := 1;\n{ELSIF defined(B)}\nx := 2;\n{ELSIF defined(C)}\nx := 3;\n{ELSE}\nx := 4;\n{END_IF}\n",
      {{"B", ""}, {"C", ""}});
  EXPECT_FALSE(contains(result.text, "x := 1;"));
  EXPECT_TRUE(contains(result.text, "x := 2;"));
  EXPECT_FALSE(contains(result.text, "x := 3;"));
  EXPECT_FALSE(contains(result.text, "x := 4;"));
}

TEST(ConditionalCompilation, NestedGroupsInsideAnInactiveBranchStayInactive) {
  const std::string text =
      "{IF defined(OUTER)}\n{IF defined(INNER)}\nx := 1;\n{ELSE}\nx := 2;\n{END_IF}\n{ELSE}\nx := 3;\n{END_IF}\n";
  ConditionalResult none = run(text, {{"INNER", ""}});
  EXPECT_FALSE(contains(none.text, "x := 1;"));  // INNER is defined, but its group is not compiled
  EXPECT_FALSE(contains(none.text, "x := 2;"));
  EXPECT_TRUE(contains(none.text, "x := 3;"));
  ConditionalResult outer = run(text, {{"OUTER", ""}});
  EXPECT_FALSE(contains(outer.text, "x := 1;"));
  EXPECT_TRUE(contains(outer.text, "x := 2;"));
  EXPECT_FALSE(contains(outer.text, "x := 3;"));
  ConditionalResult both = run(text, {{"OUTER", ""}, {"INNER", ""}});
  EXPECT_TRUE(contains(both.text, "x := 1;"));
  EXPECT_FALSE(contains(both.text, "x := 2;"));
}

TEST(ConditionalCompilation, NotAndOrAndParentheses) {
  const std::string text = "{IF defined(A) AND NOT (defined(B) OR defined(C))}\nx := 1;\n{END_IF}\n";
  EXPECT_TRUE(contains(run(text, {{"A", ""}}).text, "x := 1;"));
  EXPECT_FALSE(contains(run(text, {{"A", ""}, {"C", ""}}).text, "x := 1;"));
  EXPECT_FALSE(contains(run(text, {}).text, "x := 1;"));
  // AND binds tighter than OR.
  const std::string precedence = "{IF defined(A) OR defined(B) AND defined(C)}\nx := 1;\n{END_IF}\n";
  EXPECT_TRUE(contains(run(precedence, {{"A", ""}}).text, "x := 1;"));
  EXPECT_FALSE(contains(run(precedence, {{"B", ""}}).text, "x := 1;"));
}

TEST(ConditionalCompilation, ConstantConditions) {
  EXPECT_FALSE(contains(run("{IF 0}\nx := 1;\n{END_IF}\n").text, "x := 1;"));
  EXPECT_TRUE(contains(run("{IF 1}\nx := 1;\n{END_IF}\n").text, "x := 1;"));
  EXPECT_FALSE(contains(run("{IF FALSE}\nx := 1;\n{END_IF}\n").text, "x := 1;"));
}

TEST(ConditionalCompilation, HasValueComparesTheDefinesValue) {
  const std::string text = "{IF hasvalue(test, '1')}\nx := 1;\n{ELSIF hasvalue(test,'2')}\nx := 2;\n{END_IF}\n";
  ConditionalResult two = run(text, {{"test", "2"}});
  EXPECT_FALSE(contains(two.text, "x := 1;"));
  EXPECT_TRUE(contains(two.text, "x := 2;"));
  ConditionalResult undefined = run(text);
  EXPECT_FALSE(contains(undefined.text, "x := 1;"));
  EXPECT_FALSE(contains(undefined.text, "x := 2;"));
}

TEST(ConditionalCompilation, DefineAndUndefineInTheFileCountFromThereOn) {
  ConditionalResult result = run(
      "{IF defined(LOCAL)}\na := 1;\n{END_IF}\n{define LOCAL}\n{IF defined(LOCAL)}\nb := 1;\n{END_IF}\n"
      "{define LEVEL 3}\n{IF hasvalue(LEVEL, '3')}\nc := 1;\n{END_IF}\n{undefine LOCAL}\n{IF defined(LOCAL)}\nd := 1;\n"
      "{END_IF}\n{undefine NEVER_DEFINED}\n");
  EXPECT_FALSE(contains(result.text, "a := 1;"));
  EXPECT_TRUE(contains(result.text, "b := 1;"));
  EXPECT_TRUE(contains(result.text, "c := 1;"));
  EXPECT_FALSE(contains(result.text, "d := 1;"));
  EXPECT_TRUE(result.diagnostics.empty());  // undefining an unknown name is allowed
}

TEST(ConditionalCompilation, DefineInsideAnInactiveBranchDefinesNothing) {
  ConditionalResult result =
      run("{IF defined(NO)}\n{define LATER}\n{END_IF}\n{IF defined(LATER)}\nx := 1;\n{END_IF}\n");
  EXPECT_FALSE(contains(result.text, "x := 1;"));
}

TEST(ConditionalCompilation, DeclarationQuestionsGoToTheOracle) {
  std::vector<DeclarationQuestion> asked;
  std::vector<std::string> names;
  std::vector<std::string> arguments;
  auto oracle = [&](const DeclarationQuestion& question) {
    asked.push_back(question);
    names.emplace_back(question.name);
    arguments.emplace_back(question.argument);
    return question.name == "yes";
  };
  const std::string text =
      "{IF defined(variable: GVL.yes) AND defined(type: yes) AND defined (pou:yes) AND defined(task: yes) AND "
      "defined(resource: yes)}\na := 1;\n{END_IF}\n"
      "{IF hasattribute(pou: yes, 'vision') AND hasattribute(variable: no, 'DoCount')}\nb := 1;\n{END_IF}\n"
      "{IF hastype(variable: yes, ANY_INT)}\nc := 1;\n{END_IF}\n";
  ConditionalResult result = run(text, {}, oracle);
  EXPECT_TRUE(result.diagnostics.empty());
  EXPECT_FALSE(contains(result.text, "a := 1;"));  // GVL.yes is not "yes"
  EXPECT_FALSE(contains(result.text, "b := 1;"));
  EXPECT_TRUE(contains(result.text, "c := 1;"));
  ASSERT_EQ(asked.size(), 8u);
  using Ask = DeclarationQuestion::Ask;
  using Kind = DeclarationQuestion::Kind;
  EXPECT_EQ(asked[0].kind, Kind::Variable);
  EXPECT_EQ(names[0], "GVL.yes");
  EXPECT_EQ(asked[1].kind, Kind::Type);
  EXPECT_EQ(asked[2].kind, Kind::Pou);
  EXPECT_EQ(asked[3].kind, Kind::Task);
  EXPECT_EQ(asked[4].kind, Kind::Resource);
  EXPECT_EQ(asked[5].ask, Ask::HasAttribute);
  EXPECT_EQ(asked[5].kind, Kind::Pou);
  EXPECT_EQ(arguments[5], "vision");
  EXPECT_EQ(asked[6].kind, Kind::Variable);
  EXPECT_EQ(arguments[6], "DoCount");
  EXPECT_EQ(asked[7].ask, Ask::HasType);
  EXPECT_EQ(arguments[7], "ANY_INT");
  // The scope of a question is its {IF}: the offset of the pragma.
  EXPECT_EQ(asked[7].at, text.find("{IF hastype"));
}

TEST(ConditionalCompilation, InactiveGroupsAreNotAskedAbout) {
  int questions = 0;
  auto oracle = [&](const DeclarationQuestion&) {
    ++questions;
    return true;
  };
  run("{IF defined(NO)}\n{IF defined(pou: P)}\nx := 1;\n{END_IF}\n{END_IF}\n", {}, oracle);
  EXPECT_EQ(questions, 0);
}

TEST(ConditionalCompilation, UnbalancedPragmas) {
  EXPECT_EQ(messages(run("{IF defined(A)}\nx := 1;\n")), std::vector<std::string>{"{IF} without {END_IF}"});
  EXPECT_EQ(messages(run("x := 1;\n{END_IF}\n")), std::vector<std::string>{"{END_IF} without {IF}"});
  EXPECT_EQ(messages(run("{ELSE}\n")), std::vector<std::string>{"{ELSE} without {IF}"});
  EXPECT_EQ(messages(run("{ELSIF defined(A)}\n")), std::vector<std::string>{"{ELSIF} without {IF}"});
  EXPECT_EQ(messages(run("{IF defined(A)}\n{ELSE}\n{ELSIF defined(B)}\n{END_IF}\n")),
            std::vector<std::string>{"{ELSIF} after {ELSE}"});
  EXPECT_EQ(messages(run("{IF defined(A)}\n{ELSE}\n{ELSE}\n{END_IF}\n")),
            std::vector<std::string>{"second {ELSE} in one group"});
  // An unclosed inactive group leaves out the rest of the file.
  ConditionalResult unclosed = run("{IF defined(A)}\nx := 1;\ny := 2;\n");
  EXPECT_FALSE(contains(unclosed.text, "y := 2;"));
  // The finding points at the pragma.
  ConditionalResult stray = run("x := 1;\n{END_IF}\n");
  ASSERT_EQ(stray.diagnostics.size(), 1u);
  EXPECT_EQ(stray.diagnostics[0].range.begin, 8u);
  EXPECT_EQ(stray.diagnostics[0].range.end, 16u);
}

TEST(ConditionalCompilation, ConditionsThatDoNotRead) {
  EXPECT_EQ(messages(run("{IF}\n{END_IF}\n")), std::vector<std::string>{"missing condition after {IF}/{ELSIF}"});
  EXPECT_EQ(messages(run("{IF defined(A}\n{END_IF}\n")),
            std::vector<std::string>{"expected ')' before the end of the condition"});
  EXPECT_EQ(messages(run("{IF SIM}\n{END_IF}\n")),
            std::vector<std::string>{"'SIM' is not a condition; a define is tested with defined(SIM)"});
  EXPECT_EQ(messages(run("{IF defined(A) foo}\n{END_IF}\n")),
            std::vector<std::string>{"unexpected 'foo' in condition"});
  EXPECT_EQ(messages(run("{IF defined(thing: A)}\n{END_IF}\n")).size(), 1u);
  EXPECT_EQ(messages(run("{IF hastype(pou: A, INT)}\n{END_IF}\n")).size(), 1u);
  EXPECT_EQ(messages(run("{IF hasvalue(A, 1)}\n{END_IF}\n")),
            std::vector<std::string>{"expected a quoted value, found '1'"});
  const std::vector<std::string> unknown = messages(run("{IF hasconstantvalue(A, 1)}\n{END_IF}\n"));
  ASSERT_EQ(unknown.size(), 1u);
  EXPECT_TRUE(unknown[0].starts_with("unknown condition operator 'hasconstantvalue'"));
  EXPECT_EQ(messages(run("{ELSE defined(A)}\n")).size(), 2u);  // no IF, and a condition on ELSE
  EXPECT_EQ(messages(run("{define}\n")), std::vector<std::string>{"{define} needs a name"});
  // A condition that does not read is false: its branch is left out.
  EXPECT_FALSE(contains(run("{IF defined(A) foo}\nx := 1;\n{END_IF}\n", {{"A", ""}}).text, "x := 1;"));
}

TEST(ConditionalCompilation, MalformedConditionsInInactiveCodeAreStillReported) {
  EXPECT_EQ(messages(run("{IF defined(NO)}\n{IF defined(}\n{END_IF}\n{END_IF}\n")).size(), 1u);
}

TEST(ConditionalCompilation, CheckingFindsTheSameAsEvaluating) {
  const std::string text = "{IF defined(A}\nx := 1;\n{END_IF}\n{END_IF}\n";
  const SyntaxTree tree = SyntaxTree::parse(text);
  const std::vector<ConditionalPragma> pragmas = find_conditional_pragmas(tree);
  ASSERT_EQ(pragmas.size(), 3u);
  EXPECT_EQ(text.substr(pragmas[0].range.begin, pragmas[0].range.end - pragmas[0].range.begin), "{IF defined(A}");
  EXPECT_EQ(check_conditional_pragmas(text, pragmas).size(), run(text).diagnostics.size());
  EXPECT_EQ(check_conditional_pragmas(text, pragmas).size(), 2u);
}

TEST(ConditionalCompilation, PragmasInCommentsAndStringsAreNotDirectives) {
  ConditionalResult result = run("(* {IF defined(A)} *)\ns := '{END_IF}';\nx := 1;\n// {ELSE}\n");
  EXPECT_TRUE(result.diagnostics.empty());
  EXPECT_TRUE(contains(result.text, "x := 1;"));
}

TEST(ConditionalCompilation, QuickTestForConditionalPragmas) {
  EXPECT_TRUE(may_have_conditional_pragmas("x;\n{ if defined(A)}"));
  EXPECT_TRUE(may_have_conditional_pragmas("{Define X}"));
  EXPECT_FALSE(may_have_conditional_pragmas("{attribute 'hide'} {warning 'x'} {IFFY}"));
  ConditionalResult none = run("{attribute 'hide'}\nx := 1;\n");
  EXPECT_TRUE(none.inactive.empty());
}

}  // namespace
}  // namespace rung::project
