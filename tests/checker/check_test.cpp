// The semantic checker end to end: texts in, diagnostics out (codes and positions).
#include "checker/check.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace rung::check {
namespace {

std::vector<std::string> codes_of(const std::vector<std::pair<std::string, std::string>>& files,
                                  project::Profile profile = project::Profile::Codesys) {
  project::ProjectConfig config;
  config.profile = profile;
  auto workspace = Workspace::from_texts(files, config);
  std::vector<std::string> codes;
  for (const auto& file : workspace->check_all(1)) {
    for (const auto& diagnostic : file.diagnostics) codes.push_back(diagnostic.code);
  }
  return codes;
}

std::vector<std::string> codes_of(const std::string& text, project::Profile profile = project::Profile::Codesys) {
  return codes_of({{"P.st", text}}, profile);
}

using Codes = std::vector<std::string>;

TEST(Check, CleanProgramHasNoDiagnostics) {
  EXPECT_EQ(codes_of("PROGRAM P\nVAR a : INT; b : DINT; t : TON; END_VAR\n"
                     "b := a + 1;\nt(IN := a > 3, PT := T#1s);\nIF t.Q THEN a := 0; END_IF\nEND_PROGRAM\n"),
            Codes{});
}

TEST(Check, IntegerLiteralIntoBoolIsC0032) {
  // 000a L4695-4711: bReady := 211 -> "Cannot convert type 'USINT' to type 'BOOL'"
  project::ProjectConfig config;
  auto workspace =
      Workspace::from_texts({{"P.st", "PROGRAM P\nVAR bReady : BOOL; END_VAR\nbReady := 211;\nEND_PROGRAM\n"}}, config);
  auto results = workspace->check_all(1);
  ASSERT_EQ(results.size(), 1u);
  ASSERT_EQ(results[0].diagnostics.size(), 1u);
  EXPECT_EQ(results[0].diagnostics[0].code, "E101");
  EXPECT_EQ(results[0].diagnostics[0].message, "cannot convert type 'USINT' to type 'BOOL'");
}

TEST(Check, ConversionHelpNamesAFunctionThatExists) {
  // The help names the standard conversion: STRING_TO_UINT for a STRING(43), TO_INT for an enum
  // value; none where no function converts (into an enum).
  project::ProjectConfig config;
  config.profile = project::Profile::Twincat;
  auto workspace =
      Workspace::from_texts({{"P.st",
                              "{attribute 'strict'}\nTYPE E_Mode : (AUTO, MANUAL); END_TYPE\n"
                              "PROGRAM P\nVAR s : STRING(43); u : UINT; e : E_Mode; i : INT; r : REAL; END_VAR\n"
                              "u := s;\ni := e;\ne := i;\ni := r;\nEND_PROGRAM\n"}},
                            config);
  auto results = workspace->check_all(1);
  ASSERT_EQ(results.size(), 1u);
  std::vector<std::string> found;
  for (const auto& d : results[0].diagnostics) found.push_back(d.code + ": " + d.message + " | " + d.help);
  EXPECT_EQ(found, (Codes{"E101: cannot convert type 'STRING(43)' to type 'UINT' | use STRING_TO_UINT(x)",
                          "E101: cannot convert type 'E_Mode' to type 'INT' | use TO_INT(x)",
                          "E101: cannot convert type 'INT' to type 'E_Mode' | ",
                          "E105: implicit conversion from REAL to INT may lose data | "
                          "use an explicit conversion: REAL_TO_INT()"}));
}

TEST(Check, SubrangeConstantOutOfRange) {
  // 000a L6216-6225: nPosition : INT(0..90); nPosition := 99;
  EXPECT_EQ(codes_of("PROGRAM P\nVAR n : INT(0..90); END_VAR\nn := 99;\nn := 90;\nEND_PROGRAM\n"), Codes{"E102"});
}

TEST(Check, UnknownVariableOfAGlobalListSuggestsTheCloseOne) {
  auto workspace = Workspace::from_texts(
      {{"GVL_IO.st",
        "{attribute 'qualified_only'}\nVAR_GLOBAL\n    bStartButton : BOOL;\n    bStop : BOOL;\nEND_VAR\n"},
       {"P.st", "PROGRAM P\nVAR b : BOOL; END_VAR\nb := GVL_IO.bStartButon;\nb := GVL_IO.nZzz;\nEND_PROGRAM\n"}},
      project::ProjectConfig{});
  const FileDiagnostics result = workspace->check_source(*workspace->model().find_source("P.st"));
  ASSERT_EQ(result.diagnostics.size(), 2u);
  EXPECT_EQ(result.diagnostics[0].code, "E005");
  EXPECT_EQ(result.diagnostics[0].help, "did you mean 'bStartButton'?");
  EXPECT_EQ(result.diagnostics[1].code, "E005");
  EXPECT_EQ(result.diagnostics[1].help, "");  // nothing close
}

TEST(Check, UndeclaredNameSuggestsTheCloseOne) {
  project::ProjectConfig config;
  auto workspace = Workspace::from_texts(
      {{"P.st", "PROGRAM P\nVAR bStart : BOOL; END_VAR\nbStrat := TRUE;\nEND_PROGRAM\n"}}, config);
  auto results = workspace->check_all(1);
  ASSERT_EQ(results[0].diagnostics.size(), 1u);
  EXPECT_EQ(results[0].diagnostics[0].code, "E001");
  EXPECT_EQ(results[0].diagnostics[0].help, "did you mean 'bStart'?");
}

TEST(Check, NamesResolveAcrossFilesInAnyOrder) {
  EXPECT_EQ(codes_of({{"A.st", "PROGRAM A\nVAR m : FB_M; END_VAR\nm(x := GVL.limit);\nEND_PROGRAM\n"},
                      {"FB_M.st", "FUNCTION_BLOCK FB_M\nVAR_INPUT x : E_Mode; END_VAR\nEND_FUNCTION_BLOCK\n"},
                      {"GVL.st", "VAR_GLOBAL CONSTANT limit : E_Mode := E_Mode.Fast; END_VAR\n"},
                      {"E.st", "TYPE E_Mode : (Slow, Fast); END_TYPE\n"}}),
            Codes{});
}

TEST(Check, UnknownTypeIsTheLibraryCode) {
  EXPECT_EQ(codes_of("PROGRAM P\nVAR f : FB_FromVendorLib; END_VAR\nf();\nEND_PROGRAM\n"), Codes{"E002"});
}

TEST(Check, StatementRules) {
  EXPECT_EQ(codes_of("PROGRAM P\nVAR i : INT; END_VAR\nEXIT;\nEND_PROGRAM\n"), Codes{"E408"});
  EXPECT_EQ(codes_of("PROGRAM P\nVAR i : INT; END_VAR\nCASE i OF 1: i := 2; 1: i := 3; END_CASE\nEND_PROGRAM\n"),
            Codes{"E405"});
  EXPECT_EQ(codes_of("PROGRAM P\nVAR i : INT; END_VAR\nIF i THEN i := 1; END_IF\nEND_PROGRAM\n"), Codes{"E103"});
  EXPECT_EQ(codes_of("PROGRAM P\nVAR CONSTANT c : INT := 1; END_VAR\nc := 2;\nEND_PROGRAM\n"), Codes{"E401"});
  EXPECT_EQ(codes_of("PROGRAM P\nVAR i : INT; END_VAR\nFOR i := 1 TO 3 DO i := 2; END_FOR\nEND_PROGRAM\n"),
            Codes{"E407"});
  EXPECT_EQ(codes_of("PROGRAM P\nVAR i : INT; END_VAR\ni := i / 0;\nEND_PROGRAM\n"), Codes{"E702"});
  EXPECT_EQ(codes_of("PROGRAM P\nVAR a : ARRAY[1..3] OF INT; END_VAR\na[4] := 1;\nEND_PROGRAM\n"), Codes{"E107"});
  EXPECT_EQ(codes_of("PROGRAM P\nVAR t : TON; END_VAR\nt.Q := TRUE;\nEND_PROGRAM\n"), Codes{"E402"});
}

// Found on a real OpenPLC program: E_State#Idle as a CASE label is a constant, like Idle and
// E_State.Idle, and takes part in the duplicate-label check.
TEST(Check, TypedEnumValuesAreConstantCaseLabels) {
  const std::string type = "TYPE E_State : (Idle, Run := 5); END_TYPE\n";
  EXPECT_EQ(codes_of(type + "PROGRAM P\nVAR s : E_State; END_VAR\n"
                            "CASE s OF E_State#Idle: s := E_State#Run; E_State#Run: ; END_CASE\nEND_PROGRAM\n"),
            Codes{});
  EXPECT_EQ(codes_of(type + "PROGRAM P\nVAR s : E_State; END_VAR\n"
                            "CASE s OF E_State#Run: ; E_State.Run: ; END_CASE\nEND_PROGRAM\n"),
            Codes{"E405"});
}

TEST(Check, CallRules) {
  EXPECT_EQ(codes_of("PROGRAM P\nVAR t : TON; END_VAR\nt(IN := TRUE, PTT := T#1s);\nEND_PROGRAM\n"), Codes{"E301"});
  EXPECT_EQ(codes_of("PROGRAM P\nVAR t : TON; END_VAR\nt(Q := TRUE);\nEND_PROGRAM\n"), Codes{"E308"});
  EXPECT_EQ(codes_of("PROGRAM P\nTON(IN := TRUE);\nEND_PROGRAM\n"), Codes{"E307"});
}

TEST(Check, NarrowingIsAWarningInCodesysAndAnErrorInIec) {
  const std::string text = "PROGRAM P\nVAR i : INT; d : DINT; END_VAR\ni := d;\nEND_PROGRAM\n";
  EXPECT_EQ(codes_of(text, project::Profile::Codesys), Codes{"E105"});
  EXPECT_EQ(codes_of(text, project::Profile::Iec), Codes{"E101"});
}

TEST(Check, DeclarationRules) {
  EXPECT_EQ(codes_of("FUNCTION F : INT\nVAR RETAIN r : INT; END_VAR\nF := r;\nEND_FUNCTION\n"), Codes{"E202"});
  EXPECT_EQ(codes_of("PROGRAM P\nVAR a : INT; a : BOOL; END_VAR\nEND_PROGRAM\n"), Codes{"E003"});
  EXPECT_EQ(codes_of("INTERFACE I\nMETHOD M : BOOL\nEND_METHOD\nEND_INTERFACE\n"
                     "FUNCTION_BLOCK FB IMPLEMENTS I\nEND_FUNCTION_BLOCK\n"),
            Codes{"E204"});
}

TEST(Check, ObsoleteWarnsAtUseButNotInsideItself) {
  EXPECT_EQ(codes_of("{attribute 'obsolete' := 'use F2'}\nFUNCTION F : INT\nF := 1;\nEND_FUNCTION\n"
                     "PROGRAM P\nVAR i : INT; END_VAR\ni := F();\nEND_PROGRAM\n"),
            Codes{"E601"});
}

TEST(Check, BrokenCodeGivesSyntaxErrorsAndNoCrash) {
  const Codes codes = codes_of("PROGRAM P\nVAR a : INT END_VAR\na := := 3;\nIF a THEN\nEND_PROGRAM\n");
  ASSERT_FALSE(codes.empty());
  EXPECT_EQ(codes.front()[0], 'S');
}

TEST(Check, EditInABodyRechecksOnlyThatFile) {
  project::ProjectConfig config;
  auto workspace = Workspace::from_texts({{"A.st", "PROGRAM A\nVAR x : INT; END_VAR\nx := 1;\nEND_PROGRAM\n"},
                                          {"B.st", "PROGRAM B\nVAR y : INT; END_VAR\ny := 2;\nEND_PROGRAM\n"}},
                                         config);
  auto changed = workspace->update(0, "PROGRAM A\nVAR x : INT; END_VAR\nx := z;\nEND_PROGRAM\n");
  EXPECT_EQ(changed, std::vector<SourceId>{0});
  EXPECT_EQ(workspace->check_source(0).diagnostics.size(), 1u);
  // A declaration change re-checks the files that name what changed: B names nothing of A.
  changed = workspace->update(0, "PROGRAM A\nVAR x : INT; z : INT; END_VAR\nx := z;\nEND_PROGRAM\n");
  EXPECT_EQ(changed, std::vector<SourceId>{0});
  EXPECT_TRUE(workspace->check_source(0).diagnostics.empty());
  // B starts naming A.z; then A's interface changes again (z becomes BOOL): both are re-checked.
  EXPECT_EQ(workspace->update(1, "PROGRAM B\nVAR y : INT; END_VAR\ny := A.z;\nEND_PROGRAM\n"),
            std::vector<SourceId>{1});
  changed = workspace->update(0, "PROGRAM A\nVAR x : INT; z : BOOL; END_VAR\nx := 1;\nEND_PROGRAM\n");
  EXPECT_EQ(changed, (std::vector<SourceId>{0, 1}));
  EXPECT_FALSE(workspace->check_source(1).diagnostics.empty());  // y := A.z: BOOL into INT
}

TEST(Check, UnknownQualifierIsTheMissingLibraryCode) {
  // TcUnit.RUN() without TcUnit's stubs: E002, like unknown library types and POUs; a qualifier
  // close to a local name is still a typo (E001 with did-you-mean).
  EXPECT_EQ(codes_of("PROGRAM P\nVAR fbMotor : TON; END_VAR\nTcUnit.RUN();\nfbMotr.IN := TRUE;\nEND_PROGRAM\n"),
            (Codes{"E002", "E001"}));
}

TEST(Check, ExplicitDecimalLiteral) {
  // 10#30000 (TcUnit examples): a decimal number, so it fits a UINT like 30000 does, and 40000
  // is out of range for an INT like the plain literal.
  EXPECT_EQ(codes_of("PROGRAM P\nVAR u : UINT := 10#30000; i : INT; END_VAR\ni := 10#40000;\nEND_PROGRAM\n"),
            (Codes{"E102"}));
}

TEST(Check, TwinCatHeadersWithModifiersAndSemicolons) {
  // PROGRAM INTERNAL Roots is a program named Roots; a ';' after a method header
  // (METHOD PUBLIC SetBuffer : BOOL;) keeps the method's parameters, locals and result in scope.
  const std::string text =
      "PROGRAM INTERNAL Roots\n"
      "VAR n : INT; END_VAR\n"
      "n := n + 1;\n"
      "END_PROGRAM\n"
      "FUNCTION_BLOCK FB_Buffer\n"
      "VAR nSize : UDINT; END_VAR\n"
      "METHOD PUBLIC SetBuffer : BOOL;\n"
      "VAR_INPUT nLength : UDINT; END_VAR\n"
      "VAR nCopied : UDINT; END_VAR\n"
      "nCopied := MIN(nLength, 10);\n"
      "nSize := nCopied;\n"
      "SetBuffer := nCopied > 0;\n"
      "END_METHOD\n"
      "END_FUNCTION_BLOCK\n"
      "PROGRAM Main\n"
      "VAR fb : FB_Buffer; ok : BOOL; END_VAR\n"
      "ok := fb.SetBuffer(nLength := 1);\n"
      "Roots();\n"
      "END_PROGRAM\n";
  EXPECT_EQ(codes_of(text, project::Profile::Twincat), Codes{});
}

TEST(Check, UnreadableFileInTheMiddleKeepsLaterFilesApart) {
  // Files are parsed and their symbols collected on several threads under the ids they will get;
  // a file that cannot be read shifts the ids of every file after it.
  namespace fs = std::filesystem;
  const fs::path folder = fs::temp_directory_path() / "rung_check_unreadable";
  fs::remove_all(folder);
  fs::create_directories(folder);
  std::ofstream(folder / "a.st") << "FUNCTION_BLOCK FB_A\nVAR_INPUT x : INT; END_VAR\nEND_FUNCTION_BLOCK\n";
  std::ofstream(folder / "c.st") << "PROGRAM P\nVAR f : FB_A; END_VAR\nf(x := 1);\nf.y := 2;\nEND_PROGRAM\n"
                                    "FUNCTION F_Loop : INT\nF_Loop := F_Loop();\nEND_FUNCTION\n";
  project::ProjectConfig config;
  LoadOptions options;
  options.threads = 2;
  auto workspace = Workspace::load_files({folder / "a.st", folder / "missing.st", folder / "c.st"}, config, options);
  ASSERT_EQ(workspace->load_errors.size(), 1u);
  std::vector<std::string> found;
  for (const auto& file : workspace->check_all(1)) {
    for (const auto& diagnostic : file.diagnostics) {
      found.push_back(fs::path(file.path).filename().string() + ":" + diagnostic.code);
    }
  }
  // f.y: FB_A has no member y (FB_A itself resolves); the recursion is reported in c.st, the file
  // its symbols say they belong to.
  EXPECT_EQ(found, (Codes{"c.st:E005", "c.st:E209"}));
  fs::remove_all(folder);
}

}  // namespace
}  // namespace rung::check
