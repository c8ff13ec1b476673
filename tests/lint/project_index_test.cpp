// The linter's project index (checker/lint/project_index.hpp), which the language server keeps
// across edits: after every kind of edit, a refreshed index must answer like one built anew, and a
// lint run with the kept index must find exactly what a run without it finds.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "checker/check.hpp"
#include "checker/lint/lint.hpp"
#include "checker/lint/lint_rule.hpp"
#include "checker/lint/project_index.hpp"

namespace rung::lint {
namespace {

using Files = std::vector<std::pair<std::string, std::string>>;

std::vector<check::SourceId> mentioning(const ProjectIndex& index, std::string_view name) {
  const std::span<const check::SourceId> files = index.files_mentioning(name);
  return {files.begin(), files.end()};
}

check::SourceId id_of(const check::Workspace& workspace, const std::string& path) {
  return *workspace.model().find_source(path);
}

const Files kPlant = {
    {"motor.st",
     "FUNCTION_BLOCK FB_Motor\n"
     "VAR_INPUT bStart : BOOL; END_VAR\n"
     "VAR nSpeed : INT; nSpare : INT; END_VAR\n"
     "nSpeed := 10;\n"
     "END_FUNCTION_BLOCK\n"},
    {"main.st",
     "PROGRAM Main\n"
     "VAR fbMotor : FB_Motor; NSPEED : INT; bLamp AT %QX0.0 : BOOL; END_VAR\n"
     "fbMotor(bStart := TRUE);\n"
     "bLamp := TRUE;\n"
     "END_PROGRAM\n"},
    {"tools.st",
     "FUNCTION F_Unused : INT\n"
     "F_Unused := nSpare;\n"
     "END_FUNCTION\n"},
    {"config.st",
     "CONFIGURATION Plant\n"
     "RESOURCE Cpu ON PLC\n"
     "TASK Cyclic (INTERVAL := T#10MS, PRIORITY := 1);\n"
     "PROGRAM Run WITH Cyclic : Main;\n"
     "END_RESOURCE\n"
     "END_CONFIGURATION\n"}};

TEST(ProjectIndex, FollowsEditsFileByFile) {
  auto workspace = check::Workspace::from_texts(kPlant, {});
  const check::SourceId motor = id_of(*workspace, "motor.st");
  const check::SourceId main = id_of(*workspace, "main.st");
  ProjectIndex index;
  index.refresh(workspace->model());
  EXPECT_EQ(mentioning(index, "fb_motor"), (std::vector<check::SourceId>{motor, main}));  // any case
  EXPECT_TRUE(index.mentions_output_address(main));
  EXPECT_FALSE(index.mentions_output_address(motor));
  EXPECT_TRUE(index.spelled_otherwise("nSpeed"));  // Main declares NSPEED
  EXPECT_TRUE(index.spelled_otherwise("NSPEED"));
  EXPECT_FALSE(index.spelled_otherwise("bStart"));
  EXPECT_FALSE(index.spelled_otherwise("nUnknown"));

  // Main no longer names the block nor a %Q address, declares nSpeed as FB_Motor does, and names
  // a new word.
  workspace->update(main,
                    "PROGRAM Main\n"
                    "VAR nSpeed : INT; nFresh : INT; END_VAR\n"
                    "nFresh := 1;\n"
                    "END_PROGRAM\n");
  index.refresh(workspace->model());
  EXPECT_EQ(mentioning(index, "FB_Motor"), (std::vector<check::SourceId>{motor}));
  EXPECT_EQ(mentioning(index, "NFRESH"), (std::vector<check::SourceId>{main}));
  EXPECT_FALSE(index.mentions_output_address(main));
  EXPECT_FALSE(index.spelled_otherwise("nSpeed"));
  EXPECT_TRUE(index.spelled_otherwise("NSPEED"));

  // The same answers as an index built from nothing.
  ProjectIndex fresh;
  fresh.refresh(workspace->model());
  for (const char* word : {"FB_Motor", "nSpeed", "nFresh", "fbMotor", "Main", "TRUE", "nSpare"}) {
    EXPECT_EQ(mentioning(index, word), mentioning(fresh, word)) << word;
  }
}

// "CODE@offset message" of every finding of one file.
std::vector<std::string> findings(const check::Workspace& workspace, check::SourceId id, ProjectIndex* kept) {
  AnalysisCache cache(kept);
  std::vector<std::string> out;
  for (const Finding& finding : lint_source(workspace, id, {}, &cache).findings) {
    out.push_back(finding.diagnostic.code + "@" + std::to_string(finding.diagnostic.range.begin) + " " +
                  finding.diagnostic.message);
  }
  return out;
}

void expect_same_as_fresh(const check::Workspace& workspace, ProjectIndex& kept, const std::string& step) {
  for (check::SourceId id = 0; id < workspace.model().source_count(); ++id) {
    if (workspace.model().source(id).library) continue;
    EXPECT_EQ(findings(workspace, id, &kept), findings(workspace, id, nullptr))
        << step << ": " << workspace.model().source(id).document->path();
  }
}

TEST(ProjectIndex, AKeptIndexLintsLikeAFreshOne) {
  auto workspace = check::Workspace::from_texts(kPlant, {});
  ProjectIndex kept;
  expect_same_as_fresh(*workspace, kept, "loaded");
  // Some findings at all, or the comparisons below would prove nothing.
  EXPECT_FALSE(findings(*workspace, id_of(*workspace, "motor.st"), &kept).empty());

  // A body edit (the model keeps its symbols): tools.st stops naming nSpare, so FB_Motor's nSpare
  // is no longer possibly used by an unresolved name.
  workspace->update(id_of(*workspace, "tools.st"), "FUNCTION F_Unused : INT\nF_Unused := 1;\nEND_FUNCTION\n");
  expect_same_as_fresh(*workspace, kept, "body edit");
  const auto unused_spare = [&] {
    const std::vector<std::string> found = findings(*workspace, id_of(*workspace, "motor.st"), &kept);
    return std::count_if(found.begin(), found.end(),
                         [](const std::string& f) { return f.starts_with("L070") && f.find("nSpare") != f.npos; });
  };
  EXPECT_EQ(unused_spare(), 1);

  // A body edit that brings a name in: Main now names nSpare (unresolved there), which may be
  // FB_Motor's, so nSpare is no longer reported unused. An index that missed the new word, or
  // kept Main's old unresolved names, would still report it.
  workspace->update(id_of(*workspace, "main.st"),
                    "PROGRAM Main\n"
                    "VAR fbMotor : FB_Motor; NSPEED : INT; bLamp AT %QX0.0 : BOOL; END_VAR\n"
                    "fbMotor(bStart := TRUE);\n"
                    "bLamp := nSpare > 0;\n"
                    "END_PROGRAM\n");
  expect_same_as_fresh(*workspace, kept, "body edit naming nSpare");
  EXPECT_EQ(unused_spare(), 0);

  // An interface edit (linked again): FB_Motor renamed, so Main's instance no longer resolves.
  workspace->update(id_of(*workspace, "motor.st"),
                    "FUNCTION_BLOCK FB_Drive\n"
                    "VAR_INPUT bStart : BOOL; END_VAR\n"
                    "VAR nSpeed : INT; nSpare : INT; END_VAR\n"
                    "nSpeed := 10;\n"
                    "END_FUNCTION_BLOCK\n");
  expect_same_as_fresh(*workspace, kept, "interface edit");

  // A file added to the project.
  workspace->add_file("late.st", "FUNCTION F_Late : INT\nF_Late := nSpare;\nEND_FUNCTION\n");
  expect_same_as_fresh(*workspace, kept, "file added");

  // Back to the start.
  workspace->update(id_of(*workspace, "motor.st"), kPlant[0].second);
  workspace->update(id_of(*workspace, "tools.st"), kPlant[2].second);
  expect_same_as_fresh(*workspace, kept, "edits undone");
}

}  // namespace
}  // namespace rung::lint
