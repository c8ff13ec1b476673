// The library side of the language server's code actions (checker/query): the END_* a block
// lacks, ELSE for a CASE, "did you mean", declaring an undeclared variable with the type its use
// implies, formal <-> informal calls, missing interface members, and edits of container files.
// Each test applies the proposed edit to the file and compares the result, as an editor would.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "checker/lint/lint.hpp"
#include "checker/query/call_form.hpp"
#include "checker/query/case_else.hpp"
#include "checker/query/declare_variable.hpp"
#include "checker/query/interface_members.hpp"
#include "checker/query/missing_end.hpp"
#include "checker/query/name_suggestions.hpp"
#include "checker/query/source_edits.hpp"
#include "tests/support/marked_project.hpp"

namespace rung::check {
namespace {

using testing::MarkedProject;
using Files = MarkedProject::Files;

// Four spaces, as the tests' files indent.
project::FormatSettings spaces() {
  project::FormatSettings settings;
  settings.use_tabs = false;
  return settings;
}

std::string applied(std::string_view text, const std::vector<lint::TextEdit>& edits) {
  size_t skipped = 0;
  std::string out = lint::apply_edits(text, edits, &skipped);
  EXPECT_EQ(skipped, 0u);
  return out;
}

// ---- missing END_* ----------------------------------------------------------------------------

std::vector<std::string> closed(const std::string& path, const std::string& text,
                                const project::FormatSettings& settings = spaces()) {
  const Document document = Document::from_bytes(path, text);
  std::vector<std::string> out;
  for (const query::ClosingInsertion& insertion : query::missing_end_insertions(document, settings)) {
    out.push_back(applied(document.file_text(), {insertion.edit}));
  }
  return out;
}

TEST(MissingEnd, ClosesAfterTheLastLineIndentedDeeperThanTheOpener) {
  const std::string text =
      "FUNCTION_BLOCK FB_A\n"
      "VAR\n"
      "    x : INT;\n"
      "END_VAR\n"
      "IF x > 0 THEN\n"
      "    x := 1;\n"
      "ELSIF x < 0 THEN\n"
      "    x := 2;\n"
      "\n"
      "x := 3;\n"
      "END_FUNCTION_BLOCK\n";
  EXPECT_EQ(closed("a.st", text), std::vector<std::string>{"FUNCTION_BLOCK FB_A\n"
                                                           "VAR\n"
                                                           "    x : INT;\n"
                                                           "END_VAR\n"
                                                           "IF x > 0 THEN\n"
                                                           "    x := 1;\n"
                                                           "ELSIF x < 0 THEN\n"
                                                           "    x := 2;\n"
                                                           "END_IF\n"
                                                           "\n"
                                                           "x := 3;\n"
                                                           "END_FUNCTION_BLOCK\n"});
}

TEST(MissingEnd, NestedBlockTakesItsOpenersIndentationAndCase) {
  const std::string text =
      "PROGRAM P\n"
      "VAR i, n : INT; END_VAR\n"
      "    for i := 1 to 3 do\n"
      "        n := n + i;\n"
      "END_PROGRAM\n";
  project::FormatSettings settings = spaces();
  settings.keyword_case = project::KeywordCase::Preserve;
  settings.end_semicolon = project::EndSemicolon::Always;
  EXPECT_EQ(closed("a.st", text, settings), std::vector<std::string>{"PROGRAM P\n"
                                                                     "VAR i, n : INT; END_VAR\n"
                                                                     "    for i := 1 to 3 do\n"
                                                                     "        n := n + i;\n"
                                                                     "    end_for;\n"
                                                                     "END_PROGRAM\n"});
}

TEST(MissingEnd, EndOfFileWithoutLineBreak) {
  EXPECT_EQ(closed("a.st", "PROGRAM P\nVAR b : BOOL; END_VAR\nWHILE b DO\n    b := FALSE;"),
            std::vector<std::string>{"PROGRAM P\nVAR b : BOOL; END_VAR\nWHILE b DO\n    b := FALSE;\nEND_WHILE"});
}

TEST(MissingEnd, InsideTheCdataOfATwinCatBody) {
  const std::string pou =
      "<?xml version=\"1.0\" encoding=\"utf-8\"?>\r\n"
      "<TcPlcObject Version=\"1.1.0.1\">\r\n"
      "  <POU Name=\"FB_A\" Id=\"{00000000-0000-0000-0000-000000000001}\">\r\n"
      "    <Declaration><![CDATA[FUNCTION_BLOCK FB_A\r\nVAR\r\n\tb : BOOL;\r\nEND_VAR\r\n]]></Declaration>\r\n"
      "    <Implementation>\r\n"
      "      <ST><![CDATA[IF b THEN\r\n\tb := FALSE;\r\n]]></ST>\r\n"
      "    </Implementation>\r\n"
      "  </POU>\r\n"
      "</TcPlcObject>\r\n";
  const std::vector<std::string> fixed = closed("FB_A.TcPOU", pou);
  ASSERT_EQ(fixed.size(), 1u);
  EXPECT_NE(fixed[0].find("<ST><![CDATA[IF b THEN\r\n\tb := FALSE;\r\nEND_IF\r\n]]></ST>"), std::string::npos) << fixed[0];
}

// ---- CASE ELSE --------------------------------------------------------------------------------

std::optional<std::string> with_else(const std::string& text, const std::string& at) {
  const Document document = Document::from_bytes("a.st", text);
  const SyntaxNode statement = query::case_statement_at(document, static_cast<uint32_t>(text.find(at)));
  const std::optional<lint::TextEdit> edit = query::add_case_else(document, statement, spaces());
  if (!edit) return std::nullopt;
  return applied(text, {*edit});
}

TEST(CaseElse, GoesBeforeEndCaseIndentedLikeTheLabels) {
  const std::string text =
      "PROGRAM P\nVAR n : INT; END_VAR\n"
      "CASE n OF\n"
      "    1:\n"
      "        n := 2;\n"
      "    2: n := 1;\n"
      "END_CASE\n"
      "END_PROGRAM\n";
  EXPECT_EQ(with_else(text, "n := 2"), "PROGRAM P\nVAR n : INT; END_VAR\n"
                                       "CASE n OF\n"
                                       "    1:\n"
                                       "        n := 2;\n"
                                       "    2: n := 1;\n"
                                       "    ELSE\n"
                                       "        (* other values *)\n"
                                       "END_CASE\n"
                                       "END_PROGRAM\n");
}

TEST(CaseElse, OnOneLineAndNotTwice) {
  EXPECT_EQ(with_else("PROGRAM P\nVAR n : INT; END_VAR\nCASE n OF 1: n := 2; END_CASE\nEND_PROGRAM\n", "CASE"),
            "PROGRAM P\nVAR n : INT; END_VAR\nCASE n OF 1: n := 2; ELSE (* other values *) END_CASE\nEND_PROGRAM\n");
  EXPECT_EQ(with_else("PROGRAM P\nVAR n : INT; END_VAR\nCASE n OF 1: n := 2; ELSE n := 0; END_CASE\nEND_PROGRAM\n",
                      "CASE"),
            std::nullopt);
  EXPECT_EQ(with_else("PROGRAM P\nVAR n : INT; END_VAR\nn := 1;\nEND_PROGRAM\n", "n := 1"), std::nullopt);
}

// ---- did you mean -----------------------------------------------------------------------------

const Files kMotor = {
    {"motor.st",
     "FUNCTION_BLOCK FB_Motor\n"
     "VAR_INPUT\n    bStart : BOOL;\nEND_VAR\n"
     "VAR_OUTPUT\n    bRunning : BOOL;\nEND_VAR\n"
     "bRunning := bStart;\n"
     "END_FUNCTION_BLOCK\n"},
    {"main.st",
     "PROGRAM Main\n"
     "VAR\n    fbMotor : FB_Motor;\n    nCounter : INT;\nEND_VAR\n"
     "nCountr := 1;\n"
     "fbMotor(bStrat := TRUE);\n"
     "nCounter := BOOL_TO_INT(fbMotor.bRuning);\n"
     "nCounter := nZzz;\n"
     "END_PROGRAM\n"}};

std::string suggested(const MarkedProject& project, const std::string& marked) {
  const auto suggestion = query::suggest_name(project.workspace(), project.id("main.st"), project.at("main.st", marked));
  if (!suggestion) return "(none)";
  // The whole line after the fix, so that the test shows both the replacement and what it replaced.
  const std::string fixed =
      applied(project.text_of("main.st"), {lint::TextEdit{suggestion->range, suggestion->replacement}});
  const size_t line_begin = fixed.rfind('\n', suggestion->range.begin) + 1;
  return fixed.substr(line_begin, fixed.find('\n', suggestion->range.begin) - line_begin);
}

TEST(NameSuggestions, TheCandidatesTheCheckerNames) {
  const MarkedProject project(kMotor);
  EXPECT_EQ(suggested(project, "nCou|ntr :="), "nCounter := 1;");                               // E001
  EXPECT_EQ(suggested(project, "bSt|rat"), "fbMotor(bStart := TRUE);");                           // E301
  EXPECT_EQ(suggested(project, "bRu|ning"), "nCounter := BOOL_TO_INT(fbMotor.bRunning);");        // E005
  EXPECT_EQ(suggested(project, "nZ|zz"), "(none)");                                    // nothing close
  EXPECT_EQ(suggested(project, "nCoun|ter := BOOL"), "(none)");                        // declared
}

TEST(NameSuggestions, AVariableOfAGlobalList) {
  const MarkedProject project(Files{
      {"GVL_IO.st", "{attribute 'qualified_only'}\nVAR_GLOBAL\n    bStartButton : BOOL;\nEND_VAR\n"},
      {"main.st", "PROGRAM Main\nVAR b : BOOL; END_VAR\nb := GVL_IO.bStartButon;\nb := GVL_IO.bStartButton;\nEND_PROGRAM\n"}});
  EXPECT_EQ(suggested(project, "GVL_IO.bSta|rtButon"), "b := GVL_IO.bStartButton;");
  EXPECT_EQ(suggested(project, "GVL_IO.bSta|rtButton"), "(none)");  // declared
}

// ---- declare a variable -----------------------------------------------------------------------

const Files kUses = {
    {"types.st",
     "TYPE E_State : (Idle, Busy); END_TYPE\n"
     "FUNCTION F_Scale : REAL\nVAR_INPUT\n    rIn : REAL;\n    nGain : DINT;\nEND_VAR\nF_Scale := rIn;\nEND_FUNCTION\n"},
    {"main.st",
     "PROGRAM Main\n"
     "VAR_INPUT\n    bStart : BOOL;\nEND_VAR\n"
     "VAR\n    eState : E_State;\n    aValues : ARRAY[1..10] OF LREAL;\nEND_VAR\n"
     "IF bReady AND bStart THEN eNext := eState; END_IF\n"
     "rScaled := F_Scale(rRaw, nGain := nFactor);\n"
     "FOR i := 1 TO 10 DO aValues[i] := rTotal + 1.5; END_FOR\n"
     "WHILE NOT bStop DO sText := 'x'; END_WHILE\n"
     "nCount := nCount + 1;\n"
     "vUnknown := vOther;\n"
     "END_PROGRAM\n"
     "FUNCTION_BLOCK FB_Axis\n"
     "METHOD M_Move : BOOL\n"
     "M_Move := rTarget > 1.0;\n"
     "END_METHOD\n"
     "END_FUNCTION_BLOCK\n"}};

std::string type_of_use(const MarkedProject& project, const std::string& marked) {
  const auto variable =
      query::undeclared_variable_at(project.workspace(), project.id("main.st"), project.at("main.st", marked));
  return variable ? variable->name + " : " + variable->type + " in " + std::string(variable->pou->name) : "(none)";
}

TEST(DeclareVariable, TheTypeComesFromTheUse) {
  const MarkedProject project(kUses);
  EXPECT_EQ(type_of_use(project, "bRe|ady"), "bReady : BOOL in Main");          // AND with a BOOL
  EXPECT_EQ(type_of_use(project, "eN|ext"), "eNext : E_State in Main");          // assigned an E_State
  EXPECT_EQ(type_of_use(project, "rSc|aled"), "rScaled : REAL in Main");         // a function's result
  EXPECT_EQ(type_of_use(project, "rR|aw"), "rRaw : REAL in Main");               // first input, by position
  EXPECT_EQ(type_of_use(project, "nFac|tor"), "nFactor : DINT in Main");         // named input
  EXPECT_EQ(type_of_use(project, "FOR |i"), "i : INT in Main");                  // FOR counter
  EXPECT_EQ(type_of_use(project, "rTo|tal"), "rTotal : LREAL in Main");          // + 1.5 into an LREAL
  EXPECT_EQ(type_of_use(project, "bS|top"), "bStop : BOOL in Main");             // NOT in a condition
  EXPECT_EQ(type_of_use(project, "sT|ext"), "sText : STRING in Main");           // a string literal
  EXPECT_EQ(type_of_use(project, "nCo|unt := nCount"), "nCount : INT in Main");  // x := x + 1
  EXPECT_EQ(type_of_use(project, "rTa|rget"), "rTarget : REAL in M_Move");       // compared with a REAL
  EXPECT_EQ(type_of_use(project, "vUn|known"), "(none)");                        // nothing tells
  EXPECT_EQ(type_of_use(project, "bSt|art THEN"), "(none)");                     // declared
}

std::string declared(const MarkedProject& project, const std::string& marked, ast::VarSection section) {
  const auto variable =
      query::undeclared_variable_at(project.workspace(), project.id("main.st"), project.at("main.st", marked));
  if (!variable) return "(none)";
  const auto edit = query::declare_variable(project.workspace(), *variable, section, spaces());
  return edit ? applied(project.text_of("main.st"), {*edit}) : "(no edit)";
}

TEST(DeclareVariable, IntoTheLastPlainBlockOfTheSectionOrANewOne) {
  const MarkedProject project(kUses);
  const std::string var = declared(project, "bRe|ady", ast::VarSection::Var);
  EXPECT_NE(var.find("    aValues : ARRAY[1..10] OF LREAL;\n    bReady : BOOL;\nEND_VAR\n"), std::string::npos) << var;
  const std::string output = declared(project, "bRe|ady", ast::VarSection::Output);
  EXPECT_NE(output.find("    bStart : BOOL;\nEND_VAR\nVAR_OUTPUT\n    bReady : BOOL;\nEND_VAR\nVAR\n"), std::string::npos)
      << output;
  const std::string method = declared(project, "rTa|rget", ast::VarSection::Input);
  EXPECT_NE(method.find("METHOD M_Move : BOOL\nVAR_INPUT\n    rTarget : REAL;\nEND_VAR\nM_Move :="), std::string::npos)
      << method;
}

// ---- formal and informal calls ----------------------------------------------------------------

const Files kCalls = {
    {"main.st",
     "FUNCTION F_Add : INT\nVAR_INPUT\n    a : INT;\n    b : INT;\nEND_VAR\nF_Add := a + b;\nEND_FUNCTION\n"
     "FUNCTION_BLOCK FB_Count\nVAR_INPUT\n    bUp : BOOL;\n    nMax : INT;\nEND_VAR\n"
     "VAR_OUTPUT\n    nValue : INT;\nEND_VAR\nEND_FUNCTION_BLOCK\n"
     "PROGRAM Main\nVAR\n    n : INT;\n    fb : FB_Count;\nEND_VAR\n"
     "n := F_Add(1, (* two *) 2);\n"
     "n := F_Add(a := n, b := 3);\n"
     "n := F_Add(b := 3, a := n);\n"
     "fb(TRUE, 10);\n"
     "fb(bUp := TRUE, nValue => n);\n"
     "n := LIMIT(0, n, 10);\n"
     "n := MAX(1, 2, 3);\n"
     "END_PROGRAM\n"}};

std::string rewritten(const MarkedProject& project, const std::string& marked, bool formal) {
  const auto rewrite = formal ? query::to_formal_call(project.workspace(), project.id("main.st"), project.at("main.st", marked))
                              : query::to_informal_call(project.workspace(), project.id("main.st"), project.at("main.st", marked));
  if (!rewrite) return "(none)";
  const std::string text = applied(project.text_of("main.st"), rewrite->edits);
  const size_t line = text.rfind('\n', project.at("main.st", marked)) + 1;
  return text.substr(line, text.find('\n', line) - line);
}

TEST(CallForm, ToFormalNamesEachArgumentByItsPlace) {
  const MarkedProject project(kCalls);
  EXPECT_EQ(rewritten(project, "F_A|dd(1,", true), "n := F_Add(a := 1, (* two *) b := 2);");
  EXPECT_EQ(rewritten(project, "fb(TR|UE", true), "fb(bUp := TRUE, nMax := 10);");
  EXPECT_EQ(rewritten(project, "LIM|IT", true), "n := LIMIT(MN := 0, IN := n, MX := 10);");
  EXPECT_EQ(rewritten(project, "MA|X(1", true), "(none)");       // extensible: IN3 has no name
  EXPECT_EQ(rewritten(project, "F_A|dd(a", true), "(none)");     // already formal
}

TEST(CallForm, ToInformalOnlyForFunctionsInDeclarationOrder) {
  const MarkedProject project(kCalls);
  EXPECT_EQ(rewritten(project, "F_A|dd(a", false), "n := F_Add(n, 3);");
  EXPECT_EQ(rewritten(project, "F_A|dd(b", false), "(none)");      // the order would change the binding
  EXPECT_EQ(rewritten(project, "fb(bU|p", false), "(none)");       // a function block instance, an output
  EXPECT_EQ(rewritten(project, "F_A|dd(1,", false), "(none)");     // already informal
}

// ---- interface members ------------------------------------------------------------------------

TEST(InterfaceMembers, SkeletonsWithTheInterfacesSignatures) {
  const MarkedProject project(Files{
      {"itf.st",
       "INTERFACE I_Base\nMETHOD Reset\nEND_METHOD\nEND_INTERFACE\n"
       "INTERFACE I_Motor EXTENDS I_Base\n"
       "METHOD Start : BOOL\nVAR_INPUT\n    nSpeed : INT;\nEND_VAR\nEND_METHOD\n"
       "PROPERTY Speed : INT\nEND_PROPERTY\n"
       "END_INTERFACE\n"},
      {"fb.st",
       "FUNCTION_BLOCK FB_Motor IMPLEMENTS I_Motor\n"
       "METHOD Reset\nEND_METHOD\n"
       "END_FUNCTION_BLOCK\n"}});
  const Symbol* block = project.model().find_global("FB_Motor");
  ASSERT_NE(block, nullptr);
  const std::vector<query::MissingMembers> missing = query::missing_interface_members(project.model(), *block);
  ASSERT_EQ(missing.size(), 1u);
  EXPECT_EQ(missing[0].interface->name, "I_Motor");
  ASSERT_EQ(missing[0].members.size(), 2u);  // Reset is there
  const auto edit = query::implement_members(project.workspace(), *block, missing[0].members, spaces());
  ASSERT_TRUE(edit);
  EXPECT_EQ(applied(project.text_of("fb.st"), {*edit}),
            "FUNCTION_BLOCK FB_Motor IMPLEMENTS I_Motor\n"
            "METHOD Reset\nEND_METHOD\n"
            "METHOD Start : BOOL\nVAR_INPUT\n    nSpeed : INT;\nEND_VAR\nEND_METHOD\n"
            "PROPERTY Speed : INT\nEND_PROPERTY\n"
            "END_FUNCTION_BLOCK\n");
}

// ---- container edits --------------------------------------------------------------------------

TEST(SourceEdits, ContainerEditsStayInsideTheStTheFileStores) {
  const std::string pou =
      "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n"
      "<TcPlcObject Version=\"1.1.0.1\">\n"
      "  <POU Name=\"FB_A\" Id=\"{00000000-0000-0000-0000-000000000001}\">\n"
      "    <Declaration><![CDATA[FUNCTION_BLOCK FB_A\nVAR\n\tb : BOOL;\nEND_VAR\n]]></Declaration>\n"
      "    <Implementation>\n"
      "      <ST><![CDATA[b := TRUE;]]></ST>\n"
      "    </Implementation>\n"
      "  </POU>\n"
      "</TcPlcObject>\n";
  const Document document = Document::from_bytes("FB_A.TcPOU", pou);
  const std::string_view tree = document.tree()->text();
  const auto at = [&](std::string_view needle) { return static_cast<uint32_t>(tree.find(needle)); };
  // In the body: mapped into the CDATA.
  const auto body = query::file_edits_of(document, {lint::TextEdit{{at("TRUE"), at("TRUE") + 4}, "FALSE"}});
  ASSERT_TRUE(body);
  EXPECT_NE(applied(document.file_text(), *body).find("<![CDATA[b := FALSE;]]>"), std::string::npos);
  // After the body's last character (typing at its end) still belongs to it.
  const uint32_t end = at("TRUE;") + 5;
  EXPECT_TRUE(query::file_edits_of(document, {lint::TextEdit{{end, end}, " b := FALSE;"}}));
  // What would end the CDATA section is refused, and so is an edit spanning the declaration and the
  // body: between them lies the line break rung adds, which the file does not store.
  EXPECT_FALSE(query::file_edits_of(document, {lint::TextEdit{{end, end}, "(* ]]> *)"}}));
  EXPECT_FALSE(query::file_edits_of(document, {lint::TextEdit{{at("END_VAR"), at("b := TRUE")}, ""}}));
  EXPECT_TRUE(query::file_edits_of(document, {lint::TextEdit{{at("END_VAR"), at("END_VAR") + 7}, "END_VAR"}}));
}

}  // namespace
}  // namespace rung::check
