// The query API the language server calls (checker/query): go to definition, find references,
// type under the cursor, members after '.'. Positions are FILE offsets, written in the tests as
// a snippet of the file with '|' where the cursor stands.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "checker/check.hpp"
#include "checker/query/definition.hpp"
#include "checker/query/members.hpp"
#include "checker/query/references.hpp"
#include "checker/query/type_at.hpp"
#include "tests/support/marked_project.hpp"

namespace rung::check {
namespace {

using Files = testing::MarkedProject::Files;

// The shared marked project, with the answers these tests compare: symbols, types and references.
class Project : public testing::MarkedProject {
 public:
  using MarkedProject::MarkedProject;

  const Symbol* symbol(const std::string& path, const std::string& marked, size_t nth = 0) const {
    return query::symbol_at(workspace(), id(path), at(path, marked, nth));
  }
  const Type* type(const std::string& path, const std::string& marked, size_t nth = 0) const {
    return query::type_at(workspace(), id(path), at(path, marked, nth));
  }

  // "path@offset" of every reference, checking that each range spells the symbol's name.
  std::vector<std::string> references(const Symbol* symbol, bool include_declaration = true) const {
    std::vector<std::string> out;
    for (const query::Location& location : query::find_references(workspace(), symbol, include_declaration)) {
      const std::string& text = text_of(location.path);
      const std::string_view spelled =
          std::string_view(text).substr(location.range.begin, location.range.end - location.range.begin);
      EXPECT_TRUE(names_equal(spelled, symbol->name)) << location.path << ": '" << spelled << "'";
      out.push_back(where(location));
    }
    return out;
  }
};

// "path@offset" items in the order find_references gives: by path, then by offset.
std::vector<std::string> sorted(std::vector<std::string> items) {
  auto key = [](const std::string& item) {
    const size_t at = item.rfind('@');
    return std::make_pair(item.substr(0, at), std::stoul(item.substr(at + 1)));
  };
  std::sort(items.begin(), items.end(), [&](const std::string& a, const std::string& b) { return key(a) < key(b); });
  return items;
}

std::vector<std::string> names_of(const std::vector<const Symbol*>& symbols) {
  std::vector<std::string> names;
  for (const Symbol* symbol : symbols) names.emplace_back(symbol->name);
  return names;
}

const Files kMachine = {
    {"GVL.st",
     "VAR_GLOBAL\n"
     "  gSpeed : INT;\n"
     "  gMode : E_Mode;\n"
     "END_VAR\n"},
    {"Types.st",
     "TYPE E_Mode : (Idle, Run, Stop) END_TYPE\n"
     "TYPE ST_Point : STRUCT x : REAL; y : REAL; END_STRUCT END_TYPE\n"},
    {"FB_Base.st",
     "FUNCTION_BLOCK FB_Base\n"
     "VAR_OUTPUT bBusy : BOOL; END_VAR\n"
     "METHOD Reset : BOOL\n"
     "bBusy := FALSE;\n"
     "Reset := TRUE;\n"
     "END_METHOD\n"
     "END_FUNCTION_BLOCK\n"},
    {"FB_Motor.st",
     "FUNCTION_BLOCK FB_Motor EXTENDS FB_Base\n"
     "VAR_INPUT bStart : BOOL; target : ST_Point; END_VAR\n"
     "VAR_OUTPUT nSpeed : INT; END_VAR\n"
     "VAR nCount : INT; END_VAR\n"
     "METHOD Start : BOOL\n"
     "VAR_INPUT nRamp : INT; END_VAR\n"
     "THIS^.nSpeed := nRamp;\n"
     "SUPER^.Reset();\n"
     "Start := BSTART;\n"
     "END_METHOD\n"
     "IF bStart THEN nCount := nCount + 1; nSpeed := gSpeed; END_IF\n"
     "END_FUNCTION_BLOCK\n"},
    {"Scale.st",
     "FUNCTION Scale : ST_Point\n"
     "VAR_INPUT p : ST_Point; k : REAL; END_VAR\n"
     "Scale.x := p.x * k;\n"
     "Scale.y := p.y * k;\n"
     "END_FUNCTION\n"},
    {"Main.st",
     "PROGRAM Main\n"
     "VAR\n"
     "  fbMotor : FB_Motor;\n"
     "  points : ARRAY[0..3] OF ST_Point;\n"
     "  pTarget : POINTER TO ST_Point;\n"
     "  origin : ST_Point := (x := 1.5, y := 0);\n"
     "  mode : E_Mode := E_Mode#Run;\n"
     "  nCount : INT;\n"
     "END_VAR\n"
     "fbMotor(bStart := gSpeed > 0, nSpeed => nCount);\n"
     "IF fbMotor.bStart AND fbMotor.bBusy THEN fbMotor.Start(nRamp := 10); END_IF\n"
     "GVL.gSpeed := GVL.gSpeed + 1;\n"
     "IF gMode = E_Mode.Run OR mode = Run THEN points[0] := Scale(p := origin, k := 2.0); END_IF\n"
     "fbMotor.Reset();\n"
     "END_PROGRAM\n"},
    {"Service.st",
     "PROGRAM Service\n"
     "VAR gSpeed : REAL; END_VAR\n"  // hides the global of the same name
     "VAR_EXTERNAL gMode : E_Mode; END_VAR\n"
     "gSpeed := 2.5;\n"
     "gMode := E_Mode.Stop;\n"
     "END_PROGRAM\n"},
};

TEST(QueryDefinition, LocalVariable) {
  const Project project(kMachine);
  const Symbol* count = project.symbol("Main.st", "nSpeed => n|Count");
  ASSERT_NE(count, nullptr);
  EXPECT_EQ(count->kind, SymbolKind::Variable);
  EXPECT_EQ(count->owner->name, "Main");
  const auto location =
      query::definition_at(project.workspace(), project.id("Main.st"), project.at("Main.st", "nSpeed => n|Count"));
  ASSERT_TRUE(location.has_value());
  EXPECT_EQ(location->path, "Main.st");
  EXPECT_EQ(location->range.begin, project.at("Main.st", "  |nCount : INT;"));
  EXPECT_EQ(location->range.end, location->range.begin + 6);
  // The cursor right after the name still means it (editors send the position after a word).
  EXPECT_EQ(project.symbol("Main.st", "nSpeed => nCount|"), count);
  // FB_Motor's own nCount is another symbol.
  const Symbol* fb_count = project.symbol("FB_Motor.st", "nCount := |nCount");
  ASSERT_NE(fb_count, nullptr);
  EXPECT_NE(fb_count, count);
  EXPECT_EQ(fb_count->owner->name, "FB_Motor");
}

TEST(QueryReferences, LocalVariableStaysInItsPou) {
  const Project project(kMachine);
  const Symbol* count = project.symbol("FB_Motor.st", "|nCount := nCount");
  ASSERT_NE(count, nullptr);
  EXPECT_EQ(project.references(count), (std::vector<std::string>{project.where("FB_Motor.st", "VAR |nCount"),
                                                                 project.where("FB_Motor.st", "|nCount := nCount"),
                                                                 project.where("FB_Motor.st", "nCount := |nCount")}));
  EXPECT_EQ(project.references(count, false),
            (std::vector<std::string>{project.where("FB_Motor.st", "|nCount := nCount"),
                                      project.where("FB_Motor.st", "nCount := |nCount")}));
}

TEST(QueryReferences, GlobalQualifiedAndNotButNotTheLocalThatHidesIt) {
  const Project project(kMachine);
  const Symbol* speed = project.symbol("Main.st", "GVL.|gSpeed :=");
  ASSERT_NE(speed, nullptr);
  EXPECT_EQ(speed->owner->kind, SymbolKind::GlobalList);
  EXPECT_EQ(project.symbol("Main.st", "bStart := |gSpeed"), speed);
  EXPECT_EQ(project.symbol("GVL.st", "|gSpeed"), speed);  // the declaration itself
  // Service declares a local gSpeed: its uses are not the global's.
  const Symbol* local = project.symbol("Service.st", "|gSpeed := 2.5");
  ASSERT_NE(local, nullptr);
  EXPECT_NE(local, speed);
  EXPECT_EQ(project.references(speed),
            sorted({project.where("GVL.st", "|gSpeed"), project.where("FB_Motor.st", "nSpeed := |gSpeed"),
                    project.where("Main.st", "bStart := |gSpeed"), project.where("Main.st", "GVL.|gSpeed :="),
                    project.where("Main.st", "GVL.|gSpeed + 1")}));
  EXPECT_EQ(project.references(local), (std::vector<std::string>{project.where("Service.st", "VAR |gSpeed"),
                                                                 project.where("Service.st", "|gSpeed := 2.5")}));
  // The qualifier names the list.
  const Symbol* list = project.symbol("Main.st", "G|VL.gSpeed :=");
  ASSERT_NE(list, nullptr);
  EXPECT_EQ(list->kind, SymbolKind::GlobalList);
  EXPECT_EQ(project.references(list).size(), 2u);
}

TEST(QueryReferences, VarExternalIsTheGlobal) {
  const Project project(kMachine);
  const Symbol* mode = project.symbol("Service.st", "|gMode := E_Mode");
  ASSERT_NE(mode, nullptr);
  EXPECT_EQ(mode->owner->kind, SymbolKind::GlobalList);
  EXPECT_EQ(project.references(mode), sorted({project.where("GVL.st", "|gMode"), project.where("Main.st", "IF |gMode"),
                                              project.where("Service.st", "VAR_EXTERNAL |gMode"),
                                              project.where("Service.st", "|gMode := E_Mode")}));
}

TEST(QueryReferences, FunctionBlockInputAsNamedArgumentMemberAndCaseInsensitive) {
  const Project project(kMachine);
  const Symbol* start = project.symbol("Main.st", "fbMotor(|bStart :=");
  ASSERT_NE(start, nullptr);
  EXPECT_EQ(start->section, ast::VarSection::Input);
  EXPECT_EQ(start->owner->name, "FB_Motor");
  EXPECT_EQ(project.symbol("Main.st", "fbMotor.b|Start AND"), start);
  EXPECT_EQ(project.symbol("FB_Motor.st", "Start := B|START"), start);  // BSTART is bStart
  EXPECT_EQ(project.references(start),
            sorted({project.where("FB_Motor.st", "VAR_INPUT |bStart"), project.where("FB_Motor.st", "Start := |BSTART"),
                    project.where("FB_Motor.st", "IF |bStart"), project.where("Main.st", "fbMotor(|bStart"),
                    project.where("Main.st", "fbMotor.|bStart AND")}));
  // An output given with => and an inherited output read as a member.
  const Symbol* speed = project.symbol("Main.st", "|nSpeed => nCount");
  ASSERT_NE(speed, nullptr);
  EXPECT_EQ(speed->section, ast::VarSection::Output);
  const Symbol* busy = project.symbol("Main.st", "fbMotor.|bBusy");
  ASSERT_NE(busy, nullptr);
  EXPECT_EQ(busy->owner->name, "FB_Base");
}

TEST(QueryReferences, MethodsThisAndSuper) {
  const Project project(kMachine);
  const Symbol* start = project.symbol("Main.st", "fbMotor.|Start(");
  ASSERT_NE(start, nullptr);
  EXPECT_EQ(start->kind, SymbolKind::Method);
  // Inside the method its name is its result.
  EXPECT_EQ(project.references(start), (std::vector<std::string>{project.where("FB_Motor.st", "METHOD |Start"),
                                                                 project.where("FB_Motor.st", "|Start := BSTART"),
                                                                 project.where("Main.st", "fbMotor.|Start(")}));
  const Symbol* ramp = project.symbol("Main.st", "Start(|nRamp");
  ASSERT_NE(ramp, nullptr);
  EXPECT_EQ(ramp->owner, start);
  EXPECT_EQ(project.symbol("FB_Motor.st", "THIS^.|nSpeed"), project.symbol("Main.st", "|nSpeed => nCount"));
  const Symbol* reset = project.symbol("FB_Motor.st", "SUPER^.|Reset");
  ASSERT_NE(reset, nullptr);
  EXPECT_EQ(reset->owner->name, "FB_Base");
  EXPECT_EQ(project.symbol("FB_Motor.st", "|THIS^")->name, "FB_Motor");
  EXPECT_EQ(project.references(reset),
            (std::vector<std::string>{
                project.where("FB_Base.st", "METHOD |Reset"), project.where("FB_Base.st", "|Reset := TRUE"),
                project.where("FB_Motor.st", "SUPER^.|Reset"), project.where("Main.st", "fbMotor.|Reset")}));
}

TEST(QueryReferences, EnumValueQualifiedTypedAndBare) {
  const Project project(kMachine);
  const Symbol* run = project.symbol("Main.st", "E_Mode.|Run");
  ASSERT_NE(run, nullptr);
  EXPECT_EQ(run->kind, SymbolKind::EnumValue);
  EXPECT_EQ(project.symbol("Main.st", "E_Mode#|Run"), run);
  EXPECT_EQ(project.symbol("Main.st", "mode = |Run"), run);
  EXPECT_EQ(project.references(run),
            sorted({project.where("Types.st", "Idle, |Run"), project.where("Main.st", "E_Mode#|Run"),
                    project.where("Main.st", "E_Mode.|Run"), project.where("Main.st", "mode = |Run")}));
  // The type part of E_Mode#Run is the enumeration.
  EXPECT_EQ(project.symbol("Main.st", "E_Mo|de#Run"), project.symbol("Types.st", "TYPE |E_Mode"));
}

TEST(QueryReferences, TypeInDeclarationsExtendsAndResults) {
  const Project project(kMachine);
  const Symbol* point = project.symbol("Main.st", "ARRAY[0..3] OF |ST_Point");
  ASSERT_NE(point, nullptr);
  EXPECT_EQ(point->kind, SymbolKind::DataType);
  EXPECT_EQ(project.symbol("Scale.st", "FUNCTION Scale : ST_|Point"), point);
  EXPECT_EQ(project.symbol("Main.st", "POINTER TO ST_|Point"), point);
  // FB_Motor's input, Scale's result and input, Main's array, pointer and variable.
  EXPECT_EQ(project.references(point, false).size(), 6u);
  EXPECT_EQ(project.references(point, true).size(), 7u);
  const Symbol* base = project.symbol("FB_Motor.st", "EXTENDS |FB_Base");
  ASSERT_NE(base, nullptr);
  EXPECT_EQ(base->kind, SymbolKind::FunctionBlock);
  EXPECT_EQ(project.references(base, false),
            (std::vector<std::string>{project.where("FB_Motor.st", "EXTENDS |FB_Base")}));
  // A function used as a call, and its own name inside it (its result).
  const Symbol* scale = project.symbol("Main.st", "|Scale(p :=");
  ASSERT_NE(scale, nullptr);
  EXPECT_EQ(project.references(scale).size(), 4u);
}

TEST(QueryDefinition, FunctionArgumentsAndStructureInitialValues) {
  const Project project(kMachine);
  const Symbol* k = project.symbol("Main.st", "k| := 2.0");
  ASSERT_NE(k, nullptr);
  EXPECT_EQ(k->owner->name, "Scale");
  const Symbol* x = project.symbol("Main.st", "(|x := 1.5");
  ASSERT_NE(x, nullptr);
  EXPECT_EQ(x->owner->name, "ST_Point");
  EXPECT_EQ(project.symbol("Scale.st", "p.|x * k"), x);
  EXPECT_EQ(project.symbol("Scale.st", "Scale.|x :="), x);
  EXPECT_EQ(project.references(x).size(), 4u);  // declaration, initial value, Scale.x, p.x
}

TEST(QueryType, ExpressionsUnderTheCursor) {
  const Project project(kMachine);
  ASSERT_NE(project.type("Main.st", "fbMotor.b|Start AND"), nullptr);
  EXPECT_EQ(project.type("Main.st", "fbMotor.b|Start AND")->name, "BOOL");
  EXPECT_EQ(project.type("Main.st", "GVL.gSpeed |+ 1")->name, "INT");
  EXPECT_EQ(project.type("Main.st", "|fbMotor(")->name, "FB_Motor");
  EXPECT_EQ(project.type("Main.st", "E_Mode.R|un")->name, "E_Mode");
  EXPECT_EQ(project.type("Main.st", "p|oints[0]")->name, "ARRAY[0..3] OF ST_Point");
  EXPECT_EQ(project.type("Main.st", "points[0|] :=")->name, "ST_Point");  // the cursor on ']'
  EXPECT_EQ(project.type("Main.st", "|Scale(p :=")->name, "ST_Point");
  EXPECT_EQ(project.type("Main.st", "  |origin : ST_Point")->name, "ST_Point");
  EXPECT_EQ(project.type("Main.st", "|PROGRAM Main"), nullptr);  // a keyword is no expression
}

TEST(QueryMembers, AfterADot) {
  const Project project(kMachine);
  const Symbol* motor = project.symbol("Main.st", "fbMotor : |FB_Motor");
  ASSERT_NE(motor, nullptr);
  // Inputs, outputs, methods; inherited ones after the own; no locals (nCount).
  EXPECT_EQ(names_of(query::members_of(motor)),
            (std::vector<std::string>{"bStart", "target", "nSpeed", "Start", "bBusy", "Reset"}));
  EXPECT_EQ(names_of(query::members_of(project.type("Main.st", "|fbMotor("))), names_of(query::members_of(motor)));
  EXPECT_EQ(names_of(query::members_of(project.symbol("Types.st", "TYPE |E_Mode"))),
            (std::vector<std::string>{"Idle", "Run", "Stop"}));
  EXPECT_EQ(names_of(query::members_of(project.type("Main.st", "p|oints[0]"))), std::vector<std::string>{});
  EXPECT_EQ(names_of(query::members_of(project.type("Main.st", "points[0|] :="))),
            (std::vector<std::string>{"x", "y"}));
  EXPECT_EQ(names_of(query::members_of(project.symbol("Main.st", "G|VL.gSpeed :="))),
            (std::vector<std::string>{"gSpeed", "gMode"}));
}

TEST(QueryDefinition, GlobalScopeOperatorIlAndNestedInitialValues) {
  const Project project(
      Files{{"GVL.st", "VAR_GLOBAL nLevel : INT; END_VAR\n"},
            {"Types.st", "TYPE ST_Pair : STRUCT a : INT; b : INT; END_STRUCT END_TYPE\n"},
            {"P.st",
             "PROGRAM P\nVAR nLevel : INT; aPairs : ARRAY[0..1] OF ST_Pair := [(a := 1), 1((b := 2))]; END_VAR\n"
             "nLevel := .nLevel;\nEND_PROGRAM\n"},
            {"F.st", "FUNCTION F_Twice : INT\nVAR_INPUT n : INT; END_VAR\nLD n\nMUL 2\nST F_Twice\nEND_FUNCTION\n"},
            {"Q.st", "PROGRAM Q\nVAR r : INT; END_VAR\nLD nLevel\nF_Twice\nST r\nEND_PROGRAM\n"}});
  const Symbol* global = project.symbol("GVL.st", "|nLevel");
  ASSERT_NE(global, nullptr);
  // CODESYS .x: the global even where a local of the same name hides it.
  EXPECT_EQ(project.symbol("P.st", ".|nLevel"), global);
  EXPECT_NE(project.symbol("P.st", "|nLevel := .nLevel"), global);
  EXPECT_EQ(project.symbol("Q.st", "LD |nLevel"), global);  // an IL operand
  EXPECT_EQ(project.references(global, false),
            (std::vector<std::string>{project.where("P.st", ".|nLevel"), project.where("Q.st", "LD |nLevel")}));
  // An IL operator that calls a function, and the function's result inside it.
  const Symbol* twice = project.symbol("Q.st", "|F_Twice");
  ASSERT_NE(twice, nullptr);
  EXPECT_EQ(twice->kind, SymbolKind::Function);
  EXPECT_EQ(project.references(twice, false),
            (std::vector<std::string>{project.where("F.st", "ST |F_Twice"), project.where("Q.st", "|F_Twice")}));
  // Members named in the elements of an array's initial value.
  const Symbol* a = project.symbol("P.st", "(|a := 1)");
  ASSERT_NE(a, nullptr);
  EXPECT_EQ(a->owner->name, "ST_Pair");
  EXPECT_EQ(project.symbol("P.st", "((|b := 2))")->owner, a->owner);
}

TEST(QueryDefinition, LibraryNamesAndNamespaces) {
  const Project project(Files{{"P.st",
                               "PROGRAM P\nVAR t1 : Standard.TON; t2 : TON; END_VAR\n"
                               "t1(IN := TRUE, PT := T#1s);\nt2.IN := t1.Q;\nEND_PROGRAM\n"}});
  const Symbol* ton = project.symbol("P.st", "Standard.T|ON");
  ASSERT_NE(ton, nullptr);
  EXPECT_TRUE(ton->has(kLibrary));
  EXPECT_EQ(ton->kind, SymbolKind::FunctionBlock);
  EXPECT_EQ(project.symbol("P.st", "Stan|dard.TON"), nullptr);  // the namespace itself has no declaration
  const Symbol* in = project.symbol("P.st", "t1(|IN :=");
  ASSERT_NE(in, nullptr);
  EXPECT_EQ(in->owner, project.symbol("P.st", "t2 : |TON"));
  const auto location = query::declaration_location(project.workspace(), *in);
  EXPECT_NE(location.path.find("library"), std::string::npos);
  // A library symbol's references are searched in the stubs too: found in the project, and in
  // TON's own ST body in the library (the runner's implementation).
  std::vector<std::string> in_project;
  size_t in_library = 0;
  for (const query::Location& location : query::find_references(project.workspace(), in, false)) {
    if (location.path == "P.st") {
      in_project.push_back(project.where(location));
    } else if (location.path.find("TON.st") != std::string::npos) {
      ++in_library;
    }
  }
  EXPECT_EQ(in_project,
            (std::vector<std::string>{project.where("P.st", "t1(|IN :="), project.where("P.st", "t2.|IN :=")}));
  EXPECT_GT(in_library, 0u);
}

TEST(QueryDefinition, ConfigurationProgramWith) {
  const Project project({{"Main.st", "PROGRAM PRG_Main\nVAR_INPUT a : INT; END_VAR\nEND_PROGRAM\n"},
                         {"Config.st",
                          "CONFIGURATION C\nRESOURCE R ON PLC\nTASK T(INTERVAL := T#10ms);\n"
                          "PROGRAM Inst WITH T : PRG_Main(a := 1);\nEND_RESOURCE\nEND_CONFIGURATION\n"}},
                        project::Profile::Iec);
  const Symbol* main = project.symbol("Config.st", ": PRG_|Main");
  ASSERT_NE(main, nullptr);
  EXPECT_EQ(main->kind, SymbolKind::Program);
  const Symbol* a = project.symbol("Config.st", "(|a := 1)");
  ASSERT_NE(a, nullptr);
  EXPECT_EQ(a->owner, main);
  EXPECT_EQ(project.symbol("Config.st", "WITH |T :"), nullptr);  // a task: no symbol
  EXPECT_EQ(project.references(main, false), (std::vector<std::string>{project.where("Config.st", ": |PRG_Main")}));
}

// A TwinCAT object: the ST sits in CDATA sections inside XML. Positions in and out are offsets
// of the .TcPOU file, not of the text the parser read.
TEST(QueryDefinition, InsideATwinCatContainer) {
  const std::string pou =
      "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n"
      "<TcPlcObject Version=\"1.1.0.1\">\n"
      "  <POU Name=\"FB_Valve\" Id=\"{1}\">\n"
      "    <Declaration><![CDATA[FUNCTION_BLOCK FB_Valve\n"
      "VAR\n"
      "  bOpen : BOOL;\n"
      "END_VAR\n"
      "]]></Declaration>\n"
      "    <Implementation>\n"
      "      <ST><![CDATA[bOpen := gSpeed > 0;\n"
      "IF bOpen THEN gSpeed := 0; END_IF]]></ST>\n"
      "    </Implementation>\n"
      "  </POU>\n"
      "</TcPlcObject>\n";
  const Project project(Files{{"GVL.st", "VAR_GLOBAL gSpeed : INT; END_VAR\n"}, {"FB_Valve.TcPOU", pou}},
                        project::Profile::Twincat);
  const Symbol* open = project.symbol("FB_Valve.TcPOU", "IF b|Open");
  ASSERT_NE(open, nullptr);
  const auto location = query::definition_at(project.workspace(), project.id("FB_Valve.TcPOU"),
                                             project.at("FB_Valve.TcPOU", "IF b|Open"));
  ASSERT_TRUE(location.has_value());
  EXPECT_EQ(location->range.begin, project.at("FB_Valve.TcPOU", "  |bOpen : BOOL"));
  EXPECT_EQ(project.references(open), (std::vector<std::string>{project.where("FB_Valve.TcPOU", "  |bOpen : BOOL"),
                                                                project.where("FB_Valve.TcPOU", "|bOpen := gSpeed"),
                                                                project.where("FB_Valve.TcPOU", "IF |bOpen")}));
  const Symbol* speed = project.symbol("GVL.st", "|gSpeed");
  EXPECT_EQ(project.references(speed, false),
            (std::vector<std::string>{project.where("FB_Valve.TcPOU", "bOpen := |gSpeed"),
                                      project.where("FB_Valve.TcPOU", "THEN |gSpeed")}));
  // XML markup has no parsed text under it.
  EXPECT_EQ(project.symbol("FB_Valve.TcPOU", "<POU Na|me"), nullptr);
}

TEST(QueryDefinition, BrokenCodeStillAnswers) {
  const Project project(Files{{"GVL.st", "VAR_GLOBAL gLevel : INT; END_VAR\n"},
                              {"P.st",
                               "PROGRAM P\nVAR nLevel : INT; END_VAR\n"
                               "nLevel := ;\n"
                               "IF nLevel > THEN\n"
                               "nLevel := gLevel + ;\n"
                               "END_IF\n"
                               "END_PROGRAM\n"}});
  ASSERT_FALSE(project.workspace().model().source(project.id("P.st")).document->diagnostics().empty());
  const Symbol* level = project.symbol("P.st", "nLevel := g|Level");
  ASSERT_NE(level, nullptr);
  EXPECT_EQ(level->owner->kind, SymbolKind::GlobalList);
  const Symbol* local = project.symbol("P.st", "|nLevel := gLevel");
  ASSERT_NE(local, nullptr);
  EXPECT_EQ(local->owner->name, "P");
  EXPECT_EQ(project.references(local).size(), 4u);
  EXPECT_EQ(project.references(level, false), (std::vector<std::string>{project.where("P.st", "|gLevel +")}));
}

}  // namespace
}  // namespace rung::check
