// vcs::merge_lines and vcs::merge_file: independent changes merge cleanly; real conflicts leave
// markers around the smallest unit; merged vendor files stay readable with unique ids.
#include "vcs/merge.hpp"

#include <gtest/gtest.h>

#include <pugixml.hpp>
#include <random>
#include <string>
#include <vector>

#include "parser/containers/read_container.hpp"
#include "tests/support/test_paths.hpp"
#include "tests/vcs/git_fixture.hpp"
#include "vcs/object_model.hpp"

namespace rung::vcs {
namespace {

using test::crlf;

// A file of the container reader's tests.
std::string container_file(const char* name) {
  return test::read_file(test::source_dir() / "tests/parser/containers/data" / name);
}

std::string motor() {
  return container_file("FB_Motor.TcPOU");
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

TEST(MergeLines, IndependentChangesApplyAndOverlapsConflict) {
  const std::string base = "a\nb\nc\nd\ne\n";
  MergeResult clean = merge_lines(base, "A\nb\nc\nd\ne\n", "a\nb\nc\nd\nE\n");
  EXPECT_EQ(clean.text, "A\nb\nc\nd\nE\n");
  EXPECT_EQ(clean.conflicts, 0u);
  MergeResult same = merge_lines(base, "a\nX\nc\nd\ne\n", "a\nX\nc\nd\ne\n");
  EXPECT_EQ(same.text, "a\nX\nc\nd\ne\n");
  MergeResult conflict = merge_lines(base, "a\nB1\nc\nd\ne\n", "a\nB2\nc\nd\ne\n");
  EXPECT_EQ(conflict.conflicts, 1u);
  EXPECT_EQ(conflict.text, "a\n<<<<<<< ours\nB1\n=======\nB2\n>>>>>>> theirs\nc\nd\ne\n");
}

const char* kBase =
    "FUNCTION_BLOCK FB_A\nVAR\n    x : INT;\nEND_VAR\nx := 1;\nEND_FUNCTION_BLOCK\n\n"
    "FUNCTION_BLOCK FB_B\nVAR\n    y : INT;\nEND_VAR\ny := 2;\nEND_FUNCTION_BLOCK\n";

TEST(MergeFile, StChangesToDifferentPousAndAdditionsAtTheSamePlaceMerge) {
  const std::string ours =
      replaced(kBase, "x := 1;", "x := 10;") + "\nFUNCTION F_Ours : INT\nF_Ours := 1;\nEND_FUNCTION\n";
  const std::string theirs =
      replaced(kBase, "y := 2;", "y := 20;") + "\nFUNCTION F_Theirs : INT\nF_Theirs := 2;\nEND_FUNCTION\n";
  const MergeResult r = merge_file("x.st", kBase, ours, theirs);
  EXPECT_EQ(r.conflicts, 0u);
  EXPECT_EQ(r.text,
            "FUNCTION_BLOCK FB_A\nVAR\n    x : INT;\nEND_VAR\nx := 10;\nEND_FUNCTION_BLOCK\n\n"
            "FUNCTION_BLOCK FB_B\nVAR\n    y : INT;\nEND_VAR\ny := 20;\nEND_FUNCTION_BLOCK\n"
            "\nFUNCTION F_Ours : INT\nF_Ours := 1;\nEND_FUNCTION\n"
            "\nFUNCTION F_Theirs : INT\nF_Theirs := 2;\nEND_FUNCTION\n");
}

TEST(MergeFile, StConflictMarksOnlyTheConflictingLines) {
  const std::string ours = replaced(replaced(kBase, "x := 1;", "x := 10;"), "y : INT;", "y : DINT;");
  const std::string theirs = replaced(kBase, "x := 1;", "x := 11;");
  const MergeResult r = merge_file("x.st", kBase, ours, theirs);
  EXPECT_EQ(r.conflicts, 1u);
  EXPECT_EQ(
      r.text,
      "FUNCTION_BLOCK FB_A\nVAR\n    x : INT;\nEND_VAR\n<<<<<<< ours\nx := 10;\n=======\nx := 11;\n>>>>>>> theirs\n"
      "END_FUNCTION_BLOCK\n\nFUNCTION_BLOCK FB_B\nVAR\n    y : DINT;\nEND_VAR\ny := 2;\nEND_FUNCTION_BLOCK\n");
}

TEST(MergeFile, StDeletedHereChangedThereIsAConflict) {
  const std::string ours = kBase;
  const std::string ours_without_b = std::string(kBase).substr(0, std::string(kBase).find("\nFUNCTION_BLOCK FB_B"));
  const std::string theirs = replaced(kBase, "y := 2;", "y := 3;");
  const MergeResult r = merge_file("x.st", kBase, ours_without_b + "\n", theirs);
  EXPECT_EQ(r.conflicts, 1u);
  EXPECT_NE(r.text.find("<<<<<<< ours\n=======\n\nFUNCTION_BLOCK FB_B"), std::string::npos) << r.text;
  ASSERT_EQ(r.notes.size(), 1u);
  EXPECT_EQ(r.notes[0], "FB_B: deleted on our side, changed on theirs");
}

// The objects a TwinCAT file holds, with their declarations and bodies, as rung reads them.
std::string objects_of(const std::string& path, const std::string& text) {
  const FileObjects file = read_objects(path, text);
  EXPECT_TRUE(file.errors.empty()) << file.errors.front();
  std::string out;
  for (const Object& o : file.objects) out += o.content_key() + "\n";
  return out;
}

TEST(MergeFile, TwinCatIndependentChangesMergeAndReadBack) {
  const std::string base = motor();
  // Ours: a method body changed, LineIds moved.
  const std::string ours = replaced(replaced(base, "fSpeed := fTarget;", "fSpeed := fTarget * 2.0;"),
                                    "<LineId Id=\"2\" Count=\"1\" />", "<LineId Id=\"4\" Count=\"3\" />");
  // Theirs: a variable added to the declaration and a new method before the property.
  const std::string method = crlf(
      "    <Method Name=\"M_Stop\" Id=\"{8c1e1f7a-3b4c-4d5e-9f60-1a2b3c4d5e99}\">\n"
      "      <Declaration><![CDATA[METHOD M_Stop : BOOL\n]]></Declaration>\n"
      "      <Implementation>\n        <ST><![CDATA[fSpeed := 0;]]></ST>\n      </Implementation>\n"
      "    </Method>\n");
  const std::string theirs =
      replaced(replaced(base, crlf("    fSpeed : LREAL;\n"), crlf("    fSpeed : LREAL;\n    nErrors : UINT;\n")),
               "    <Property Name=\"P_Speed\"", method + "    <Property Name=\"P_Speed\"");
  const MergeResult r = merge_file("FB_Motor.TcPOU", base, ours, theirs);
  EXPECT_EQ(r.conflicts, 0u);
  EXPECT_TRUE(r.error.empty()) << r.error;
  // Byte-exact: their two changes applied to our file.
  const std::string expected =
      replaced(replaced(ours, crlf("    fSpeed : LREAL;\n"), crlf("    fSpeed : LREAL;\n    nErrors : UINT;\n")),
               "    <Property Name=\"P_Speed\"", method + "    <Property Name=\"P_Speed\"");
  EXPECT_EQ(r.text, expected);
  EXPECT_EQ(objects_of("FB_Motor.TcPOU", r.text), objects_of("FB_Motor.TcPOU", expected));
}

TEST(MergeFile, TwinCatConflictInsideOneBodyKeepsTheFileWellFormed) {
  const std::string base = motor();
  const std::string ours = replaced(base, "nState := 0;", "nState := 10;");
  const std::string theirs = replaced(base, "nState := 0;", "nState := 20;");
  const MergeResult r = merge_file("FB_Motor.TcPOU", base, ours, theirs);
  EXPECT_EQ(r.conflicts, 1u);
  EXPECT_NE(
      r.text.find(crlf(
          "<ST><![CDATA[<<<<<<< ours\nnState := 10;\n=======\nnState := 20;\n>>>>>>> theirs\nfSpeed := 0;]]></ST>")),
      std::string::npos)
      << r.text;
  pugi::xml_document doc;
  EXPECT_TRUE(doc.load_string(r.text.c_str()));
}

TEST(MergeFile, TwinCatIdsStayUnique) {
  const std::string base = motor();
  // Both sides paste a copy of the same method (same GUID) under different names.
  const auto with_method = [&](const std::string& name) {
    return replaced(base, "    <Property Name=\"P_Speed\"",
                    "    <Method Name=\"" + name +
                        "\" Id=\"{aaaaaaaa-3b4c-4d5e-9f60-1a2b3c4d5e99}\">\n"
                        "      <Declaration><![CDATA[METHOD " +
                        name +
                        "\n]]></Declaration>\n    </Method>\n"
                        "    <Property Name=\"P_Speed\"");
  };
  const MergeResult r = merge_file("FB_Motor.TcPOU", base, with_method("M_One"), with_method("M_Two"));
  EXPECT_EQ(r.conflicts, 0u);
  pugi::xml_document doc;
  ASSERT_TRUE(doc.load_string(r.text.c_str()));
  std::vector<std::string> ids;
  for (const pugi::xpath_node n : doc.select_nodes("//*[@Id and starts-with(@Id, '{')]"))
    ids.emplace_back(n.node().attribute("Id").value());
  std::vector<std::string> sorted = ids;
  std::sort(sorted.begin(), sorted.end());
  EXPECT_EQ(std::adjacent_find(sorted.begin(), sorted.end()), sorted.end());
  EXPECT_NE(r.text.find("M_One"), std::string::npos);
  EXPECT_NE(r.text.find("M_Two"), std::string::npos);
}

TEST(MergeFile, MalformedXmlIsAnErrorAndKeepsOurs) {
  const MergeResult r = merge_file("FB_Motor.TcPOU", motor(), motor(), "<?xml version=\"1.0\"?><TcPlcObject><POU>");
  EXPECT_NE(r.error.find("malformed XML in the theirs version"), std::string::npos) << r.error;
  EXPECT_EQ(r.text, motor());
}

// Found by the merge property test (merge_fuzz_test.cpp): a VAR_GLOBAL block was known by its
// first variable, so a variable added at the top on both sides made two new blocks, each with a
// copy of the others, and our deletion survived only in our copy.
TEST(MergeFile, StGvlWithNewFirstVariablesOnBothSidesStaysOneBlock) {
  const std::string base = "VAR_GLOBAL\n    bStart : BOOL;\n    bStop : BOOL;\n    bSensor : BOOL;\nEND_VAR\n";
  const std::string ours = "VAR_GLOBAL\n    nOurs : INT;\n    bStart : BOOL;\n    bStop : BOOL;\nEND_VAR\n";
  const std::string theirs =
      "VAR_GLOBAL\n    nTheirs : INT;\n    bStart : BOOL;\n    bStop : BOOL;\n    bSensor : BOOL;\nEND_VAR\n";
  const MergeResult r = merge_file("GVL.st", base, ours, theirs);
  // One block, merged line by line: both additions at the same place are a conflict.
  EXPECT_EQ(r.conflicts, 1u);
  EXPECT_EQ(r.text,
            "VAR_GLOBAL\n<<<<<<< ours\n    nOurs : INT;\n=======\n    nTheirs : INT;\n>>>>>>> theirs\n"
            "    bStart : BOOL;\n    bStop : BOOL;\nEND_VAR\n");
  // Apart, they merge cleanly.
  const std::string theirs_apart =
      "VAR_GLOBAL\n    bStart : BOOL;\n    nTheirs : INT;\n    bStop : BOOL;\n    bSensor : BOOL;\nEND_VAR\n";
  const MergeResult apart = merge_file("GVL.st", base, ours, theirs_apart);
  EXPECT_EQ(apart.conflicts, 0u);
  EXPECT_EQ(apart.text,
            "VAR_GLOBAL\n    nOurs : INT;\n    bStart : BOOL;\n    nTheirs : INT;\n    bStop : BOOL;\nEND_VAR\n");
}

// Found by the merge property test: CODESYS writes one <data name=".../pou"> per POU; with one
// key for both, their change to the second POU was dropped without a word.
TEST(MergeFile, PlcOpenSiblingsSharingANameMergeOneByOne) {
  const std::string base = container_file("Codesys_application.xml");
  const std::string ours = replaced(base, "\tdev.Poll();", "\tdev.Poll();\n\tdev.Flush();");
  const std::string theirs = replaced(base, "GVL_Mqtt.nQos := 2;", "GVL_Mqtt.nQos := 1;");
  const MergeResult r = merge_file("Codesys_application.xml", base, ours, theirs);
  EXPECT_EQ(r.conflicts, 0u);
  EXPECT_TRUE(r.error.empty()) << r.error;
  EXPECT_NE(r.text.find("dev.Flush();"), std::string::npos);
  EXPECT_NE(r.text.find("GVL_Mqtt.nQos := 1;"), std::string::npos);
  EXPECT_EQ(r.text.find("GVL_Mqtt.nQos := 2;"), std::string::npos);
  // And when only they changed anything.
  const MergeResult theirs_only = merge_file("Codesys_application.xml", base, base, theirs);
  EXPECT_NE(theirs_only.text.find("GVL_Mqtt.nQos := 1;"), std::string::npos);
}

// Found by the merge property test: in PLCopen an initial value is an attribute, and ours won
// where both changed one, so their value was dropped silently.
TEST(MergeFile, PlcOpenValueChangedDifferentlyOnBothSidesIsAConflict) {
  const std::string base = container_file("Small_plcopen.xml");
  const std::string ours = replaced(base, "<simpleValue value=\"10\"/>", "<simpleValue value=\"11\"/>");
  const std::string theirs = replaced(base, "<simpleValue value=\"10\"/>", "<simpleValue value=\"12\"/>");
  const MergeResult r = merge_file("Small_plcopen.xml", base, ours, theirs);
  EXPECT_EQ(r.conflicts, 1u);
  EXPECT_EQ(r.text, ours);
  ASSERT_EQ(r.notes.size(), 1u);
  EXPECT_NE(r.notes[0].find("variable|nMax/initialValue#0/simpleValue#0@value: changed differently on both sides: "
                            "kept ours"),
            std::string::npos)
      << r.notes[0];
  // Metadata the tool rewrites on every save stays a silent "ours".
  const std::string ours_saved = replaced(base, "2024-05-03T08:00:00", "2024-06-01T10:00:00");
  const std::string theirs_saved = replaced(base, "2024-05-03T08:00:00", "2024-06-02T11:00:00");
  EXPECT_EQ(merge_file("Small_plcopen.xml", base, ours_saved, theirs_saved).conflicts, 0u);
}

// Found by the merge property test: a <type> holds one type; two different choices were both
// kept (<DINT/><REAL/>), a clean merge that rung then read as DINT.
TEST(MergeFile, PlcOpenTypeChosenDifferentlyOnBothSidesIsAConflict) {
  const std::string base = container_file("Small_plcopen.xml");
  const std::string type = "<variable name=\"nTick\" address=\"%MW4\">\n              <type>\n                <";
  const std::string ours = replaced(base, type + "INT/>", type + "DINT/>");
  const std::string theirs = replaced(base, type + "INT/>", type + "REAL/>");
  const MergeResult r = merge_file("Small_plcopen.xml", base, ours, theirs);
  EXPECT_EQ(r.conflicts, 1u);
  EXPECT_EQ(r.text, ours);
  ASSERT_EQ(r.notes.size(), 1u);
  EXPECT_NE(r.notes[0].find("variable|nTick/type#0/DINT#0: replaced differently on both sides: kept ours"),
            std::string::npos)
      << r.notes[0];
  // The same choice on both sides, or one side's alone, is no conflict.
  EXPECT_EQ(merge_file("Small_plcopen.xml", base, ours, ours).conflicts, 0u);
  const MergeResult theirs_only = merge_file("Small_plcopen.xml", base, base, theirs);
  EXPECT_EQ(theirs_only.conflicts, 0u);
  EXPECT_EQ(theirs_only.text, theirs);
}

// Found by the merge property test: a method written after its block is a unit of its own;
// their deletion of the block and its method against our change of the method marked the method
// but took the block from under it, so choosing ours left an orphan method.
TEST(MergeFile, StPouDeletedThereWhileItsMemberChangedHereIsKeptInTheConflict) {
  const std::string base =
      "FUNCTION_BLOCK FB_A\nVAR\n    x : INT;\nEND_VAR\nx := 1;\nEND_FUNCTION_BLOCK\n"
      "METHOD M_Run : BOOL\nM_Run := TRUE;\nEND_METHOD\n\n"
      "PROGRAM P\nEND_PROGRAM\n";
  const std::string ours = replaced(base, "M_Run := TRUE;", "M_Run := FALSE;");
  const std::string theirs = "PROGRAM P\nEND_PROGRAM\n";
  const MergeResult r = merge_file("x.st", base, ours, theirs);
  EXPECT_EQ(r.conflicts, 2u);
  EXPECT_EQ(r.text,
            "<<<<<<< ours\nFUNCTION_BLOCK FB_A\nVAR\n    x : INT;\nEND_VAR\nx := 1;\nEND_FUNCTION_BLOCK\n=======\n"
            ">>>>>>> theirs\n<<<<<<< ours\nMETHOD M_Run : BOOL\nM_Run := FALSE;\nEND_METHOD\n=======\n"
            ">>>>>>> theirs\nPROGRAM P\nEND_PROGRAM\n");
  EXPECT_EQ(r.notes, (std::vector<std::string>{"FB_A: deleted on their side, a member of it changed on ours",
                                               "FB_A.M_RUN: changed on our side, deleted on theirs"}));
}

// The text of an .EXP object from its "(* @NESTEDCOMMENTS" line to the next one's.
std::string exp_object(const std::string& text, const std::string& header) {
  const size_t at = text.find(header);
  const size_t begin = text.rfind("(* @NESTEDCOMMENTS", at);
  const size_t end = text.find("(* @NESTEDCOMMENTS", at);
  EXPECT_NE(at, std::string::npos) << header;
  return text.substr(begin, end == std::string::npos ? std::string::npos : end - begin);
}

// Found by the merge property test: an .EXP object's markers went with the object before it,
// so deleting that one took them along and left the next object unreadable; deleting both
// neighbours was a conflict. Each object now starts at its own "(* @NESTEDCOMMENTS" line.
TEST(MergeFile, ExpObjectsDeletedOnEachSideGoWithTheirOwnMarkers) {
  const std::string base = container_file("Project.EXP");
  const std::string ours = replaced(base, exp_object(base, "PROGRAM PLC_PRG"), "");
  const std::string theirs = replaced(base, exp_object(base, "gCounter : FB_COUNT"), "");
  const MergeResult r = merge_file("Project.EXP", base, ours, theirs);
  EXPECT_EQ(r.conflicts, 0u);
  EXPECT_EQ(r.text, replaced(ours, exp_object(base, "gCounter : FB_COUNT"), ""));
  const FileObjects read = read_objects("Project.EXP", r.text);
  std::vector<std::string> names;
  for (const Object& o : read.objects) names.push_back(o.name);
  EXPECT_EQ(names, (std::vector<std::string>{"ST_AXIS", "FB_COUNT", "F_LD"}));
}

// Random edits of a real file on both sides, each to a different line of the ST inside: the
// merge never loses a side's change silently and never writes an unreadable file.
TEST(MergeFile, RandomIndependentEditsOfARealFileAreAllKept) {
  const std::string base = motor();
  const std::vector<std::string> lines = {"nState := 1;",       "bRunning := nState = 1;", "M_Start := TRUE;",
                                          "P_Speed := fSpeed;", "fSpeed := P_Speed;",      "nState := 0;",
                                          "fSpeed := 0;"};
  std::mt19937 random(17);
  for (int round = 0; round < 40; ++round) {
    std::vector<size_t> order(lines.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::shuffle(order.begin(), order.end(), random);
    const std::string& mine = lines[order[0]];
    const std::string& other = lines[order[1]];
    const std::string mine_new = mine.substr(0, mine.size() - 1) + " + " + std::to_string(round) + ";";
    const std::string other_new = other.substr(0, other.size() - 1) + " - " + std::to_string(round) + ";";
    const MergeResult r =
        merge_file("FB_Motor.TcPOU", base, replaced(base, mine, mine_new), replaced(base, other, other_new));
    ASSERT_EQ(r.conflicts, 0u) << mine << " / " << other;
    EXPECT_NE(r.text.find(mine_new), std::string::npos);
    EXPECT_NE(r.text.find(other_new), std::string::npos);
    const FileObjects read = read_objects("FB_Motor.TcPOU", r.text);
    EXPECT_TRUE(read.errors.empty());
    ASSERT_EQ(read.objects.size(), 1u);
    EXPECT_EQ(read.objects[0].parts.size(), 7u);
  }
}

}  // namespace
}  // namespace rung::vcs
