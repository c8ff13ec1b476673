// vcs::semantic_diff on files given in memory: what counts as a change and how it is reported.
#include "vcs/semantic_diff.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "tests/support/test_paths.hpp"

namespace rung::vcs {
namespace {

FilePair modified(const std::string& path, const std::string& before, const std::string& after) {
  return FilePair{FileVersion{path, before}, FileVersion{path, after}};
}

std::vector<std::string> summary(const DiffReport& report) {
  std::vector<std::string> out;
  for (const ObjectChange& c : report.changes) {
    std::string s = c.change + " " + c.kind + " " + c.name;
    if (!c.old_name.empty()) s += " was " + c.old_name;
    if (!c.old_path.empty()) s += " from " + c.old_path;
    out.push_back(s);
  }
  return out;
}

const char* kPump =
    "FUNCTION_BLOCK FB_Pump\n"
    "VAR_INPUT\n"
    "    bRun : BOOL;\n"
    "END_VAR\n"
    "VAR\n"
    "    nSpeed : INT := 10;\n"
    "    fOld : REAL;\n"
    "END_VAR\n"
    "IF bRun THEN\n"
    "    nSpeed := nSpeed + 1;\n"
    "END_IF\n"
    "END_FUNCTION_BLOCK\n";

TEST(SemanticDiff, FormattingKeywordCaseAndCommentsAreNoChange) {
  const std::string reformatted =
      "function_block FB_Pump\nvar_input bRun:BOOL; end_var\n"
      "VAR\n nSpeed:INT:=10; (* speed *)\n fOld : REAL;\nEND_VAR\n"
      "if bRun then nSpeed:=nSpeed+1; end_if // step\nEND_FUNCTION_BLOCK\n";
  const DiffReport report = semantic_diff({modified("FB_Pump.st", kPump, reformatted)});
  EXPECT_TRUE(report.changes.empty()) << summary(report).front();
  EXPECT_EQ(report.files, 1u);
  DiffOptions comments;
  comments.comments = true;
  const DiffReport with_comments = semantic_diff({modified("FB_Pump.st", kPump, reformatted)}, comments);
  EXPECT_EQ(summary(with_comments), std::vector<std::string>{"modified FUNCTION_BLOCK FB_Pump"});
}

TEST(SemanticDiff, DeclarationsAddedRemovedRetypedAndBodyHunks) {
  std::string after = kPump;
  after.replace(after.find("nSpeed : INT := 10;"), 19, "nSpeed : DINT := 20;");
  after.replace(after.find("    fOld : REAL;\n"), 17, "");
  after.replace(after.find("    bRun : BOOL;\n"), 17, "    bRun : BOOL;\n    {attribute 'hide'}\n    nMax : INT;\n");
  after.replace(after.find("nSpeed + 1"), 10, "nSpeed + 2");
  const DiffReport report = semantic_diff({modified("FB_Pump.st", kPump, after)});
  ASSERT_EQ(report.changes.size(), 1u);
  const ObjectChange& c = report.changes[0];
  EXPECT_EQ(c.change, "modified");
  ASSERT_EQ(c.declarations.size(), 3u);
  EXPECT_EQ(c.declarations[0].what, std::vector<std::string>{"removed"});
  EXPECT_EQ(c.declarations[0].before, "VAR fOld : REAL");
  EXPECT_EQ(c.declarations[1].what, std::vector<std::string>{"added"});
  EXPECT_EQ(c.declarations[1].after, "{attribute 'hide'} VAR_INPUT nMax : INT");
  EXPECT_EQ(c.declarations[2].what, (std::vector<std::string>{"retyped", "initial value"}));
  EXPECT_EQ(c.declarations[2].before, "VAR nSpeed : INT := 10");
  EXPECT_EQ(c.declarations[2].after, "VAR nSpeed : DINT := 20");
  ASSERT_EQ(c.bodies.size(), 1u);
  EXPECT_EQ(c.bodies[0].diff,
            "@@ -1,3 +1,3 @@\n IF bRun THEN\n-\tnSpeed := nSpeed + 1;\n+\tnSpeed := nSpeed + 2;\n END_IF\n");
  EXPECT_EQ(c.bodies[0].added_lines, 1u);
  EXPECT_EQ(c.bodies[0].removed_lines, 1u);
}

TEST(SemanticDiff, RenamedByContentMovedBetweenFilesAddedRemoved) {
  const std::string f_old = "FUNCTION F_Old : INT\nVAR_INPUT x : INT; END_VAR\nF_Old := x * 2;\nEND_FUNCTION\n";
  const std::string f_new = "FUNCTION F_New : INT\nVAR_INPUT x : INT; END_VAR\nF_New := x * 2;\nEND_FUNCTION\n";
  const std::string prog = "PROGRAM P\nVAR i : INT; END_VAR\ni := i + 1;\nEND_PROGRAM\n";
  const std::string gone = "TYPE E_Gone : (A, B); END_TYPE\n";
  const std::string fresh = "TYPE E_New : (C, D); END_TYPE\n";
  const DiffReport report = semantic_diff({
      modified("src/F.st", f_old, f_new),
      FilePair{FileVersion{"src/a.st", prog}, std::nullopt},
      FilePair{std::nullopt, FileVersion{"src/b/P.st", prog}},
      modified("src/types.st", gone, fresh),
  });
  EXPECT_EQ(summary(report),
            (std::vector<std::string>{"renamed FUNCTION F_New was F_Old", "moved PROGRAM P from src/a.st",
                                      "removed TYPE E_Gone", "added TYPE E_New"}));
}

TEST(SemanticDiff, MembersAddedAndRemovedAndBodiesPerMember) {
  const std::string motor = test::read_file(test::source_dir() / "tests/parser/containers/data/FB_Motor.TcPOU");
  std::string after = motor;
  after.replace(after.find("fSpeed := fTarget;"), 18, "fSpeed := fTarget * 2.0;");
  const size_t action = after.find("    <Action Name=\"A_Reset\"");
  const size_t action_end = after.find("</Action>", action) + 11;  // with its CRLF
  after.erase(action, action_end - action);
  after.replace(after.find("<LineId Id=\"3\" Count=\"2\" />"), 27, "<LineId Id=\"9\" Count=\"1\" />");
  const DiffReport report = semantic_diff({modified("FB_Motor.TcPOU", motor, after)});
  ASSERT_EQ(report.changes.size(), 1u);
  const ObjectChange& c = report.changes[0];
  ASSERT_EQ(c.members.size(), 1u);
  EXPECT_EQ(c.members[0].change + " " + c.members[0].kind + " " + c.members[0].member, "removed ACTION A_Reset");
  ASSERT_EQ(c.bodies.size(), 1u);
  EXPECT_EQ(c.bodies[0].member, "M_Start");
  EXPECT_EQ(c.bodies[0].diff, "@@ -1,2 +1,2 @@\n-fSpeed := fTarget;\n+fSpeed := fTarget * 2.0;\n M_Start := TRUE;\n");
}

TEST(SemanticDiff, UnreadableFilesAreReportedByName) {
  const DiffReport report = semantic_diff(
      {modified("FB_Bad.TcPOU", "<?xml version=\"1.0\"?><TcPlcObject>", std::string("\x00\xff\x00\x01", 4))});
  ASSERT_EQ(report.errors.size(), 2u);
  EXPECT_EQ(report.errors[0].path, "FB_Bad.TcPOU");
  EXPECT_EQ(report.errors[0].message, "binary file; not PLC source");
  EXPECT_EQ(report.errors[1].path, "FB_Bad.TcPOU");
  EXPECT_NE(report.errors[1].message.find("malformed XML"), std::string::npos);
}

}  // namespace
}  // namespace rung::vcs
