// rung.toml [lint]: rule levels, naming patterns, thresholds, the baseline file, and the P002/P003
// diagnostics for what the reader does not accept.
#include <gtest/gtest.h>

#include "checker/project/project_config.hpp"
#include "parser/diagnostic_codes.hpp"

namespace rung::project {
namespace {

LoadedConfig parse(std::string text) {
  return parse_project_config(std::move(text), "/tmp/rung_lint_settings");
}

TEST(LintSettings, ReadsEveryKind) {
  LoadedConfig loaded = parse(R"([lint]
baseline = "ci/lint-baseline.json"
[lint.rules]
L030 = "error"
empty-statement = "off"
todo-comment = "on"
[lint.naming]
BOOL = "b"
global = "g_"
[lint.thresholds]
max_nesting = 4
max_cyclomatic_complexity = 0
)");
  EXPECT_TRUE(loaded.diagnostics.empty()) << loaded.diagnostics.front().message;
  const LintSettings& lint = loaded.config.lint;
  EXPECT_EQ(lint.baseline, "ci/lint-baseline.json");
  EXPECT_EQ(lint.rules, (std::map<std::string, std::string>{
                            {"L030", "error"}, {"empty-statement", "off"}, {"todo-comment", "on"}}));
  EXPECT_EQ(lint.naming, (std::map<std::string, std::string>{{"BOOL", "b"}, {"global", "g_"}}));
  EXPECT_EQ(lint.thresholds, (std::map<std::string, int64_t>{{"max_nesting", 4}, {"max_cyclomatic_complexity", 0}}));
  // Key offsets point at the key in rung.toml.
  ASSERT_TRUE(lint.key_offsets.count("rules.L030"));
  EXPECT_EQ(loaded.text.substr(lint.key_offsets.at("rules.L030"), 4), "L030");
  EXPECT_EQ(loaded.text.substr(lint.key_offsets.at("naming.global"), 6), "global");
  EXPECT_EQ(loaded.text.substr(lint.key_offsets.at("thresholds.max_nesting"), 11), "max_nesting");
  EXPECT_EQ(loaded.text.substr(lint.key_offsets.at("baseline"), 8), "baseline");
}

TEST(LintSettings, RuleKeysAreCaseInsensitiveCodesOrNames) {
  LoadedConfig loaded = parse("[lint.rules]\nl030 = \"off\"\nCASE-WITHOUT-ELSE = \"hint\"\n");
  EXPECT_TRUE(loaded.diagnostics.empty());
  EXPECT_EQ(loaded.config.lint.rules.size(), 2u);
}

TEST(LintSettings, UnknownRuleIsP002WithASuggestion) {
  LoadedConfig loaded = parse("[lint.rules]\ncase-withut-else = \"off\"\nL999 = \"off\"\n");
  ASSERT_EQ(loaded.diagnostics.size(), 2u);
  const Diagnostic& typo = loaded.diagnostics[0];
  EXPECT_EQ(typo.code, codes::kConfigUnknownKey);
  EXPECT_EQ(typo.severity, Severity::Warning);
  EXPECT_NE(typo.message.find("case-withut-else"), std::string::npos) << typo.message;
  EXPECT_NE(typo.help.find("did you mean 'case-without-else'"), std::string::npos) << typo.help;
  EXPECT_EQ(loaded.text.substr(typo.range.begin, 16), "case-withut-else");
  EXPECT_EQ(loaded.diagnostics[1].code, codes::kConfigUnknownKey);
  EXPECT_TRUE(loaded.config.lint.rules.empty());
}

TEST(LintSettings, BadValuesAreP003) {
  LoadedConfig loaded = parse(R"([lint]
baseline = 3
[lint.rules]
L030 = "loud"
L031 = true
[lint.naming]
BOOL = 1
[lint.thresholds]
max_nesting = -1
max_lines = "200"
)");
  ASSERT_EQ(loaded.diagnostics.size(), 6u);
  for (const Diagnostic& d : loaded.diagnostics) {
    EXPECT_EQ(d.code, codes::kConfigBadValue) << d.message;
    EXPECT_EQ(d.severity, Severity::Error);
  }
  EXPECT_NE(loaded.diagnostics[1].message.find("L030"), std::string::npos);
  const LintSettings& lint = loaded.config.lint;
  EXPECT_TRUE(lint.baseline.empty());
  EXPECT_TRUE(lint.rules.empty());
  EXPECT_TRUE(lint.naming.empty());
  EXPECT_TRUE(lint.thresholds.empty());
}

TEST(LintSettings, UnknownLintKeyAndWrongShapes) {
  LoadedConfig loaded = parse("[lint]\nrule = {}\nnaming = \"b\"\n");
  ASSERT_EQ(loaded.diagnostics.size(), 2u);
  EXPECT_EQ(loaded.diagnostics[0].code, codes::kConfigUnknownKey);
  EXPECT_NE(loaded.diagnostics[0].help.find("rules"), std::string::npos);
  EXPECT_EQ(loaded.diagnostics[1].code, codes::kConfigBadValue);
  EXPECT_NE(loaded.diagnostics[1].message.find("[lint.naming]"), std::string::npos);

  LoadedConfig not_table = parse("lint = 1\n");
  ASSERT_EQ(not_table.diagnostics.size(), 1u);
  EXPECT_EQ(not_table.diagnostics[0].code, codes::kConfigBadValue);
}

}  // namespace
}  // namespace rung::project
