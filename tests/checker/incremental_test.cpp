// Workspace::update: after any edit, the diagnostics must be exactly those of a workspace loaded
// fresh from the same texts — whether the edit took the incremental path (body only) or the full
// link. Run under ASan, these tests also catch views left pointing into a replaced text.
#include <gtest/gtest.h>

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

TEST(IncrementalCheck, InterfaceEditLinksTheWholeProject) {
  std::string text = kProject[0].second;
  text.replace(text.find("Auto)"), 4, "Automatic");  // E_Mode.Auto no longer exists
  expect_same_as_fresh(kProject, "Types.st", text, false);
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
