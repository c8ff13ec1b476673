// Cases of the usage rules that one golden file cannot show: uses in other files of the project
// (an instance's local read elsewhere, a block used or extended elsewhere), projects without a
// CONFIGURATION or without any PROGRAM, and lint_all sharing one analysis across files.
#include <gtest/gtest.h>

#include "checker/check.hpp"
#include "checker/lint/lint.hpp"
#include "checker/lint/usage_analysis.hpp"

namespace rung::lint {
namespace {

using Files = std::vector<std::pair<std::string, std::string>>;

// "file:CODE:name" for each finding of `code` in the project (the name is the flagged text).
std::vector<std::string> findings_of(std::string_view code, const Files& files) {
  project::ProjectConfig config;
  config.lint.rules[std::string(code)] = "on";
  auto workspace = check::Workspace::from_texts(files, config);
  std::vector<std::string> found;
  for (const FileFindings& file : lint_all(*workspace, config.lint, 1)) {
    const std::string_view text = workspace->model().source(file.source).document->file_text();
    for (const Finding& finding : file.findings) {
      if (finding.diagnostic.code != code) continue;
      const TextRange range = finding.diagnostic.range;
      found.push_back(file.path + ":" + std::string(text.substr(range.begin, range.end - range.begin)));
    }
  }
  return found;
}

const char* const kBlock =
    "FUNCTION_BLOCK FB_Axis\n"
    "VAR_INPUT xEnable : BOOL; nChannel : INT; END_VAR\n"
    "VAR_OUTPUT xReady : BOOL; END_VAR\n"
    "VAR nPosition : DINT; nSpare : DINT; END_VAR\n"
    "xReady := xEnable;\n"
    "END_FUNCTION_BLOCK\n";

TEST(UsageRules, ALocalReadFromAnotherFileIsUsed) {
  const Files files = {{"FB_Axis.st", kBlock},
                       {"Main.st",
                        "PROGRAM Main\nVAR fbAxis : FB_Axis; n : DINT; END_VAR\n"
                        "fbAxis(xEnable := TRUE);\nn := fbAxis.nPosition;\nEND_PROGRAM\n"}};
  EXPECT_EQ(findings_of("L070", files), std::vector<std::string>{"FB_Axis.st:nSpare"});
}

TEST(UsageRules, AMemberOfAnUnknownTypeMayBeAnyLocal) {
  // The object's type comes from a library rung has no stubs for: nSpare may be what it reads.
  const Files files = {{"FB_Axis.st", kBlock},
                       {"Main.st",
                        "PROGRAM Main\nVAR fbAxis : FB_Axis; fbOther : Lib.FB_Unknown; n : DINT; END_VAR\n"
                        "fbAxis(xEnable := TRUE);\nn := fbOther.nSpare + fbAxis.nPosition;\nEND_PROGRAM\n"}};
  EXPECT_TRUE(findings_of("L070", files).empty());
}

TEST(UsageRules, ADerivedBlockInAnotherFileReadsTheInput) {
  const Files files = {{"FB_Axis.st", kBlock},
                       {"FB_Linear.st",
                        "FUNCTION_BLOCK FB_Linear EXTENDS FB_Axis\nVAR n : INT; END_VAR\n"
                        "n := nChannel;\nEND_FUNCTION_BLOCK\n"}};
  EXPECT_TRUE(findings_of("L071", files).empty());
  const Files alone = {{"FB_Axis.st", kBlock}};
  EXPECT_EQ(findings_of("L071", alone), std::vector<std::string>{"FB_Axis.st:nChannel"});
}

TEST(UsageRules, APouUsedInAnotherFileIsUsed) {
  const Files files = {{"FB_Axis.st", kBlock},
                       {"F_Unused.st", "FUNCTION F_Unused : INT\nF_Unused := 1;\nEND_FUNCTION\n"},
                       {"Main.st", "PROGRAM Main\nVAR fbAxis : FB_Axis; END_VAR\nfbAxis();\nEND_PROGRAM\n"}};
  EXPECT_EQ(findings_of("L072", files), std::vector<std::string>{"F_Unused.st:F_Unused"});
}

TEST(UsageRules, ProgramsAreReportedOnlyWhenAConfigurationSaysWhatRuns) {
  // Without a CONFIGURATION the tasks live in the vendor's project file, which rung does not read.
  const Files without = {{"Main.st", "PROGRAM Main\nVAR n : INT; END_VAR\nn := 1;\nEND_PROGRAM\n"},
                         {"Spare.st", "PROGRAM Spare\nVAR n : INT; END_VAR\nn := 1;\nEND_PROGRAM\n"}};
  EXPECT_TRUE(findings_of("L072", without).empty());
  Files with = without;
  with.push_back({"Config.st",
                  "CONFIGURATION C\nRESOURCE R ON PLC\nTASK T(INTERVAL := T#10MS, PRIORITY := 1);\n"
                  "PROGRAM Inst WITH T : Main;\nEND_RESOURCE\nEND_CONFIGURATION\n"});
  EXPECT_EQ(findings_of("L072", with), std::vector<std::string>{"Spare.st:Spare"});
}

TEST(UsageRules, ALibraryProjectHasNoUnusedPousOrTypes) {
  // No PROGRAM at all: the POUs and types are there for the projects that use the library.
  const Files files = {{"FB_Axis.st", kBlock}, {"Types.st", "TYPE E_Mode : (A, B); END_TYPE\n"}};
  EXPECT_TRUE(findings_of("L072", files).empty());
  EXPECT_TRUE(findings_of("L073", files).empty());
}

TEST(UsageRules, CodeThatOtherDefinesCompileCounts) {
  // DEBUG is not defined: the branch is blanked for checking, but a DEBUG build uses nDebug.
  const Files files = {{"Main.st",
                        "PROGRAM Main\nVAR nDebug : INT; nCount : INT; nUnused : INT; END_VAR\n"
                        "nCount := nCount + 1;\n{IF defined(DEBUG)}\nnDebug := nCount;\n{END_IF}\nEND_PROGRAM\n"}};
  EXPECT_EQ(findings_of("L070", files), std::vector<std::string>{"Main.st:nUnused"});
}

TEST(UsageRules, TheSharedAnalysisGivesWhatEachFileAloneGives) {
  const Files files = {{"FB_Axis.st", kBlock},
                       {"Main.st",
                        "PROGRAM Main\nVAR fbAxis : FB_Axis; nUnused : INT; END_VAR\n"
                        "fbAxis(xEnable := TRUE);\nEND_PROGRAM\n"}};
  project::ProjectConfig config;
  auto workspace = check::Workspace::from_texts(files, config);
  const std::vector<FileFindings> together = lint_all(*workspace, config.lint, 2);
  ASSERT_EQ(together.size(), 2u);
  for (const FileFindings& shared : together) {
    const FileFindings alone = lint_source(*workspace, shared.source, config.lint);
    ASSERT_EQ(shared.findings.size(), alone.findings.size()) << shared.path;
    for (size_t i = 0; i < alone.findings.size(); ++i) {
      EXPECT_EQ(shared.findings[i].diagnostic.code, alone.findings[i].diagnostic.code);
      EXPECT_EQ(shared.findings[i].diagnostic.range.begin, alone.findings[i].diagnostic.range.begin);
    }
  }
}

TEST(UsageAnalysis, RecordsWhatTheCodeDoesWithEachName) {
  const std::string text =
      "FUNCTION F : INT\nVAR_IN_OUT io : INT; END_VAR\nF := io;\nio := 1;\nEND_FUNCTION\n"
      "PROGRAM Main\nVAR a : INT; b : INT; p : POINTER TO INT; fb : TON; arr : ARRAY[0..3] OF INT; END_VAR\n"
      "a := b;\nF(io := a);\np := ADR(b);\nfb(IN := a > 0, Q => arr[1]);\nEND_PROGRAM\n";
  project::ProjectConfig config;
  auto workspace = check::Workspace::from_texts({{"Main.st", text}}, config);
  const check::ProjectModel& model = workspace->model();
  const FileUsage usage = collect_usage(model, 0);
  const check::Symbol* main = model.find_global("Main");
  ASSERT_NE(main, nullptr);
  auto flags_of = [&](std::string_view name) {
    uint16_t flags = 0;
    for (const uint32_t index : usage.uses_of(model.find_member(main, name))) flags |= usage.uses[index].flags;
    return flags;
  };
  EXPECT_EQ(flags_of("a"), kUseWrite | kUseInOut | kUseRead);
  EXPECT_EQ(flags_of("b"), kUseRead | kUseAddress);
  EXPECT_EQ(flags_of("p"), kUseWrite);
  EXPECT_EQ(flags_of("fb"), kUseCall);
  EXPECT_EQ(flags_of("arr"), kUseWrite | kUseOutputTarget | kUsePart);
}

}  // namespace
}  // namespace rung::lint
