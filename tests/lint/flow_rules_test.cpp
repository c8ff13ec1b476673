// Cases of the flow lint rules that the golden files do not show: the labels that point at the
// first occurrence (L033, L034), which self-assignments get no fix (L035), and how the removal
// edits treat the blanks and the line around what they remove.
#include <gtest/gtest.h>

#include "checker/check.hpp"
#include "checker/lint/flow_support.hpp"
#include "checker/lint/lint.hpp"

namespace rung::lint {
namespace {

// The findings of `code` in `text` (one file, CODESYS profile, the rule switched on).
std::vector<Finding> findings_of(std::string_view code, const std::string& text) {
  project::ProjectConfig config;
  config.lint.rules[std::string(code)] = "on";
  auto workspace = check::Workspace::from_texts({{"Main.st", text}}, config);
  std::vector<Finding> found;
  for (Finding& finding : lint_source(*workspace, 0, config.lint).findings) {
    if (finding.diagnostic.code == code) found.push_back(std::move(finding));
  }
  return found;
}

std::string_view text_at(const std::string& text, TextRange range) {
  return std::string_view(text).substr(range.begin, range.end - range.begin);
}

TEST(FlowRules, DuplicateConditionPointsAtTheFirstTest) {
  const std::string text =
      "PROGRAM Main\nVAR a : BOOL; b : BOOL; n : INT; END_VAR\n"
      "IF a AND b THEN n := 1; ELSIF a THEN n := 2; ELSIF A and B THEN n := 3; END_IF\nEND_PROGRAM\n";
  const std::vector<Finding> found = findings_of("L033", text);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(text_at(text, found[0].diagnostic.range), "A and B");
  ASSERT_EQ(found[0].diagnostic.labels.size(), 1u);
  EXPECT_EQ(text_at(text, found[0].diagnostic.labels[0].range), "a AND b");
  EXPECT_EQ(found[0].diagnostic.labels[0].message, "first tested here");
}

TEST(FlowRules, IdenticalCaseBranchesPointAtTheFirstBranch) {
  const std::string text =
      "PROGRAM Main\nVAR s : INT; x : INT; b : BOOL; END_VAR\n"
      "CASE s OF\n1: x := 1; b := TRUE;\n2: x := 2;\n3, 4: x := 1; b := TRUE;\nELSE x := 0;\nEND_CASE\nEND_PROGRAM\n";
  const std::vector<Finding> found = findings_of("L034", text);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(text_at(text, found[0].diagnostic.range), "3, 4");
  ASSERT_EQ(found[0].diagnostic.labels.size(), 1u);
  EXPECT_EQ(text_at(text, found[0].diagnostic.labels[0].range), "1");
  EXPECT_NE(found[0].diagnostic.help.find("1, 3, 4"), std::string::npos) << found[0].diagnostic.help;
}

TEST(FlowRules, SelfAssignmentOfALocatedVariableHasNoFix) {
  // x := x on an AT %... variable may be there to keep the I/O mapped: reported, not removed.
  const std::string text =
      "PROGRAM Main\nVAR nMapped AT %MW10 : INT; n : INT; END_VAR\nnMapped := nMapped;\nn := n;\nEND_PROGRAM\n";
  const std::vector<Finding> found = findings_of("L035", text);
  ASSERT_EQ(found.size(), 2u);
  EXPECT_FALSE(found[0].fix.has_value());
  ASSERT_TRUE(found[1].fix.has_value());
  EXPECT_EQ(apply_edits(text, found[1].fix->edits),
            "PROGRAM Main\nVAR nMapped AT %MW10 : INT; n : INT; END_VAR\nnMapped := nMapped;\nEND_PROGRAM\n");
}

TEST(FlowRules, RemovalTakesTheLineOrTheBlanksBefore) {
  // `text` without the removal range of `length` bytes at `at`.
  const auto removed = [](std::string text, size_t at, size_t length) {
    const auto begin = static_cast<uint32_t>(at);
    const TextRange range = flow::removal_range(text, {begin, begin + static_cast<uint32_t>(length)});
    return text.erase(range.begin, range.end - range.begin);
  };
  // Alone on its line: the line goes, also with a Windows line break.
  EXPECT_EQ(removed("a;\n    ;\nb;\n", 7, 1), "a;\nb;\n");
  EXPECT_EQ(removed("a;\r\n  x := x;  \r\nb;", 6, 7), "a;\r\nb;");
  // After code: the blanks before it go with it.
  EXPECT_EQ(removed("IF c THEN ; END_IF", 10, 1), "IF c THEN END_IF");
  EXPECT_EQ(removed("x := 1;;\n", 7, 1), "x := 1;\n");
  // At the start of a line before a comment: the comment keeps the indentation.
  EXPECT_EQ(removed("    ;   // note\n", 4, 1), "    // note\n");
}

TEST(FlowRules, TokensCompareWithoutCaseCommentsAndBlanksButStringsExactly) {
  const std::string text =
      "PROGRAM Main\nVAR s : STRING; b : BOOL; END_VAR\n"
      "IF s = 'Ab' THEN b := TRUE; ELSIF S (* same *)= 'Ab' THEN b := FALSE; ELSIF s = 'AB' THEN b := TRUE; "
      "END_IF\nEND_PROGRAM\n";
  const std::vector<Finding> found = findings_of("L033", text);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(text_at(text, found[0].diagnostic.range), "S (* same *)= 'Ab'");
}

}  // namespace
}  // namespace rung::lint
