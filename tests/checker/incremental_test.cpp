// Workspace::update: after any edit, the diagnostics must be exactly those of a workspace loaded
// fresh from the same texts — whether the edit took the incremental path (body only) or the full
// link. Run under ASan, these tests also catch views left pointing into a replaced text.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include "checker/check.hpp"

namespace rung::check {
namespace {

using Files = std::vector<std::pair<std::string, std::string>>;

// file:line:col code message, for every project file, in order.
std::vector<std::string> render(const Workspace& workspace) {
  std::vector<std::string> lines;
  for (const auto& file : workspace.check_all(1)) {
    const Document& document = *workspace.model().source(file.source).document;
    for (const auto& d : file.diagnostics) {
      const FilePosition at = document.position_of_file_offset(d.range.begin);
      std::string line =
          file.path + ":" + std::to_string(at.line) + ":" + std::to_string(at.column) + " " + d.code + " " + d.message;
      for (const auto& label : d.labels) {
        const FilePosition label_at = document.position_of_file_offset(label.range.begin);
        line +=
            " [" + std::to_string(label_at.line) + ":" + std::to_string(label_at.column) + " " + label.message + "]";
      }
      lines.push_back(line);
    }
  }
  return lines;
}

const Files kProject = {
    {"Types.st",
     "TYPE E_Mode : (Off, Manual, Auto); END_TYPE\n"
     "TYPE ST_Axis : STRUCT pos : REAL; speed : REAL; mode : E_Mode; END_STRUCT END_TYPE\n"
     "FUNCTION Clamp : REAL\nVAR_INPUT v, lo, hi : REAL; END_VAR\n"
     "Clamp := MIN(MAX(v, lo), hi);\nEND_FUNCTION\n"},
    {"GVL.st", "VAR_GLOBAL\n  gAxis : ST_Axis;\n  gCount AT %MW10 : INT;\nEND_VAR\n"},
    {"FB_Axis.st",
     "FUNCTION_BLOCK FB_Axis\nVAR_INPUT target : REAL; END_VAR\nVAR_OUTPUT done : BOOL; END_VAR\n"
     "VAR t : TON; END_VAR\n"
     "gAxis.pos := Clamp(target, 0.0, 100.0);\nt(IN := gAxis.mode = E_Mode.Auto, PT := T#1s);\ndone := t.Q;\n"
     "END_FUNCTION_BLOCK\n"},
    {"Main.st",
     "PROGRAM Main\nVAR axis : FB_Axis; mode : E_Mode := E_Mode.Manual; END_VAR\n"
     "axis(target := 12.5);\nIF axis.done THEN gCount := gCount + 1; mode := Auto; END_IF\nEND_PROGRAM\n"},
};

// Applies the edit to a copy of the project, through update() and through a fresh load, and
// compares the results.
void expect_same_as_fresh(Files project, const std::string& path, const std::string& text, bool expect_only_this_file) {
  project::ProjectConfig config;
  auto edited = Workspace::from_texts(project, config);
  edited->check_all(1);
  SourceId id = *edited->model().find_source(path);
  const std::vector<SourceId> changed = edited->update(id, text);
  if (expect_only_this_file) {
    EXPECT_EQ(changed, std::vector<SourceId>{id});
  }
  for (auto& [name, content] : project) {
    if (name == path) content = text;
  }
  auto fresh = Workspace::from_texts(project, config);
  EXPECT_EQ(render(*edited), render(*fresh)) << "after editing " << path;
}

TEST(IncrementalCheck, BodyEditThatAddsAnErrorAndMovesLines) {
  std::string text = kProject[2].second;
  text.replace(text.find("gAxis.pos :="), 0, "\n\n(* two lines more *)\nbogus := 1;\n");
  expect_same_as_fresh(kProject, "FB_Axis.st", text, true);
}

TEST(IncrementalCheck, BodyEditInTheFileThatDeclaresTypesOthersUse) {
  std::string text = kProject[0].second;
  text.replace(text.find("Clamp := MIN"), 0, "(* a comment that shifts the body *)\n");
  text.replace(text.find("hi);"), 4, "hi) + 'x';");  // a type error in the body
  expect_same_as_fresh(kProject, "Types.st", text, true);
}

TEST(IncrementalCheck, SeveralBodyEditsInARow) {
  project::ProjectConfig config;
  auto edited = Workspace::from_texts(kProject, config);
  Files project = kProject;
  const SourceId id = *edited->model().find_source("Main.st");
  for (int round = 0; round < 5; ++round) {
    // More lines each round; a type error in every other round.
    std::string text = kProject[3].second;
    for (int i = 0; i <= round; ++i) text.replace(text.find("axis(target"), 0, "mode := Off;\n");
    if (round % 2 == 1) text.replace(text.find("gCount + 1"), 10, "gCount + 'a'");
    project[3].second = text;
    EXPECT_EQ(edited->update(id, text), std::vector<SourceId>{id});
    auto fresh = Workspace::from_texts(project, config);
    EXPECT_EQ(render(*edited), render(*fresh)) << "round " << round;
  }
}

// The files named in `ids`, by path.
std::vector<std::string> paths_of(const Workspace& workspace, const std::vector<SourceId>& ids) {
  std::vector<std::string> paths;
  for (const SourceId id : ids) paths.push_back(workspace.model().source(id).document->path());
  std::sort(paths.begin(), paths.end());
  return paths;
}

// The rendered diagnostics of each file.
std::map<std::string, std::vector<std::string>> by_file(const Workspace& workspace) {
  std::map<std::string, std::vector<std::string>> files;
  for (const std::string& line : render(workspace)) files[line.substr(0, line.find(':'))].push_back(line);
  return files;
}

// An edit of declarations: the result must equal a fresh load, every file whose diagnostics
// changed must be among the files update() returned, and those must be exactly `expected`.
void expect_interface_edit(Files project, const std::string& path, const std::string& text,
                           std::vector<std::string> expected) {
  project::ProjectConfig config;
  auto edited = Workspace::from_texts(project, config);
  const auto before = by_file(*edited);
  const SourceId id = *edited->model().find_source(path);
  const std::vector<SourceId> changed = edited->update(id, text);
  ASSERT_FALSE(changed.empty());
  EXPECT_EQ(changed.front(), id) << "the edited file comes first";
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(paths_of(*edited, changed), expected);
  for (auto& [name, content] : project) {
    if (name == path) content = text;
  }
  auto fresh = Workspace::from_texts(project, config);
  EXPECT_EQ(render(*edited), render(*fresh)) << "after editing " << path;
  const auto after = by_file(*edited);
  const std::vector<std::string> returned = paths_of(*edited, changed);
  for (const auto& [file, lines] : after) {
    const auto old_lines = before.find(file);
    if (old_lines != before.end() && old_lines->second == lines) continue;
    EXPECT_TRUE(std::find(returned.begin(), returned.end(), file) != returned.end())
        << file << " has new diagnostics but update() did not return it";
  }
}

TEST(IncrementalCheck, RemovedEnumValueRelinksTheFilesThatNameIt) {
  std::string text = kProject[0].second;
  text.replace(text.find("Auto)"), 4, "Automatic");  // E_Mode.Auto no longer exists
  // Every file that names a declaration of Types.st: all of its symbols are new.
  expect_interface_edit(kProject, "Types.st", text, {"Types.st", "GVL.st", "FB_Axis.st", "Main.st"});
}

TEST(IncrementalCheck, AddedInputRelinksOnlyTheUsersOfTheBlock) {
  std::string text = kProject[2].second;
  text.replace(text.find("target : REAL;"), 0, "accel : REAL; ");
  expect_interface_edit(kProject, "FB_Axis.st", text, {"FB_Axis.st", "Main.st"});
}

TEST(IncrementalCheck, RemovedInputGivesTheCallerAnError) {
  std::string text = kProject[2].second;
  text.replace(text.find("target : REAL;"), 14, "aim : REAL;");
  text.replace(text.find("Clamp(target"), 12, "Clamp(aim");
  expect_interface_edit(kProject, "FB_Axis.st", text, {"FB_Axis.st", "Main.st"});
}

TEST(IncrementalCheck, ChangedFieldTypeReachesUsesThroughTheGlobal) {
  std::string text = kProject[0].second;
  text.replace(text.find("pos : REAL"), 10, "pos : STRING");  // gAxis.pos := Clamp(...) now fails
  expect_interface_edit(kProject, "Types.st", text, {"Types.st", "GVL.st", "FB_Axis.st", "Main.st"});
}

TEST(IncrementalCheck, RenamedBlockLeavesItsUsersWithUnknownType) {
  std::string text = kProject[2].second;
  text.replace(text.find("FB_Axis\n"), 7, "FB_Drive");
  expect_interface_edit(kProject, "FB_Axis.st", text, {"FB_Axis.st", "Main.st"});
}

TEST(IncrementalCheck, InterfaceEditsInARowStayLikeAFreshLoad) {
  project::ProjectConfig config;
  auto edited = Workspace::from_texts(kProject, config);
  Files project = kProject;
  const SourceId id = *edited->model().find_source("Types.st");
  for (int round = 0; round < 40; ++round) {
    std::string text = kProject[0].second;
    const std::string extra = "extra" + std::to_string(round) + " : INT; ";
    text.replace(text.find("mode : E_Mode;"), 0, extra);
    if (round % 3 == 1) text.replace(text.find("Auto)"), 4, "Automatic");
    if (round % 5 == 2) text.replace(text.find("VAR_INPUT v"), 11, "VAR_INPUT value");
    project[0].second = text;
    edited->update(id, text);
    auto fresh = Workspace::from_texts(project, config);
    ASSERT_EQ(render(*edited), render(*fresh)) << "round " << round;
  }
}

TEST(IncrementalCheck, ManyInterfaceEditsEndInAFullLinkThatMatchesAFreshLoad) {
  project::ProjectConfig config;
  auto edited = Workspace::from_texts(kProject, config);
  Files project = kProject;
  const SourceId id = *edited->model().find_source("FB_Axis.st");
  size_t incremental = 0;
  // Past the 256 retired files after which update() links the whole project once.
  for (int round = 0; round < 300; ++round) {
    std::string text = kProject[2].second;
    text.replace(text.find("target : REAL;"), 0, "in" + std::to_string(round) + " : INT; ");
    project[2].second = text;
    if (edited->update(id, text).size() < project.size()) ++incremental;
  }
  EXPECT_GE(incremental, 250u);
  EXPECT_LT(incremental, 300u) << "the retired symbols never made update() link the project";
  auto fresh = Workspace::from_texts(project, config);
  EXPECT_EQ(render(*edited), render(*fresh));
}

TEST(IncrementalCheck, EditThatAddsADeclarationLinksTheWholeProject) {
  std::string text = kProject[1].second;
  text.replace(text.find("END_VAR"), 0, "  gCount2 AT %MW10 : INT;\n");  // overlaps gCount
  expect_same_as_fresh(kProject, "GVL.st", text, false);
}

TEST(IncrementalCheck, DuplicateAcrossFilesKeepsItsPositionAfterABodyEdit) {
  Files project = kProject;
  const std::string first = "FUNCTION First : INT\nFirst := 1;\nEND_FUNCTION\n";
  const std::string again = "FUNCTION Clamp : REAL\nClamp := 0;\nEND_FUNCTION\n";
  project.push_back({"Again.st", first + again});
  // The body of First grows by two lines: the duplicate Clamp moves down.
  expect_same_as_fresh(project, "Again.st",
                       "FUNCTION First : INT\nFirst := 1;\nFirst := 2;\nFirst := 3;\nEND_FUNCTION\n" + again, true);
}

}  // namespace
}  // namespace rung::check
