// Rename (checker/query/rename): which names may be renamed, which new names are refused, and the
// edits of a rename across files, global lists, inheritance and TwinCAT containers.
#include <gtest/gtest.h>

#include "checker/query/rename.hpp"
#include "tests/support/marked_project.hpp"

namespace rung::check {
namespace {

using testing::MarkedProject;

const MarkedProject::Files kLine = {
    {"GVL.st", "VAR_GLOBAL\n  gCount : INT;\n  gLimit : INT := 10;\nEND_VAR\n"},
    {"Conveyor.st",
     "INTERFACE I_Drive\n"
     "METHOD Run : BOOL\n"
     "END_METHOD\n"
     "END_INTERFACE\n"
     "FUNCTION_BLOCK FB_Conveyor IMPLEMENTS I_Drive\n"
     "VAR_INPUT bEnable : BOOL; END_VAR\n"
     "VAR nSteps : INT; END_VAR\n"
     "METHOD Run : BOOL\n"
     "Run := bEnable;\n"
     "END_METHOD\n"
     "nSteps := nSteps + 1; (* counts nSteps *)\n"
     "END_FUNCTION_BLOCK\n"},
    {"Main.st",
     "PROGRAM Main\n"
     "VAR_EXTERNAL gCount : INT; END_VAR\n"
     "VAR\n"
     "  fbBelt : FB_Conveyor;\n"
     "  itf : I_Drive;\n"
     "  tWait : TON;\n"
     "  sText : STRING := 'gCount';\n"
     "END_VAR\n"
     "fbBelt(bEnable := TRUE);\n"
     "itf := fbBelt;\n"
     "IF itf.Run() THEN gCount := GVL.gCount + XSIZEOF(gCount); END_IF\n"
     "tWait(IN := fbBelt.bEnable, PT := T#1s);\n"
     "END_PROGRAM\n"},
};

std::string refusal_at(const MarkedProject& project, const std::string& path, const std::string& marked) {
  return query::rename_target(project.workspace(), project.id(path), project.at(path, marked)).refusal;
}

// "path@offset" of each edit (all of them replace with the same new name).
std::vector<std::string> edits_of(const query::RenamePlan& plan) {
  std::vector<std::string> out;
  for (const query::TextEdit& edit : plan.edits) out.push_back(MarkedProject::where(edit.location));
  return out;
}

query::RenamePlan rename_at(const MarkedProject& project, const std::string& path, const std::string& marked,
                            std::string_view new_name) {
  const query::RenameTarget target =
      query::rename_target(project.workspace(), project.id(path), project.at(path, marked));
  EXPECT_EQ(target.refusal, "") << marked;
  if (!target.symbol) return {};
  return query::plan_rename(project.workspace(), *target.symbol, new_name);
}

TEST(QueryRename, NewNamesMustBeIdentifiersAndNoKeywords) {
  EXPECT_EQ(query::identifier_problem("nCount"), "");
  EXPECT_EQ(query::identifier_problem("_private1"), "");
  EXPECT_EQ(query::identifier_problem("Größe"), "");  // letters of any script, as the grammar reads them
  EXPECT_EQ(query::identifier_problem(""), "the new name is empty");
  EXPECT_EQ(query::identifier_problem("END_IF"), "'END_IF' is a keyword");
  EXPECT_EQ(query::identifier_problem("int"), "'int' is a keyword");
  const std::string not_identifier = "is not an IEC 61131-3 identifier";
  EXPECT_NE(query::identifier_problem("1st").find(not_identifier), std::string::npos);
  EXPECT_NE(query::identifier_problem("a-b").find(not_identifier), std::string::npos);
  EXPECT_NE(query::identifier_problem("a b").find(not_identifier), std::string::npos);
  EXPECT_NE(query::identifier_problem("x(*").find(not_identifier), std::string::npos);
  EXPECT_EQ(query::identifier_problem("a__b"),
            "'a__b' has two '_' in a row, which IEC 61131-3 does not allow in names");
}

TEST(QueryRename, RefusesWhatIsNoDeclaredName) {
  const MarkedProject project(kLine);
  EXPECT_EQ(refusal_at(project, "Main.st", "|IF itf"), "'IF' is a keyword");
  EXPECT_EQ(refusal_at(project, "Main.st", "'gC|ount'"), "this is a literal");
  EXPECT_EQ(refusal_at(project, "Main.st", "T#|1s"), "this is a literal");
  EXPECT_EQ(refusal_at(project, "Conveyor.st", "counts n|Steps"), "this is a comment");
  EXPECT_EQ(refusal_at(project, "Main.st", "|XSIZEOF"), "'XSIZEOF' is built into the compilers");
  EXPECT_EQ(refusal_at(project, "Main.st", "tWait : |TON"), "'TON' is declared in the standard library (TON.st)");
  EXPECT_EQ(refusal_at(project, "Main.st", "tWait(|IN"), "'IN' is declared in the standard library (TON.st)");
  EXPECT_EQ(refusal_at(project, "Main.st", "|GVL.gCount"),
            "the global variable list 'GVL' is named after its file GVL.st: rename the file instead");
  EXPECT_EQ(refusal_at(project, "Main.st", "gCount : |INT"), "'INT' is a keyword");
}

TEST(QueryRename, TargetAndPlaceholder) {
  const MarkedProject project(kLine);
  const query::RenameTarget target =
      query::rename_target(project.workspace(), project.id("Main.st"), project.at("Main.st", "fbBelt.bEna|ble"));
  ASSERT_NE(target.symbol, nullptr);
  EXPECT_EQ(target.placeholder, "bEnable");
  EXPECT_EQ(MarkedProject::where(target.name), project.where("Main.st", "fbBelt.|bEnable"));
  EXPECT_EQ(target.symbol->owner->name, "FB_Conveyor");
}

TEST(QueryRename, GlobalAcrossFilesWithVarExternalAndQualifiedName) {
  const MarkedProject project(kLine);
  const query::RenamePlan plan = rename_at(project, "Main.st", "THEN |gCount", "gTotal");
  EXPECT_EQ(plan.refusal, "");
  EXPECT_EQ(edits_of(plan), (std::vector<std::string>{
                                project.where("GVL.st", "  |gCount"), project.where("Main.st", "VAR_EXTERNAL |gCount"),
                                project.where("Main.st", "THEN |gCount"), project.where("Main.st", "GVL.|gCount"),
                                project.where("Main.st", "XSIZEOF(|gCount")}));
  for (const query::TextEdit& edit : plan.edits) EXPECT_EQ(edit.new_text, "gTotal");
}

TEST(QueryRename, InterfaceMethodRenamesEveryImplementation) {
  const MarkedProject project(kLine);
  const query::RenamePlan plan = rename_at(project, "Main.st", "itf.|Run()", "Start");
  EXPECT_EQ(plan.refusal, "");
  // The interface's method, the block's method and its result inside it, the call.
  EXPECT_EQ(edits_of(plan),
            (std::vector<std::string>{
                project.where("Conveyor.st", "METHOD |Run"), project.where("Conveyor.st", "METHOD |Run", 1),
                project.where("Conveyor.st", "|Run := bEnable"), project.where("Main.st", "itf.|Run()")}));
}

TEST(QueryRename, RefusesNamesThatClash) {
  const MarkedProject project(kLine);
  // A sibling in the same block, an input seen from the method, a global seen from the POU.
  EXPECT_EQ(rename_at(project, "Conveyor.st", "|nSteps :=", "bEnable").refusal,
            "'bEnable' is already visible in FB_Conveyor: variable 'bEnable' declared at Conveyor.st:6");
  EXPECT_EQ(rename_at(project, "Main.st", "|fbBelt(", "gLimit").refusal,
            "'gLimit' is already visible in Main: variable 'gLimit' declared at GVL.st:3");
  // A POU named like a standard block, and a global named like a local that uses it.
  EXPECT_EQ(rename_at(project, "Main.st", "fbBelt : |FB_Conveyor", "ton").refusal,
            "'ton' is already the name of function block 'TON' of the standard library (TON.st:7)");
  EXPECT_EQ(rename_at(project, "GVL.st", "|gCount", "itf").refusal,
            "'itf' is already visible in Main: variable 'itf' declared at Main.st:5");
  // Another spelling of the same name is no clash.
  EXPECT_EQ(rename_at(project, "Main.st", "|fbBelt(", "FBBELT").refusal, "");
  EXPECT_EQ(rename_at(project, "Main.st", "|fbBelt(", "x__y").refusal,
            "'x__y' has two '_' in a row, which IEC 61131-3 does not allow in names");
}

// A TwinCAT POU: the name in the declaration and in the XML element's Name attribute change
// together, and positions are offsets of the .TcPOU file.
TEST(QueryRename, InsideATwinCatContainer) {
  const std::string pou =
      "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n"
      "<TcPlcObject Version=\"1.1.0.1\">\n"
      "  <POU Name=\"FB_Valve\" Id=\"{1}\" SpecialFunc=\"None\">\n"
      "    <Declaration><![CDATA[FUNCTION_BLOCK FB_Valve\n"
      "VAR\n"
      "  bOpen : BOOL;\n"
      "END_VAR\n"
      "]]></Declaration>\n"
      "    <Implementation>\n"
      "      <ST><![CDATA[bOpen := NOT bOpen;]]></ST>\n"
      "    </Implementation>\n"
      "    <Method Name=\"Close\" Id=\"{2}\">\n"
      "      <Declaration><![CDATA[METHOD Close : BOOL\n"
      "]]></Declaration>\n"
      "      <Implementation>\n"
      "        <ST><![CDATA[bOpen := FALSE;]]></ST>\n"
      "      </Implementation>\n"
      "    </Method>\n"
      "    <Action Name=\"Reset\" Id=\"{3}\">\n"
      "      <Implementation>\n"
      "        <ST><![CDATA[bOpen := FALSE;]]></ST>\n"
      "      </Implementation>\n"
      "    </Action>\n"
      "  </POU>\n"
      "</TcPlcObject>\n";
  const MarkedProject project(
      MarkedProject::Files{
          {"FB_Valve.TcPOU", pou},
          {"Main.st", "PROGRAM Main\nVAR v : FB_Valve; END_VAR\nv.Close();\nv.Reset();\nEND_PROGRAM\n"}},
      project::Profile::Twincat);
  EXPECT_EQ(edits_of(rename_at(project, "FB_Valve.TcPOU", "NOT |bOpen", "bIsOpen")),
            (std::vector<std::string>{
                project.where("FB_Valve.TcPOU", "  |bOpen : BOOL"), project.where("FB_Valve.TcPOU", "|bOpen := NOT"),
                project.where("FB_Valve.TcPOU", "NOT |bOpen"), project.where("FB_Valve.TcPOU", "|bOpen := FALSE"),
                project.where("FB_Valve.TcPOU", "|bOpen := FALSE", 1)}));
  EXPECT_EQ(edits_of(rename_at(project, "Main.st", "v : |FB_Valve", "FB_Tap")),
            (std::vector<std::string>{project.where("FB_Valve.TcPOU", "<POU Name=\"|FB_Valve"),
                                      project.where("FB_Valve.TcPOU", "FUNCTION_BLOCK |FB_Valve"),
                                      project.where("Main.st", "v : |FB_Valve")}));
  EXPECT_EQ(edits_of(rename_at(project, "Main.st", "v.|Close", "Shut")),
            (std::vector<std::string>{project.where("FB_Valve.TcPOU", "<Method Name=\"|Close"),
                                      project.where("FB_Valve.TcPOU", "METHOD |Close"),
                                      project.where("Main.st", "v.|Close")}));
  EXPECT_EQ(refusal_at(project, "FB_Valve.TcPOU", "<POU Na|me"), "there is no code at this position");
  // An action's name is only in the XML: TwinCAT's ACTION header is text rung inserts.
  EXPECT_EQ(refusal_at(project, "Main.st", "v.|Reset"),
            "'Reset' is named by the XML of FB_Valve.TcPOU, not by its code: rename it in the vendor's tool");
}

TEST(QueryRename, BrokenCodeStillRenames) {
  const MarkedProject project(MarkedProject::Files{{"P.st",
                                                    "PROGRAM P\nVAR nLevel : INT; END_VAR\n"
                                                    "nLevel := ;\n"
                                                    "IF nLevel > THEN\n"
                                                    "nLevel := nLevel + ;\n"
                                                    "END_IF\n"
                                                    "END_PROGRAM\n"}});
  const query::RenamePlan plan = rename_at(project, "P.st", "IF |nLevel", "nHeight");
  EXPECT_EQ(plan.refusal, "");
  EXPECT_EQ(plan.edits.size(), 5u);
}

}  // namespace
}  // namespace rung::check
