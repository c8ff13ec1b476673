// Cases of the structure lint rules (L010, L020-L024, L050) that the golden files do not show:
// thresholds and allowed numbers from rung.toml, what the complexity counts, and where the
// one-statement-per-line fix puts the moved statement.
#include <gtest/gtest.h>

#include "checker/check.hpp"
#include "checker/lint/lint.hpp"

namespace rung::lint {
namespace {

struct RuleRun {
  std::vector<std::string> messages;  // "message @text it points at"
  std::string fixed;                  // the text with the rule's fixes applied
};

RuleRun run(std::string_view code, const std::string& text, std::map<std::string, std::string> naming = {},
            std::map<std::string, int64_t> thresholds = {}) {
  project::ProjectConfig config;
  config.lint.rules[std::string(code)] = "on";
  config.lint.naming = std::move(naming);
  config.lint.thresholds = std::move(thresholds);
  auto workspace = check::Workspace::from_texts({{"Main.st", text}}, config);
  RuleRun result;
  std::vector<TextEdit> edits;
  for (const Finding& finding : lint_source(*workspace, 0, config.lint).findings) {
    if (finding.diagnostic.code != code) continue;
    const TextRange range = finding.diagnostic.range;
    result.messages.push_back(finding.diagnostic.message + " @" + text.substr(range.begin, range.end - range.begin));
    if (finding.fix) edits.insert(edits.end(), finding.fix->edits.begin(), finding.fix->edits.end());
  }
  result.fixed = apply_edits(text, edits);
  return result;
}

using Strings = std::vector<std::string>;

TEST(StructureRules, NestingLimitIsAThreshold) {
  const std::string text =
      "PROGRAM PRG_Main\nVAR b : BOOL; i : INT; END_VAR\n"
      "IF b THEN\n  WHILE i < 3 DO\n    i := i + 1;\n  END_WHILE\nEND_IF\n"
      "REPEAT\n  i := i - 1;\nUNTIL i < 0 END_REPEAT\nEND_PROGRAM\n";
  EXPECT_EQ(run("L020", text, {}, {{"max_nesting", 1}}).messages,
            (Strings{"WHILE nested 2 levels deep (limit 1) @WHILE"}));
  EXPECT_TRUE(run("L020", text, {}, {{"max_nesting", 2}}).messages.empty());
}

TEST(StructureRules, ComplexityCountsShortCircuitOperatorsOnly) {
  // 1 + IF + OR_ELSE + AND_THEN = 4; OR, AND and XOR evaluate both operands.
  const std::string text =
      "FUNCTION F_Check : BOOL\nVAR_INPUT a, b, c : BOOL; END_VAR\n"
      "IF a OR b AND c XOR a THEN\n  F_Check := a OR_ELSE b;\nEND_IF\nF_Check := F_Check AND_THEN c;\nEND_FUNCTION\n";
  EXPECT_EQ(run("L021", text, {}, {{"max_cyclomatic_complexity", 3}}).messages,
            (Strings{"function 'F_Check' has a cyclomatic complexity of 4 (limit 3) @F_Check"}));
  EXPECT_TRUE(run("L021", text, {}, {{"max_cyclomatic_complexity", 4}}).messages.empty());
}

TEST(StructureRules, AllowedNumbersComeFromTheSettings) {
  const std::string text =
      "PROGRAM PRG_Main\nVAR i : INT; r : REAL; END_VAR\ni := 10;\ni := 2;\ni := -1;\nr := 10.0;\nEND_PROGRAM\n";
  EXPECT_EQ(run("L050", text, {{"allowed_numbers", "0, 1, 10"}}).messages,
            (Strings{"magic number 2: give it a name @2", "magic number -1: give it a name @-1"}));
}

TEST(StructureRules, AddressesInIlAndSfcBodiesAreCode) {
  const std::string text = R"(PROGRAM PRG_Il
VAR b : BOOL; END_VAR
LD %IX1.0
ST b
END_PROGRAM
)";
  EXPECT_EQ(run("L010", text).messages,
            (Strings{"direct address %IX1.0 in code: give it a name in a declaration @%IX1.0"}));
}

TEST(StructureRules, MovedStatementLinesUpUnderTheFirstOfItsLine) {
  const std::string text =
      "PROGRAM PRG_Main\nVAR a, b, c : INT; END_VAR\n"
      "CASE a OF\n\t1:  b := 1;  c := 2; a := 0;\nEND_CASE\nEND_PROGRAM\n";
  const RuleRun result = run("L024", text);
  EXPECT_EQ(result.messages, (Strings{"'c := 2;' is on the line of the statement before it @c := 2;",
                                      "'a := 0;' is on the line of the statement before it @a := 0;"}));
  EXPECT_EQ(result.fixed,
            "PROGRAM PRG_Main\nVAR a, b, c : INT; END_VAR\n"
            "CASE a OF\n\t1:  b := 1;\n\t    c := 2;\n\t    a := 0;\nEND_CASE\nEND_PROGRAM\n");
}

TEST(StructureRules, ParametersOfAnOverrideAreJudgedAtTheBase) {
  const std::string text = R"(FUNCTION_BLOCK FB_Base
END_FUNCTION_BLOCK
METHOD Configure : BOOL
VAR_INPUT a, b, c : INT; END_VAR
END_METHOD
FUNCTION_BLOCK FB_Derived EXTENDS FB_Base
END_FUNCTION_BLOCK
METHOD Configure : BOOL
VAR_INPUT a, b, c : INT; END_VAR
END_METHOD
)";
  EXPECT_EQ(
      run("L023", text, {}, {{"max_parameters", 2}}).messages,
      (Strings{"method 'FB_Base.Configure' has 3 parameters (limit 2): 3 inputs, 0 outputs, 0 in-outs @Configure"}));
}

}  // namespace
}  // namespace rung::lint
