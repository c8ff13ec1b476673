// Golden tests of the lint rules: one folder per rule, tests/lint/rules/<CODE>/ (see README.md
// there). The rule runs on bad.st and its findings must equal expected.txt; it must stay silent on
// good.st; its fixes applied to bad.st must give fixed.st. RUNG_UPDATE_GOLDEN=1 rewrites
// expected.txt and fixed.st from what rung reports (then review the diff).
#include <gtest/gtest.h>

#include <filesystem>

#include "checker/check.hpp"
#include "checker/lint/lint.hpp"
#include "parser/diagnostic_codes.hpp"
#include "tests/support/test_paths.hpp"

namespace rung::lint {
namespace {

namespace fs = std::filesystem;

fs::path rules_dir() { return rung::test::source_dir() / "tests" / "lint" / "rules"; }

// The file's text, or nullopt when it does not exist.
std::optional<std::string> read_file(const fs::path& path) {
  if (!fs::is_regular_file(path)) return std::nullopt;
  return test::read_file(path);
}

using test::write_file;
bool updating() { return test::update_golden(); }

// The folder's rung.toml (profile, [lint] settings), with the rule under test switched on.
project::ProjectConfig config_of(const fs::path& folder, const Rule& rule) {
  std::string text = read_file(folder / "rung.toml").value_or("");
  project::LoadedConfig loaded = project::parse_project_config(text, folder);
  for (const Diagnostic& d : loaded.diagnostics) ADD_FAILURE() << folder << "/rung.toml: " << d.message;
  if (!loaded.config.lint.rules.count(std::string(rule.code))) loaded.config.lint.rules[std::string(rule.code)] = "on";
  return loaded.config;
}

struct RuleRun {
  std::string report;  // "line:col: severity[CODE]: message" per finding of the rule
  std::string fixed;   // the file with the rule's fixes applied
  size_t findings = 0;
  size_t fixes = 0;
};

RuleRun run_rule(const Rule& rule, const fs::path& file, const project::ProjectConfig& config) {
  RuleRun run;
  const std::string text = read_file(file).value_or("");
  auto workspace = check::Workspace::from_texts({{file.filename().string(), text}}, config);
  const FileFindings found = lint_source(*workspace, 0, config.lint);
  const Document& document = *workspace->model().source(0).document;
  std::vector<TextEdit> edits;
  for (const Finding& finding : found.findings) {
    if (finding.diagnostic.code != rule.code) continue;
    ++run.findings;
    const FilePosition at = document.position_of_file_offset(finding.diagnostic.range.begin);
    run.report += std::to_string(at.line) + ":" + std::to_string(at.column) + ": " +
                  std::string(severity_name(finding.diagnostic.severity)) + "[" + finding.diagnostic.code +
                  "]: " + finding.diagnostic.message + "\n";
    if (finding.fix) {
      ++run.fixes;
      edits.insert(edits.end(), finding.fix->edits.begin(), finding.fix->edits.end());
    }
  }
  run.fixed = apply_edits(document.file_text(), edits);
  return run;
}

class LintRuleGolden : public ::testing::TestWithParam<std::string> {};

TEST_P(LintRuleGolden, MatchesItsExamples) {
  const Rule* rule = find_rule(GetParam());
  ASSERT_NE(rule, nullptr);
  const fs::path folder = rules_dir() / std::string(rule->code);
  ASSERT_TRUE(fs::is_regular_file(folder / "bad.st")) << "missing " << folder / "bad.st";
  ASSERT_TRUE(fs::is_regular_file(folder / "good.st")) << "missing " << folder / "good.st";
  const project::ProjectConfig config = config_of(folder, *rule);

  const RuleRun bad = run_rule(*rule, folder / "bad.st", config);
  EXPECT_GT(bad.findings, 0u) << rule->code << " finds nothing in bad.st";
  if (updating()) write_file(folder / "expected.txt", bad.report);
  EXPECT_EQ(bad.report, read_file(folder / "expected.txt").value_or("<no expected.txt>"));

  const RuleRun good = run_rule(*rule, folder / "good.st", config);
  EXPECT_EQ(good.report, "") << rule->code << " reports on good.st";

  if (rule->has_fix) {
    EXPECT_GT(bad.fixes, 0u) << rule->code << " offers no fix in bad.st";
    if (updating()) write_file(folder / "fixed.st", bad.fixed);
    EXPECT_EQ(bad.fixed, read_file(folder / "fixed.st").value_or("<no fixed.st>"));
    // A fix settles the finding: linting the fixed file offers no fix of this rule again.
    const fs::path fixed_file = folder / "fixed.st";
    if (fs::is_regular_file(fixed_file)) {
      EXPECT_EQ(run_rule(*rule, fixed_file, config).fixes, 0u);
    }
  } else {
    EXPECT_EQ(bad.fixes, 0u) << rule->code << " offers fixes but is not registered with has_fix";
    EXPECT_FALSE(fs::exists(folder / "fixed.st"));
  }
}

std::vector<std::string> rule_codes() {
  std::vector<std::string> codes;
  for (const Rule& rule : all_rules()) codes.emplace_back(rule.code);
  return codes;
}

INSTANTIATE_TEST_SUITE_P(Rules, LintRuleGolden, ::testing::ValuesIn(rule_codes()),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(LintRuleGolden);

// The rule table and the diagnostic registry describe the same rules.
TEST(LintRegistry, EveryLintCodeHasARuleAndEveryRuleACode) {
  for (const DiagnosticCodeInfo& info : all_diagnostic_codes()) {
    if (info.code.front() != 'L') continue;
    const Rule* rule = find_rule(info.code);
    ASSERT_NE(rule, nullptr) << info.code << " is registered but no lint rule implements it";
    EXPECT_EQ(rule->name, info.title) << info.code;
    EXPECT_NE(rule->check, nullptr) << info.code;
  }
  for (const Rule& rule : all_rules()) {
    const DiagnosticCodeInfo* info = find_diagnostic_code(rule.code);
    ASSERT_NE(info, nullptr) << rule.code << " is missing from parser/diagnostic_codes.cpp";
    EXPECT_TRUE(fs::is_directory(rules_dir() / std::string(rule.code))) << "no golden folder for " << rule.code;
  }
}

}  // namespace
}  // namespace rung::lint
