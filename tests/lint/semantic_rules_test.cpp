// Cases of the semantic lint rules that the one-file golden examples do not show: L011 and L012
// across files of one project (the finding names the other file), the label that points at the
// first write, L053 being off unless rung.toml switches it on, and the file-by-file runner and
// lint_all agreeing on project-wide findings.
#include <gtest/gtest.h>

#include "checker/check.hpp"
#include "checker/lint/lint.hpp"

namespace rung::lint {
namespace {

using Files = std::vector<std::pair<std::string, std::string>>;

// "file:line: message" of every finding of `code` in the project, file by file (lint_all).
std::vector<std::string> findings_of(std::string_view code, const Files& files, bool switch_on = true) {
  project::ProjectConfig config;
  if (switch_on) config.lint.rules[std::string(code)] = "on";
  auto workspace = check::Workspace::from_texts(files, config);
  std::vector<std::string> found;
  for (const FileFindings& file : lint_all(*workspace, config.lint, 1)) {
    const Document& document = *workspace->model().source(file.source).document;
    for (const Finding& finding : file.findings) {
      if (finding.diagnostic.code != code) continue;
      const FilePosition at = document.position_of_file_offset(finding.diagnostic.range.begin);
      found.push_back(file.path + ":" + std::to_string(at.line) + ": " + finding.diagnostic.message);
    }
  }
  return found;
}

const char* kOutputs =
    "VAR_GLOBAL\n"
    "    xValve AT %QX0.1 : BOOL;\n"
    "END_VAR\n";

TEST(SemanticRules, OutputWrittenInTwoFilesNamesTheFirstFile) {
  const Files files = {
      {"Outputs.st", kOutputs},
      {"Main.st", "PROGRAM Main\nVAR bOpen : BOOL; END_VAR\nxValve := bOpen;\nEND_PROGRAM\n"},
      {"Service.st", "PROGRAM Service\nVAR bTest : BOOL; END_VAR\n\nxValve := bTest;\nEND_PROGRAM\n"},
  };
  const std::vector<std::string> found = findings_of("L011", files);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0], "Service.st:4: physical output 'xValve' (%QX0.1) is also written in Main (at Main.st:3)");
}

TEST(SemanticRules, OutputLabelPointsAtTheFirstWriteInTheSameFile) {
  const std::string text = std::string(kOutputs) +
                           "PROGRAM Main\nVAR b : BOOL; END_VAR\nxValve := FALSE;\nIF b THEN xValve := TRUE; "
                           "END_IF\nEND_PROGRAM\n";
  project::ProjectConfig config;
  auto workspace = check::Workspace::from_texts({{"Main.st", text}}, config);
  std::vector<Finding> found;
  for (Finding& finding : lint_source(*workspace, 0, config.lint).findings) {
    if (finding.diagnostic.code == "L011") found.push_back(std::move(finding));
  }
  ASSERT_EQ(found.size(), 1u);
  const TextRange range = found[0].diagnostic.range;
  EXPECT_EQ(text.substr(range.begin, range.end - range.begin), "xValve");
  ASSERT_EQ(found[0].diagnostic.labels.size(), 1u);
  EXPECT_EQ(found[0].diagnostic.labels[0].message, "first written here");
  EXPECT_EQ(found[0].diagnostic.labels[0].range.begin, text.find("xValve := FALSE"));
}

TEST(SemanticRules, GlobalWrittenByTasksOfAConfigurationInAnotherFile) {
  const Files files = {
      {"Globals.st", "VAR_GLOBAL\n    gnCount : DINT;\nEND_VAR\n"},
      {"Fast.st", "PROGRAM PRG_Fast\ngnCount := gnCount + 1;\nEND_PROGRAM\n"},
      {"Slow.st", "PROGRAM PRG_Slow\ngnCount := 0;\nEND_PROGRAM\n"},
      {"Config.st",
       "CONFIGURATION C\nRESOURCE R ON PLC\nTASK tFast (INTERVAL := T#10MS, PRIORITY := 1);\n"
       "TASK tSlow (INTERVAL := T#100MS, PRIORITY := 2);\nPROGRAM a WITH tFast : PRG_Fast;\n"
       "PROGRAM b WITH tSlow : PRG_Slow;\nEND_RESOURCE\nEND_CONFIGURATION\n"},
  };
  const std::vector<std::string> found = findings_of("L012", files);
  ASSERT_EQ(found.size(), 2u);
  EXPECT_EQ(found[0], "Fast.st:2: 'gnCount' is written by programs of 2 tasks: tFast (PRG_Fast), tSlow (PRG_Slow)");
  EXPECT_EQ(found[1], "Slow.st:2: 'gnCount' is written by programs of 2 tasks: tFast (PRG_Fast), tSlow (PRG_Slow)");
}

TEST(SemanticRules, GlobalWrittenByOneProgramInTwoTasks) {
  // One program type, two instances in two tasks: the same code runs in both.
  const Files files = {
      {"Main.st",
       "VAR_GLOBAL gnCount : DINT; END_VAR\nPROGRAM PRG_Count\ngnCount := gnCount + 1;\nEND_PROGRAM\n"
       "CONFIGURATION C\nRESOURCE R ON PLC\nTASK t1 (INTERVAL := T#10MS, PRIORITY := 1);\n"
       "TASK t2 (INTERVAL := T#20MS, PRIORITY := 2);\nPROGRAM a WITH t1 : PRG_Count;\n"
       "PROGRAM b WITH t2 : PRG_Count;\nEND_RESOURCE\nEND_CONFIGURATION\n"},
  };
  const std::vector<std::string> found = findings_of("L012", files);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0], "Main.st:3: 'gnCount' is written by programs of 2 tasks: t1 (PRG_Count), t2 (PRG_Count)");
}

TEST(SemanticRules, NoConfigurationNoTaskFindings) {
  const Files files = {
      {"Main.st",
       "VAR_GLOBAL gnCount : DINT; END_VAR\nPROGRAM A\ngnCount := 1;\nEND_PROGRAM\n"
       "PROGRAM B\ngnCount := 2;\nEND_PROGRAM\n"},
  };
  EXPECT_TRUE(findings_of("L012", files).empty());
}

TEST(SemanticRules, ImplicitConversionIsOffByDefault) {
  const Files files = {{"Main.st", "PROGRAM Main\nVAR i : INT; d : DINT; END_VAR\nd := i;\nEND_PROGRAM\n"}};
  EXPECT_TRUE(findings_of("L053", files, /*switch_on=*/false).empty());
  const std::vector<std::string> found = findings_of("L053", files);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0], "Main.st:3: implicit conversion from INT to DINT: 'i'");
}

TEST(SemanticRules, NarrowingIsLeftToTheChecker) {
  // DINT to INT is E105 in `rung check`; REAL to INT too. L053 reports only what the checker accepts silently.
  const Files files = {
      {"Main.st", "PROGRAM Main\nVAR i : INT; d : DINT; r : REAL; END_VAR\ni := d;\ni := r;\nEND_PROGRAM\n"}};
  EXPECT_TRUE(findings_of("L053", files).empty());
}

}  // namespace
}  // namespace rung::lint
