// Pragmas end to end through the Workspace: message pragmas (E602, E603, E605), unknown pragmas
// (E604), malformed conditional compilation (E606), and code in inactive {IF} branches, which is
// not checked at all.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include "checker/check.hpp"

namespace rung::check {
namespace {

struct Finding {
  std::string file;
  std::string code;
  uint32_t line = 0;
  std::string message;
  Severity severity = Severity::Error;
};

using Files = std::vector<std::pair<std::string, std::string>>;

uint32_t line_of(const std::string& text, uint32_t offset) {
  return 1 +
         static_cast<uint32_t>(std::count(text.begin(), text.begin() + std::min<size_t>(offset, text.size()), '\n'));
}

std::vector<Finding> findings_of(const Workspace& workspace, const Files& files) {
  std::map<std::string, std::string> texts(files.begin(), files.end());
  std::vector<Finding> out;
  for (const auto& file : workspace.check_all(1)) {
    for (const auto& d : file.diagnostics) {
      out.push_back({file.path, d.code, line_of(texts[file.path], d.range.begin), d.message, d.severity});
    }
  }
  return out;
}

std::vector<Finding> check(const Files& files, const std::map<std::string, std::string>& defines = {}) {
  project::ProjectConfig config;
  config.defines = defines;
  auto workspace = Workspace::from_texts(files, config);
  return findings_of(*workspace, files);
}

std::vector<Finding> check(const std::string& text, const std::map<std::string, std::string>& defines = {}) {
  return check(Files{{"P.st", text}}, defines);
}

// "CODE@LINE" for each finding, in report order.
std::vector<std::string> codes_at(const std::vector<Finding>& findings) {
  std::vector<std::string> out;
  for (const auto& f : findings) out.push_back(f.code + "@" + std::to_string(f.line));
  return out;
}

using Codes = std::vector<std::string>;

TEST(PragmaCheck, MessagePragmasReportTheUsersText) {
  const auto findings = check(
      "PROGRAM P\nVAR\n  ivar : INT; {info 'TODO: should get another name'}\nEND_VAR\n"
      "{warning 'This is a warning'}\n{error 'select the variant'}\n{text 'Part xy has been compiled completely'}\n"
      "ivar := ivar + 1;\nEND_PROGRAM\n");
  ASSERT_EQ(codes_at(findings), (Codes{"E605@3", "E602@5", "E603@6", "E605@7"}));
  EXPECT_EQ(findings[0].message, "TODO: should get another name");
  EXPECT_EQ(findings[0].severity, Severity::Info);
  EXPECT_EQ(findings[1].message, "This is a warning");
  EXPECT_EQ(findings[1].severity, Severity::Warning);
  EXPECT_EQ(findings[2].message, "select the variant");
  EXPECT_EQ(findings[2].severity, Severity::Error);
  EXPECT_EQ(findings[3].message, "Part xy has been compiled completely");
}

TEST(PragmaCheck, WarningLevelDigitIsNotPartOfTheText) {
  const auto findings = check("PROGRAM P\n{warning 2 'calibrate'}\nEND_PROGRAM\n");
  ASSERT_EQ(findings.size(), 1u);
  EXPECT_EQ(findings[0].message, "calibrate");
}

TEST(PragmaCheck, UserAttributesAndKnownPragmasAreSilent) {
  EXPECT_EQ(
      codes_at(check("{attribute 'vision'}\nFUNCTION fun1 : INT\nVAR_INPUT i : INT; END_VAR\nfun1 := i;\n"
                     "END_FUNCTION\nPROGRAM P\nVAR\n  {attribute 'DoCount'}\n  ivar : INT; {attribute 'x' := 'y'}\n"
                     "END_VAR\n{region \"Main\"}\nivar := fun1(1);\n{endregion}\n{library private}\n"
                     "{include 'common.st'}\nEND_PROGRAM\n")),
      Codes{});
}

TEST(PragmaCheck, VendorPragmasForWarningsFlowControlAndAnalysisAreSilent) {
  // CODESYS V3 / TwinCAT 3: {warning disable|restore <id>}, {noflow}/{flow}, {analysis -n|+n}.
  EXPECT_EQ(codes_at(check("PROGRAM P\nVAR n : INT; END_VAR\n{warning disable C0371}\n{ WARNING Restore C0371 }\n"
                           "{noflow}\nn := n + 1;\n{flow}\n{analysis -33}\n{analysis +33}\n"
                           "{warning 'disable this'}\n{warning}\nEND_PROGRAM\n")),
            (Codes{"E602@10", "E602@11"}));
}

TEST(PragmaCheck, UnknownPragmaIsAWarningWithASuggestion) {
  const auto findings =
      check("PROGRAM P\nVAR\n  {atribute 'hide'}\n  n : INT;\nEND_VAR\n{frobnicate 1}\nn := 1;\nEND_PROGRAM\n");
  ASSERT_EQ(codes_at(findings), (Codes{"E604@3", "E604@6"}));
  EXPECT_EQ(findings[0].severity, Severity::Warning);
  EXPECT_EQ(findings[0].message, "unknown pragma {atribute 'hide'} is ignored");
}

TEST(PragmaCheck, CodeInAnInactiveBranchIsNotChecked) {
  const std::string text =
      "PROGRAM P\nVAR a : INT; END_VAR\n{IF defined(SIM)}\na := undeclared_in_sim;\n{warning 'simulation build'}\n"
      "{ELSE}\na := TRUE;\n{error 'real build'}\n{END_IF}\nEND_PROGRAM\n";
  // Without SIM the ELSE branch is compiled: BOOL into INT (E101) and the error pragma.
  EXPECT_EQ(codes_at(check(text)), (Codes{"E101@7", "E603@8"}));
  // rung.toml [defines] SIM = true: the first branch.
  EXPECT_EQ(codes_at(check(text, {{"SIM", ""}})), (Codes{"E001@4", "E602@5"}));
}

TEST(PragmaCheck, DeclarationsInTwoBranchesAreNoDuplicates) {
  const std::string text =
      "PROGRAM P\nVAR\n{IF defined(BIG)}\n  n : DINT;\n{ELSE}\n  n : INT;\n{END_IF}\nEND_VAR\nn := "
      "70000;\nEND_PROGRAM\n";
  // 70000 does not fit INT (E102) only where the INT declaration is the compiled one.
  EXPECT_EQ(codes_at(check(text)), Codes{"E102@9"});
  EXPECT_EQ(codes_at(check(text, {{"BIG", ""}})), Codes{});
}

TEST(PragmaCheck, DefineInTheFileAndHasValueFromRungToml) {
  const std::string text =
      "{define LOCAL}\nPROGRAM P\nVAR x : INT; END_VAR\n{IF defined(LOCAL) AND hasvalue(VARIANT, '2')}\nx := 2;\n"
      "{ELSE}\nx := missing;\n{END_IF}\nEND_PROGRAM\n";
  EXPECT_EQ(codes_at(check(text, {{"VARIANT", "2"}})), Codes{});
  EXPECT_EQ(codes_at(check(text, {{"VARIANT", "1"}})), Codes{"E001@7"});
}

TEST(PragmaCheck, ConditionsAboutTheProjectsOwnDeclarations) {
  const Files files = {
      {"Lib.st",
       "{attribute 'vision'}\nFUNCTION fun1 : INT\nVAR_INPUT i : INT; END_VAR\nfun1 := i;\nEND_FUNCTION\n"
       "TYPE DUT : STRUCT a : INT; END_STRUCT END_TYPE\n"},
      {"GVL.st", "VAR_GLOBAL\n  {attribute 'DoCount'}\n  g_count : INT;\n  g_multi : LREAL;\nEND_VAR\n"},
      {"P.st",
       "PROGRAM P\nVAR local : STRING(20); r : INT; d : DUT; END_VAR\n"
       "{IF defined(pou: fun1) AND defined(type: DUT) AND defined(variable: local) AND defined(variable: GVL.g_count) "
       "AND defined(variable: d.a) AND NOT defined(variable: d.b) AND defined(type: INT)}\n"
       "r := fun1(1);\n{ELSE}\nr := no1;\n{END_IF}\n"
       "{IF hasattribute(pou: fun1, 'vision') AND hasattribute(variable: g_count, 'docount')}\nr := 2;\n{ELSE}\n"
       "r := no2;\n{END_IF}\n"
       "{IF hastype(variable: g_multi, LREAL) AND hastype(variable: g_multi, ANY_REAL) AND "
       "hastype(variable: local, STRING) AND NOT hastype(variable: r, ANY_REAL)}\nr := 3;\n{ELSE}\nr := "
       "no3;\n{END_IF}\n"
       "{IF defined(pou: CheckBounds) OR defined(type: Missing) OR defined(variable: nowhere) OR "
       "hasattribute(pou: fun1, 'other') OR defined(task: T1) OR defined(resource: R1)}\nr := no4;\n{END_IF}\n"
       "END_PROGRAM\n"}};
  EXPECT_EQ(codes_at(check(files)), Codes{});
}

TEST(PragmaCheck, TasksAndResourcesOfAConfiguration) {
  const Files files = {
      {"P.st",
       "PROGRAM P\nVAR r : INT; END_VAR\n{IF defined(task: Fast) AND defined(resource: Cpu)}\nr := 1;\n{ELSE}\n"
       "r := no;\n{END_IF}\nEND_PROGRAM\n"},
      {"C.st",
       "CONFIGURATION Cell\nRESOURCE Cpu ON PLC\nTASK Fast(INTERVAL := T#10ms, PRIORITY := 1);\n"
       "PROGRAM Main WITH Fast : P;\nEND_RESOURCE\nEND_CONFIGURATION\n"}};
  EXPECT_EQ(codes_at(check(files)), Codes{});
}

TEST(PragmaCheck, DeclarationsInInactiveBranchesDoNotAnswerConditions) {
  // g_sim exists only in simulation builds; the program's own test must see that.
  const Files files = {
      {"GVL.st", "VAR_GLOBAL\n{IF defined(SIM)}\n  g_sim : BOOL;\n{END_IF}\n  g_run : BOOL;\nEND_VAR\n"},
      {"P.st",
       "PROGRAM P\n{IF defined(variable: g_sim)}\ng_sim := TRUE;\n{ELSE}\ng_run := TRUE;\n{END_IF}\nEND_PROGRAM\n"}};
  EXPECT_EQ(codes_at(check(files)), Codes{});
  EXPECT_EQ(codes_at(check(files, {{"SIM", ""}})), Codes{});
}

TEST(PragmaCheck, MalformedConditionalCompilationIsE606) {
  const auto findings = check(
      "PROGRAM P\nVAR x : INT; END_VAR\n{IF defined(A) foo}\nx := 1;\n{END_IF}\n{END_IF}\n{IF defined(B)}\nx := 2;\n");
  ASSERT_EQ(codes_at(findings), (Codes{"E606@3", "E606@6", "E606@7"}));
  EXPECT_EQ(findings[0].message, "unexpected 'foo' in condition");
  EXPECT_EQ(findings[1].message, "{END_IF} without {IF}");
  EXPECT_EQ(findings[2].message, "{IF} without {END_IF}");
}

TEST(PragmaCheck, BranchesMaySplitAStatement) {
  // The text as written does not parse (two IF headers, one END_IF); the chosen branch does.
  const std::string text =
      "PROGRAM P\nVAR a, b : BOOL; n : INT; END_VAR\n{IF defined(FAST)}\nIF a THEN\n{ELSE}\nIF b AND unknown_b THEN\n"
      "{END_IF}\nn := 1;\nEND_IF\nEND_PROGRAM\n";
  EXPECT_EQ(codes_at(check(text, {{"FAST", ""}})), Codes{});
  EXPECT_EQ(codes_at(check(text)), Codes{"E001@6"});
}

TEST(PragmaCheck, AnEditorChangeReevaluatesTheConditions) {
  project::ProjectConfig config;
  const Files files = {
      {"Lib.st", "FUNCTION Helper : INT\nHelper := 1;\nEND_FUNCTION\n"},
      {"P.st",
       "PROGRAM P\nVAR r : INT; END_VAR\n{IF defined(pou: Helper)}\nr := Helper();\n{ELSE}\nr := fallback;\n"
       "{END_IF}\nEND_PROGRAM\n"}};
  auto workspace = Workspace::from_texts(files, config);
  EXPECT_EQ(codes_at(findings_of(*workspace, files)), Codes{});
  // Helper is renamed: P's condition turns false and its ELSE branch is compiled.
  const Files renamed = {{"Lib.st", "FUNCTION Helper2 : INT\nHelper2 := 1;\nEND_FUNCTION\n"}, files[1]};
  const std::vector<SourceId> changed = workspace->update(*workspace->model().find_source("Lib.st"), renamed[0].second);
  EXPECT_NE(std::find(changed.begin(), changed.end(), *workspace->model().find_source("P.st")), changed.end());
  EXPECT_EQ(codes_at(findings_of(*workspace, renamed)), Codes{"E001@6"});
}

}  // namespace
}  // namespace rung::check
