// The lint baseline: entries survive lines moving and reformatting, count per key, go stale when
// their finding is fixed, and the file is stable JSON.
#include "checker/lint/baseline.hpp"

#include <gtest/gtest.h>

namespace rung::lint {
namespace {

const std::filesystem::path kRoot = "/plant/line1";

// Only L035 (self-assignment) runs.
project::ProjectConfig self_assignment_only() {
  project::ProjectConfig config;
  config.root = kRoot;
  for (const Rule& rule : all_rules()) config.lint.rules[std::string(rule.code)] = "off";
  config.lint.rules["L035"] = "on";
  return config;
}

struct Linted {
  std::unique_ptr<check::Workspace> workspace;
  std::vector<FileFindings> files;
};

Linted lint_texts(const std::vector<std::pair<std::string, std::string>>& files) {
  const project::ProjectConfig config = self_assignment_only();
  Linted out;
  std::vector<std::pair<std::string, std::string>> absolute;
  for (const auto& [name, text] : files) absolute.emplace_back((kRoot / name).string(), text);
  out.workspace = check::Workspace::from_texts(absolute, config);
  out.files = lint_all(*out.workspace, config.lint, 1);
  return out;
}

std::vector<BaselineEntry> entries_of(const Linted& linted) {
  std::vector<BaselineEntry> entries;
  for (const FileFindings& file : linted.files) {
    for (const Finding& finding : file.findings)
      entries.push_back(baseline_entry(*linted.workspace, file, finding, kRoot));
  }
  return entries;
}

size_t findings_left(const Linted& linted) {
  size_t n = 0;
  for (const FileFindings& file : linted.files) n += file.findings.size();
  return n;
}

constexpr const char* kMotor = R"(FUNCTION_BLOCK FB_Motor
VAR
    bRun : BOOL;
    nSpeed : INT;
END_VAR
bRun := bRun;
nSpeed := nSpeed;
METHOD Stop
bRun := bRun;
END_METHOD
END_FUNCTION_BLOCK
)";

TEST(LintBaseline, EntriesNameFileRulePouAndLineButNoLineNumber) {
  const Linted linted = lint_texts({{"src/FB_Motor.st", kMotor}});
  const std::vector<BaselineEntry> entries = entries_of(linted);
  ASSERT_EQ(entries.size(), 3u);
  EXPECT_EQ(entries[0].path, "src/FB_Motor.st");
  EXPECT_EQ(entries[0].code, "L035");
  EXPECT_EQ(entries[0].pou, "FB_Motor");
  EXPECT_EQ(entries[2].pou, "FB_Motor.Stop");
  EXPECT_EQ(entries[0].fingerprint.size(), 16u);
  // The same line text in another POU is another entry; in the same POU the same.
  EXPECT_EQ(entries[0].fingerprint, entries[2].fingerprint);
  EXPECT_NE(entries[0].fingerprint, entries[1].fingerprint);
  EXPECT_NE(entries[0].message.find("bRun"), std::string::npos);
}

TEST(LintBaseline, JsonIsSortedStableAndReadsBack) {
  const Linted linted =
      lint_texts({{"src/FB_Motor.st", kMotor}, {"A.st", "PROGRAM A\nVAR x : INT; END_VAR\nx := x;\nEND_PROGRAM\n"}});
  std::vector<BaselineEntry> entries = entries_of(linted);
  const std::string json = baseline_json(entries);
  std::reverse(entries.begin(), entries.end());
  EXPECT_EQ(baseline_json(entries), json) << "the order of the findings must not matter";
  EXPECT_LT(json.find("\"A.st\""), json.find("\"src/FB_Motor.st\""));
  EXPECT_EQ(json.find("\"line\""), std::string::npos) << "no line numbers in the baseline";
  std::string error;
  const std::optional<std::vector<BaselineEntry>> read = parse_baseline(json, &error);
  ASSERT_TRUE(read) << error;
  EXPECT_EQ(read->size(), 4u);
  EXPECT_EQ(baseline_json(*read), json);
}

TEST(LintBaseline, FindingsThatMovedOrWereReformattedStayBaselined) {
  const std::vector<BaselineEntry> baseline = entries_of(lint_texts({{"src/FB_Motor.st", kMotor}}));
  // Five lines above, other indentation and keyword case, a blank line in between.
  std::string moved = "(* 1 *)\n(* 2 *)\n(* 3 *)\n(* 4 *)\n(* 5 *)\n" + std::string(kMotor);
  moved.replace(moved.find("bRun := bRun;"), 13, "    bRun:=bRun;\n");
  moved.replace(moved.find("METHOD Stop"), 11, "method Stop");
  Linted linted = lint_texts({{"src/FB_Motor.st", moved}});
  ASSERT_EQ(findings_left(linted), 3u);
  const BaselineResult result = apply_baseline(baseline, *linted.workspace, linted.files, kRoot);
  EXPECT_EQ(result.matched, 3u);
  EXPECT_EQ(result.unmatched, 0u);
  EXPECT_EQ(findings_left(linted), 0u);
}

TEST(LintBaseline, NewFindingsAreReportedEvenWhenTheyRepeatABaselinedLine) {
  const std::vector<BaselineEntry> baseline = entries_of(lint_texts({{"src/FB_Motor.st", kMotor}}));
  std::string changed = kMotor;
  // A second `nSpeed := nSpeed;` in FB_Motor: one entry covers one of the two.
  changed.insert(changed.find("METHOD Stop"), "nSpeed := nSpeed;\n");
  Linted linted = lint_texts({{"src/FB_Motor.st", changed}});
  const BaselineResult result = apply_baseline(baseline, *linted.workspace, linted.files, kRoot);
  EXPECT_EQ(result.matched, 3u);
  ASSERT_EQ(findings_left(linted), 1u);
  EXPECT_NE(linted.files[0].findings[0].diagnostic.message.find("nSpeed"), std::string::npos);
}

TEST(LintBaseline, FixedFindingsLeaveStaleEntriesOfLintedFilesOnly) {
  std::vector<BaselineEntry> baseline = entries_of(lint_texts({{"src/FB_Motor.st", kMotor}}));
  baseline.push_back({"src/Other.st", "L035", "Other", "0123456789abcdef", "not linted this time"});
  std::string fixed = kMotor;
  fixed.erase(fixed.find("nSpeed := nSpeed;\n"), 18);
  Linted linted = lint_texts({{"src/FB_Motor.st", fixed}});
  const BaselineResult result = apply_baseline(baseline, *linted.workspace, linted.files, kRoot);
  EXPECT_EQ(result.matched, 2u);
  EXPECT_EQ(result.unmatched, 1u);
  EXPECT_EQ(findings_left(linted), 0u);
}

TEST(LintBaseline, RejectsFilesThatAreNotBaselines) {
  std::string error;
  EXPECT_FALSE(parse_baseline("not json", &error));
  EXPECT_FALSE(parse_baseline("{\"version\": 2, \"findings\": []}", &error));
  EXPECT_NE(error.find("version"), std::string::npos);
  EXPECT_FALSE(parse_baseline("{\"version\": 1}", &error));
  EXPECT_FALSE(parse_baseline("{\"version\": 1, \"findings\": [{\"path\": \"a.st\"}]}", &error));
  EXPECT_TRUE(parse_baseline("{\"version\": 1, \"findings\": []}", &error));
}

}  // namespace
}  // namespace rung::lint
