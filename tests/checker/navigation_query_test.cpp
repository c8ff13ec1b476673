// The navigation questions the language server asks beyond definition and references
// (checker/query/implementations, highlights, targets): go to implementation, which members keep
// one name through inheritance, read and write highlights, go to declaration, go to type
// definition.
#include <gtest/gtest.h>

#include "checker/query/definition.hpp"
#include "checker/query/highlights.hpp"
#include "checker/query/implementations.hpp"
#include "checker/query/targets.hpp"
#include "tests/support/marked_project.hpp"

namespace rung::check {
namespace {

using testing::MarkedProject;

// "Owner.Name" of each symbol (just "Name" at the top level).
std::vector<std::string> qualified(const std::vector<const Symbol*>& symbols) {
  std::vector<std::string> names;
  for (const Symbol* symbol : symbols) {
    names.push_back(symbol->owner ? std::string(symbol->owner->name) + "." + std::string(symbol->name)
                                  : std::string(symbol->name));
  }
  return names;
}

const MarkedProject::Files kDrives = {
    {"Interfaces.st",
     "INTERFACE I_Motor\n"
     "METHOD Start : BOOL\n"
     "END_METHOD\n"
     "PROPERTY Speed : INT\n"
     "END_PROPERTY\n"
     "END_INTERFACE\n"
     "INTERFACE I_Special EXTENDS I_Motor\n"
     "END_INTERFACE\n"},
    {"Blocks.st",
     "FUNCTION_BLOCK ABSTRACT FB_Base\n"
     "METHOD ABSTRACT Start : BOOL\n"
     "END_METHOD\n"
     "END_FUNCTION_BLOCK\n"
     "FUNCTION_BLOCK FB_Motor EXTENDS FB_Base IMPLEMENTS I_Motor\n"
     "VAR nSpeed : INT; END_VAR\n"
     "METHOD Start : BOOL\n"
     "Start := TRUE;\n"
     "END_METHOD\n"
     "PROPERTY Speed : INT\n"
     "GET\n"
     "Speed := nSpeed;\n"
     "END_GET\n"
     "END_PROPERTY\n"
     "END_FUNCTION_BLOCK\n"
     "FUNCTION_BLOCK FB_Fast EXTENDS FB_Motor\n"
     "METHOD Start : BOOL\n"
     "Start := SUPER^.Start();\n"
     "END_METHOD\n"
     "END_FUNCTION_BLOCK\n"},
    {"Special.st",
     "FUNCTION_BLOCK FB_Special IMPLEMENTS I_Special\n"
     "METHOD Start : BOOL\n"
     "END_METHOD\n"
     "PROPERTY Speed : INT\n"
     "END_PROPERTY\n"
     "END_FUNCTION_BLOCK\n"
     "FUNCTION_BLOCK FB_Other\n"  // a Start of its own, related to nothing
     "METHOD Start : BOOL\n"
     "END_METHOD\n"
     "END_FUNCTION_BLOCK\n"},
    {"Main.st",
     "PROGRAM Main\n"
     "VAR itf : I_Motor; fb : FB_Fast; END_VAR\n"
     "itf := fb;\n"
     "itf.Start();\n"
     "END_PROGRAM\n"},
};

TEST(QueryImplementations, InterfaceListsEveryImplementingBlock) {
  const MarkedProject project(kDrives);
  const Symbol* motor =
      query::symbol_at(project.workspace(), project.id("Main.st"), project.at("Main.st", "itf : I_|Motor"));
  ASSERT_NE(motor, nullptr);
  // Directly, by extending a block that implements it, and through an interface that extends it.
  EXPECT_EQ(qualified(query::implementations_of(project.model(), *motor)),
            (std::vector<std::string>{"FB_Motor", "FB_Fast", "FB_Special"}));
  const Symbol* special = project.model().find_global("FB_Special");
  const Symbol* other = project.model().find_global("FB_Other");
  EXPECT_TRUE(query::implements(*special, *motor));
  EXPECT_FALSE(query::implements(*other, *motor));
  EXPECT_FALSE(query::implements(*motor, *motor));  // an interface implements nothing
}

TEST(QueryImplementations, BlockListsItselfAndWhatExtendsIt) {
  const MarkedProject project(kDrives);
  const Symbol* base = project.model().find_global("FB_Base");
  EXPECT_EQ(qualified(query::implementations_of(project.model(), *base)),
            (std::vector<std::string>{"FB_Base", "FB_Motor", "FB_Fast"}));
  EXPECT_EQ(qualified(query::derived_blocks(project.model(), *project.model().find_global("FB_Motor"))),
            std::vector<std::string>{"FB_Fast"});
  EXPECT_EQ(qualified(query::derived_blocks(project.model(), *project.model().find_global("I_Motor"))),
            std::vector<std::string>{"I_Special"});
}

TEST(QueryImplementations, MethodsAndPropertiesOfInterfacesAndBases) {
  const MarkedProject project(kDrives);
  // A call through the interface: every implementation of the interface's method.
  const Symbol* start =
      query::symbol_at(project.workspace(), project.id("Main.st"), project.at("Main.st", "itf.|Start()"));
  ASSERT_NE(start, nullptr);
  EXPECT_EQ(start->owner->name, "I_Motor");
  EXPECT_EQ(qualified(query::implementations_of(project.model(), *start)),
            (std::vector<std::string>{"FB_Motor.Start", "FB_Fast.Start", "FB_Special.Start"}));
  // An abstract method has no body of its own: only its overrides.
  const Symbol* abstract = project.model().find_member(project.model().find_global("FB_Base"), "Start");
  EXPECT_EQ(qualified(query::implementations_of(project.model(), *abstract)),
            (std::vector<std::string>{"FB_Motor.Start", "FB_Fast.Start"}));
  const Symbol* speed = project.model().find_member(project.model().find_global("I_Motor"), "Speed");
  EXPECT_EQ(qualified(query::implementations_of(project.model(), *speed)),
            (std::vector<std::string>{"FB_Motor.Speed", "FB_Special.Speed"}));
  // A variable has no implementations.
  const Symbol* variable = project.model().find_member(project.model().find_global("FB_Motor"), "nSpeed");
  EXPECT_TRUE(query::implementations_of(project.model(), *variable).empty());
}

TEST(QueryImplementations, MemberFamilyKeepsOneNameAcrossTheHierarchy) {
  const MarkedProject project(kDrives);
  const Symbol* fast = project.model().find_global("FB_Fast");
  const Symbol* fast_start = fast->own_member("Start");
  ASSERT_NE(fast_start, nullptr);
  std::vector<std::string> family = qualified(query::member_family(project.model(), *fast_start));
  std::sort(family.begin(), family.end());
  // FB_Special.Start implements I_Motor.Start too (through I_Special); FB_Other.Start is unrelated.
  EXPECT_EQ(family, (std::vector<std::string>{"FB_Base.Start", "FB_Fast.Start", "FB_Motor.Start", "FB_Special.Start",
                                              "I_Motor.Start"}));
  EXPECT_EQ(
      qualified(query::member_family(project.model(), *project.model().find_global("FB_Other")->own_member("Start"))),
      std::vector<std::string>{"FB_Other.Start"});
  const Symbol* variable = project.model().find_member(project.model().find_global("FB_Motor"), "nSpeed");
  EXPECT_EQ(query::member_family(project.model(), *variable), std::vector<const Symbol*>{variable});
}

TEST(QueryImplementations, CyclicExtendsEnds) {
  const MarkedProject project(
      MarkedProject::Files{{"Cycle.st",
                            "FUNCTION_BLOCK FB_A EXTENDS FB_B\nMETHOD M : BOOL\nEND_METHOD\nEND_FUNCTION_BLOCK\n"
                            "FUNCTION_BLOCK FB_B EXTENDS FB_A\nMETHOD M : BOOL\nEND_METHOD\nEND_FUNCTION_BLOCK\n"}});
  const Symbol* a = project.model().find_global("FB_A");
  ASSERT_NE(a, nullptr);
  EXPECT_LE(query::implementations_of(project.model(), *a).size(), 2u);
  EXPECT_LE(query::member_family(project.model(), *a->own_member("M")).size(), 2u);
}

// "text@offset:kind" of each highlight, kind D(eclaration), R(ead), W(rite).
std::vector<std::string> highlights(const MarkedProject& project, const std::string& path, const std::string& marked) {
  const Symbol* symbol = query::symbol_at(project.workspace(), project.id(path), project.at(path, marked));
  EXPECT_NE(symbol, nullptr) << marked;
  std::vector<std::string> out;
  for (const query::Highlight& highlight : query::highlights_in(project.workspace(), symbol, project.id(path))) {
    const char kind = highlight.access == query::Access::Declaration ? 'D'
                      : highlight.access == query::Access::Write     ? 'W'
                                                                     : 'R';
    out.push_back(MarkedProject::where(highlight.location) + ":" + kind);
  }
  return out;
}

const MarkedProject::Files kPlant = {
    {"GVL.st", "VAR_GLOBAL gLevel : INT; END_VAR\n"},
    {"Types.st", "TYPE ST_Pump : STRUCT bOn : BOOL; nRpm : INT; END_STRUCT END_TYPE\n"},
    {"Plant.st",
     "PROGRAM Plant\n"
     "VAR_EXTERNAL gLevel : INT; END_VAR\n"
     "VAR\n"
     "  nLevel : INT := 3;\n"
     "  aLevels : ARRAY[0..9] OF INT;\n"
     "  i : INT;\n"
     "  pump : ST_Pump;\n"
     "  pPump : POINTER TO ST_Pump;\n"
     "  aPumps : ARRAY[0..1] OF ST_Pump;\n"
     "  tDelay : TON;\n"
     "  bDone : BOOL;\n"
     "END_VAR\n"
     "nLevel := gLevel + nLevel;\n"
     "FOR i := 0 TO 9 DO aLevels[i] := nLevel; END_FOR\n"
     "tDelay(IN := nLevel > 2, PT := T#1s, Q => bDone);\n"
     "pump.nRpm := nLevel;\n"
     "gLevel := tDelay.ET = T#0s;\n"
     "bDone := aPumps[0].bOn AND pPump^.bOn;\n"
     "GVL.gLevel := 0;\n"
     "END_PROGRAM\n"},
};

TEST(QueryHighlights, ReadsWritesAndTheDeclaration) {
  const MarkedProject project(kPlant);
  EXPECT_EQ(
      highlights(project, "Plant.st", "|nLevel := gLevel"),
      (std::vector<std::string>{
          project.where("Plant.st", "  |nLevel : INT") + ":D", project.where("Plant.st", "|nLevel := gLevel") + ":W",
          project.where("Plant.st", "gLevel + |nLevel") + ":R", project.where("Plant.st", ":= |nLevel; END_FOR") + ":R",
          project.where("Plant.st", "IN := |nLevel") + ":R",
          project.where("Plant.st", "pump.nRpm := |nLevel") + ":R"}));
  // A FOR variable is written (and read by the index); an element write writes the array.
  EXPECT_EQ(highlights(project, "Plant.st", "FOR |i"),
            (std::vector<std::string>{project.where("Plant.st", "  |i : INT") + ":D",
                                      project.where("Plant.st", "FOR |i") + ":W",
                                      project.where("Plant.st", "aLevels[|i]") + ":R"}));
  EXPECT_EQ(highlights(project, "Plant.st", "|aLevels[i]"),
            (std::vector<std::string>{project.where("Plant.st", "  |aLevels :") + ":D",
                                      project.where("Plant.st", "|aLevels[i]") + ":W"}));
  // An output bound with => writes its target; the output itself is read.
  EXPECT_EQ(highlights(project, "Plant.st", "Q => |bDone"),
            (std::vector<std::string>{project.where("Plant.st", "  |bDone : BOOL") + ":D",
                                      project.where("Plant.st", "Q => |bDone") + ":W",
                                      project.where("Plant.st", "|bDone := aPumps") + ":W"}));
}

TEST(QueryHighlights, ParametersMembersAndGlobals) {
  const MarkedProject project(kPlant);
  // An input given in a call is written; the library declares it (not in this file).
  EXPECT_EQ(highlights(project, "Plant.st", "(|IN :="),
            (std::vector<std::string>{project.where("Plant.st", "(|IN :=") + ":W"}));
  EXPECT_EQ(highlights(project, "Plant.st", "|Q => bDone"),
            (std::vector<std::string>{project.where("Plant.st", "|Q => bDone") + ":R"}));
  // The member written through pump.nRpm, read through a pointer and an array element.
  EXPECT_EQ(highlights(project, "Plant.st", "pump.|nRpm"),
            (std::vector<std::string>{project.where("Plant.st", "pump.|nRpm") + ":W"}));
  EXPECT_EQ(highlights(project, "Plant.st", "aPumps[0].|bOn"),
            (std::vector<std::string>{project.where("Plant.st", "aPumps[0].|bOn") + ":R",
                                      project.where("Plant.st", "pPump^.|bOn") + ":R"}));
  // The global through its VAR_EXTERNAL: the VAR_EXTERNAL is a declaration.
  EXPECT_EQ(highlights(project, "Plant.st", "|gLevel := tDelay"),
            (std::vector<std::string>{project.where("Plant.st", "VAR_EXTERNAL |gLevel") + ":D",
                                      project.where("Plant.st", ":= |gLevel + nLevel") + ":R",
                                      project.where("Plant.st", "|gLevel := tDelay") + ":W",
                                      project.where("Plant.st", "GVL.|gLevel := 0") + ":W"}));
  // The list before the '.' is only named, not written.
  EXPECT_EQ(highlights(project, "Plant.st", "|GVL.gLevel"),
            (std::vector<std::string>{project.where("Plant.st", "|GVL.gLevel") + ":R"}));
}

TEST(QueryTargets, DeclarationPrefersTheVarExternal) {
  const MarkedProject project(kPlant);
  const uint32_t use = project.at("Plant.st", "|gLevel := tDelay");
  const auto definition = query::definition_at(project.workspace(), project.id("Plant.st"), use);
  ASSERT_TRUE(definition.has_value());
  EXPECT_EQ(MarkedProject::where(*definition), project.where("GVL.st", "VAR_GLOBAL |gLevel"));
  const auto declaration = query::declaration_at(project.workspace(), project.id("Plant.st"), use);
  ASSERT_TRUE(declaration.has_value());
  EXPECT_EQ(MarkedProject::where(*declaration), project.where("Plant.st", "VAR_EXTERNAL |gLevel"));
  // Everything else: the same as definition.
  const uint32_t local = project.at("Plant.st", "gLevel + |nLevel");
  EXPECT_EQ(MarkedProject::where(*query::declaration_at(project.workspace(), project.id("Plant.st"), local)),
            project.where("Plant.st", "  |nLevel : INT"));
  EXPECT_FALSE(
      query::declaration_at(project.workspace(), project.id("Plant.st"), project.at("Plant.st", "|END_VAR\nnLevel")));
}

TEST(QueryTargets, TypeDefinitionOfVariablesMembersAndExpressions) {
  const MarkedProject project(kPlant);
  auto type_name = [&](const std::string& marked) -> std::string {
    const Symbol* type =
        query::type_definition_at(project.workspace(), project.id("Plant.st"), project.at("Plant.st", marked));
    return type ? std::string(type->name) : "-";
  };
  EXPECT_EQ(type_name("|pump.nRpm"), "ST_Pump");
  EXPECT_EQ(type_name("  |pPump : POINTER"), "ST_Pump");  // through POINTER TO
  EXPECT_EQ(type_name("|aPumps[0]"), "ST_Pump");          // through ARRAY OF
  EXPECT_EQ(type_name("|tDelay(IN"), "TON");              // a library block
  EXPECT_EQ(type_name("pump : ST_|Pump"), "ST_Pump");     // a type name is its own type
  EXPECT_EQ(type_name("|nLevel := gLevel"), "-");         // elementary
  EXPECT_EQ(type_name("tDelay.|ET"), "-");
  EXPECT_EQ(type_name("|FOR i"), "-");
}

}  // namespace
}  // namespace rung::check
