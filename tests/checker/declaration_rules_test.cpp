// Declaration rules: POU-local types, VAR_GLOBAL in programs, which sections and qualifiers a
// declaration may have per profile, function block instances where there is no room for them,
// initial values, subranges and enumerations, and names that clash. The OpenPCS rules quote the
// manual's message numbers (003.md, S/L codes); the CODESYS ones the textbook (000a.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "checker/check.hpp"
#include "tests/support/project_findings.hpp"

namespace rung::check {
namespace {

using Found = std::vector<std::string>;
using project::Profile;

Found found(const std::vector<std::pair<std::string, std::string>>& files, Profile profile) {
  return testing::codes_at_lines(files, testing::config_for(profile));
}

Found found(const std::string& text, Profile profile) {
  return found({{"P.st", text}}, profile);
}

// --- POU-local types (OpenPCS) ---------------------------------------------------------------

TEST(DeclarationRules, LocalTypesAreFoundInsideTheirPouOnly) {
  const std::string text =
      "PROGRAM Feld\n"
      "TYPE\n"
      "  Arr5 : ARRAY[1..5] OF INT;\n"
      "  Mode : (Off, Slow, Fast);\n"
      "END_TYPE\n"
      "VAR\n"
      "  a : Arr5;\n"
      "  m : Mode := Slow;\n"
      "END_VAR\n"
      "a[1] := 2;\n"
      "m := Fast;\n"
      "END_PROGRAM\n"
      "PROGRAM Other\n"
      "VAR\n"
      "  b : Arr5;\n"
      "END_VAR\n"
      "END_PROGRAM\n";
  EXPECT_EQ(found(text, Profile::Openpcs), Found{"E002@15"});
}

TEST(DeclarationRules, LocalTypeOnlyForTheVariablesOfItsPou) {
  // S5036: other POUs cannot know the type of a parameter, global or external.
  const std::string text =
      "FUNCTION_BLOCK Fb1\n"
      "TYPE\n"
      "  Local : STRUCT m1 : BOOL; END_STRUCT;\n"
      "END_TYPE\n"
      "VAR_INPUT inVar : Local; END_VAR\n"
      "VAR_OUTPUT outVar : ARRAY[1..2] OF Local; END_VAR\n"
      "VAR ownVar : Local; END_VAR\n"
      "ownVar.m1 := inVar.m1;\n"
      "END_FUNCTION_BLOCK\n";
  EXPECT_EQ(found(text, Profile::Openpcs), (Found{"E213@5", "E213@6"}));
  EXPECT_EQ(found(text, Profile::Codesys), (Found{"E213@5", "E213@6"}));
}

// --- VAR_GLOBAL in a PROGRAM ----------------------------------------------------------------

TEST(DeclarationRules, ProgramGlobalsAreGlobalInIecAndOpenpcs) {
  const std::string text =
      "FUNCTION_BLOCK SetOutput\n"
      "VAR_EXTERNAL shared : BOOL; END_VAR\n"
      "VAR_INPUT value : BOOL; END_VAR\n"
      "shared := value;\n"
      "END_FUNCTION_BLOCK\n"
      "PROGRAM Main\n"
      "VAR_GLOBAL shared : BOOL; END_VAR\n"
      "VAR switch : SetOutput; END_VAR\n"
      "switch(value := NOT shared);\n"
      "END_PROGRAM\n";
  EXPECT_EQ(found(text, Profile::Openpcs), Found{});
  EXPECT_EQ(found(text, Profile::Iec), Found{});
  // CODESYS declares globals in global variable lists only.
  EXPECT_EQ(found(text, Profile::Codesys), Found{"E201@7"});
}

// --- Sections --------------------------------------------------------------------------------

TEST(DeclarationRules, FunctionSectionsPerProfile) {
  const std::string text =
      "VAR_GLOBAL g : INT; END_VAR\n"
      "FUNCTION Twice : INT\n"
      "VAR_INPUT x : INT; END_VAR\n"
      "VAR_OUTPUT o : INT; END_VAR\n"
      "VAR_IN_OUT io : INT; END_VAR\n"
      "VAR_EXTERNAL g : INT; END_VAR\n"
      "Twice := x * 2;\n"
      "END_FUNCTION\n";
  // S4015, S4014, S4016: an OpenPCS function has only VAR_INPUT and VAR.
  EXPECT_EQ(found(text, Profile::Openpcs), (Found{"E201@4", "E201@5", "E201@6"}));
  EXPECT_EQ(found(text, Profile::Codesys), Found{});
}

TEST(DeclarationRules, NoVarTempInAFunction) {
  // CODESYS C0174: VAR_TEMP only in programs and function blocks.
  const std::string text =
      "FUNCTION Twice : INT\nVAR_INPUT n : INT; END_VAR\nVAR_TEMP t : INT; END_VAR\nt := n * 2;\nTwice := t;\n"
      "END_FUNCTION\n"
      "FUNCTION_BLOCK Scaler\nVAR_TEMP t : INT; END_VAR\nt := 1;\nEND_FUNCTION_BLOCK\n";
  EXPECT_EQ(found(text, Profile::Codesys), Found{"E201@3"});
}

TEST(DeclarationRules, LocatedVariablesBelongToProgramsAndGlobalLists) {
  const std::string text =
      "FUNCTION_BLOCK Reader\n"
      "VAR sw AT %IX0.0 : BOOL; wildcard AT %I* : BOOL; END_VAR\n"
      "END_FUNCTION_BLOCK\n"
      "PROGRAM Main\nVAR sw AT %IX0.2 : BOOL; END_VAR\nEND_PROGRAM\n";
  // OpenPCS S4011 / C10019 and the IEC grammar: an error. CODESYS compiles it, and every
  // instance shares the address (MP300 L10832): a warning. `%I*` is completed per instance.
  EXPECT_EQ(found(text, Profile::Iec), Found{"E201@2"});
  EXPECT_EQ(found(text, Profile::Codesys), Found{"E201@2?"});
}

// --- RETAIN and CONSTANT ----------------------------------------------------------------------

TEST(DeclarationRules, RetainInAFunctionIsAWarningInCodesys) {
  const std::string text =
      "FUNCTION Twice : INT\nVAR_INPUT n : INT; END_VAR\nVAR RETAIN last : INT; END_VAR\n"
      "last := n;\nTwice := last * 2;\nEND_FUNCTION\n";
  EXPECT_EQ(found(text, Profile::Codesys), Found{"E202@3?"});  // textbook L3639: no effect
  EXPECT_EQ(found(text, Profile::Openpcs), Found{"E202@3"});   // S4019
}

TEST(DeclarationRules, RetainOnInputsAndAddresses) {
  const std::string text =
      "FUNCTION_BLOCK Keeper\nVAR_INPUT RETAIN i : INT; END_VAR\nVAR_OUTPUT RETAIN o : INT; END_VAR\n"
      "END_FUNCTION_BLOCK\n"
      "PROGRAM Main\nVAR RETAIN counter AT %MW10 : INT; total : DINT; END_VAR\nEND_PROGRAM\n";
  // OpenPCS keeps VAR, VAR_OUTPUT and VAR_GLOBAL only (S4019); no located variable is retained
  // in OpenPCS (L10033) or CODESYS (MP300 L10830), while the IEC grammar allows both.
  EXPECT_EQ(found(text, Profile::Openpcs), (Found{"E202@2", "E202@6"}));
  EXPECT_EQ(found(text, Profile::Codesys), Found{"E202@6"});
  EXPECT_EQ(found(text, Profile::Iec), Found{});
}

TEST(DeclarationRules, ConstantOnlyWhereTheSectionMayHaveIt) {
  const std::string text =
      "VAR_GLOBAL CONSTANT ceiling : INT := 10; END_VAR\n"
      "FUNCTION_BLOCK Scaler\n"
      "VAR_INPUT CONSTANT factor : INT; END_VAR\n"
      "VAR_EXTERNAL CONSTANT ceiling : INT; END_VAR\n"
      "VAR RETAIN CONSTANT both : INT := 1; END_VAR\n"
      "VAR CONSTANT offset : INT := 1; END_VAR\n"
      "END_FUNCTION_BLOCK\n";
  EXPECT_EQ(found(text, Profile::Openpcs), (Found{"E215@3", "E215@4", "E215@5"}));  // S4018, S4008
  EXPECT_EQ(found(text, Profile::Iec), (Found{"E215@3", "E215@5"}));                // VAR_EXTERNAL CONSTANT is IEC
  EXPECT_EQ(found(text, Profile::Codesys), Found{});                                // VAR_INPUT CONSTANT is CODESYS
}

// --- Function block instances ------------------------------------------------------------------

TEST(DeclarationRules, InstancesWhereAProfileHasNoRoomForThem) {
  const std::string text =
      "TYPE WithTimer : STRUCT count : INT; t : TON; END_STRUCT; END_TYPE\n"
      "FUNCTION Delay : BOOL\nVAR_INPUT go : BOOL; END_VAR\nVAR t : TON; END_VAR\nDelay := go;\nEND_FUNCTION\n"
      "FUNCTION MakeTimer : TON\nVAR_INPUT x : INT; END_VAR\nEND_FUNCTION\n"
      "PROGRAM Main\n"
      "VAR timers : ARRAY[1..4] OF TON; single : TON; END_VAR\n"
      "VAR CONSTANT fixed : TON; END_VAR\n"
      "VAR RETAIN kept : TON; END_VAR\n"
      "single(IN := TRUE, PT := T#1s);\n"
      "END_PROGRAM\n";
  // S5004 (struct member, function), S5005 (result), S5011 (array), S5003 (CONSTANT), S5042 (RETAIN).
  EXPECT_EQ(found(text, Profile::Openpcs), (Found{"E212@1", "E212@4", "E212@7", "E212@11", "E215@12", "E202@13"}));
  EXPECT_EQ(found(text, Profile::Iec), Found{"E212@4"});  // a function keeps no state
  EXPECT_EQ(found(text, Profile::Codesys), Found{});
}

// --- Functions, EN/ENO, generic types ------------------------------------------------------------

TEST(DeclarationRules, OpenpcsFunctionsTakeAnInputAndReturnBoolByDefault) {
  const std::string text =
      "FUNCTION NoInput : INT\nNoInput := 1;\nEND_FUNCTION\n"
      "FUNCTION IsBig\nVAR_INPUT x : INT; END_VAR\nIsBig := x > 100;\nEND_FUNCTION\n"
      "PROGRAM Main\nVAR flag : BOOL; n : INT; END_VAR\nflag := IsBig(200);\nn := IsBig(200);\nEND_PROGRAM\n";
  EXPECT_EQ(found(text, Profile::Openpcs), (Found{"E214@1", "E101@11"}));  // S4036; BOOL (L8698)
}

TEST(DeclarationRules, EnAndEnoDeclarations) {
  const std::string text =
      "FUNCTION_BLOCK Good\nVAR_INPUT EN : BOOL; END_VAR\nVAR_OUTPUT ENO : BOOL; END_VAR\nENO := EN;\n"
      "END_FUNCTION_BLOCK\n"
      "FUNCTION_BLOCK Bad\nVAR EN : INT; END_VAR\nVAR_OUTPUT RETAIN ENO : BOOL; END_VAR\nEND_FUNCTION_BLOCK\n"
      "FUNCTION_BLOCK OnlyEno\nVAR_OUTPUT ENO : BOOL; END_VAR\nENO := TRUE;\nEND_FUNCTION_BLOCK\n";
  // S1031 (EN outside VAR_INPUT, not BOOL), S3041 (RETAIN), S3042 (ENO without EN).
  EXPECT_EQ(found(text, Profile::Openpcs), (Found{"E201@7", "E101@7", "E202@8", "E216@11"}));
  EXPECT_EQ(found(text, Profile::Codesys), Found{});
}

TEST(DeclarationRules, GenericTypesOnlyForStandardFunctions) {
  const std::string text = "FUNCTION Fun : INT\nVAR_INPUT InVar : ANY_INT; END_VAR\nFun := 1;\nEND_FUNCTION\n";
  EXPECT_EQ(found(text, Profile::Openpcs), Found{"E004@2"});  // S5035
  EXPECT_EQ(found(text, Profile::Codesys), Found{});
}

// --- Initial values ----------------------------------------------------------------------------

TEST(DeclarationRules, InitialValueShapes) {
  const std::string text =
      "TYPE Three : STRUCT m1 : INT; m2 : INT; m3 : BOOL; END_STRUCT; END_TYPE\n"
      "PROGRAM Main\nVAR\n"
      "  ok1 : ARRAY[1..5] OF INT := [1, 2, 3, 4, 5];\n"
      "  ok2 : ARRAY[1..6] OF INT := [2(0), 4(1)];\n"
      "  ok3 : Three := (m1 := 1, m3 := TRUE);\n"
      "  a : INT := (m1 := 5, m2 := TRUE);\n"
      "  b : INT := [4];\n"
      "  c : ARRAY[1..5] OF INT := [1, 2, 3, 4, 5, 6];\n"
      "  d : ARRAY[1..3] OF INT := [3(7), 1];\n"
      "  e : Three := (m1 := 1, m1 := 2, m4 := FALSE);\n"
      "  f : ARRAY[1..2] OF Three := [(m1 := 70000), (m3 := 5)];\n"
      "END_VAR\nEND_PROGRAM\n";
  // S5017, S5018, S5020, S5023; values inside initializers are checked against their member.
  EXPECT_EQ(found(text, Profile::Openpcs),
            (Found{"E101@7", "E101@8", "E102@9", "E102@10", "E303@11", "E005@11", "E102@12", "E101@12"}));
}

TEST(DeclarationRules, StructMemberInitialisedTwice) {
  const std::string text =
      "TYPE\n"
      "  ByMember : STRUCT m1 : INT := 5; END_STRUCT;\n"
      "  Both : STRUCT\n    m1 : INT := 5;\n    m2 : BOOL;\n  END_STRUCT := (m1 := 4, m2 := TRUE);\n"
      "END_TYPE\n";
  EXPECT_EQ(found(text, Profile::Openpcs), Found{"E303@6"});  // S4033
}

TEST(DeclarationRules, WhereInitialValuesAreNotAllowed) {
  const std::string text =
      "VAR_GLOBAL a : INT := 5; b : INT; END_VAR\n"
      "PROGRAM Main\n"
      "VAR_EXTERNAL a : INT; b : INT := 5; END_VAR\n"
      "VAR lamp AT %QX0.1 : BOOL := TRUE; END_VAR\n"
      "b := a;\nEND_PROGRAM\n";
  EXPECT_EQ(found(text, Profile::Openpcs), (Found{"E509@3", "E509@4"}));  // S4024, L10031
  EXPECT_EQ(found(text, Profile::Iec), Found{"E509@3"});
  EXPECT_EQ(found(text, Profile::Codesys), Found{});  // the MP300 manual shows VAR_EXTERNAL x : INT := 12
}

TEST(DeclarationRules, OpenpcsInitialValuesAreLiteralsOrEnumValues) {
  const std::string text =
      "TYPE Colours : (red, green); END_TYPE\n"
      "PROGRAM Main\n"
      "VAR CONSTANT maxCount : INT := 10; END_VAR\n"
      "VAR\n"
      "  base : INT := -3;\n"
      "  fromVariable : INT := base;\n"
      "  fromConstant : INT := maxCount;\n"
      "  colour : Colours := green;\n"
      "  wrong : Colours := Colours;\n"
      "END_VAR\nEND_PROGRAM\n";
  // S5043; S3012 for the type name.
  EXPECT_EQ(found(text, Profile::Openpcs), (Found{"E701@6", "E701@7", "E004@9"}));
  EXPECT_EQ(found(text, Profile::Codesys), Found{"E004@9"});
}

// --- Subranges, enumerations, strings ----------------------------------------------------------

TEST(DeclarationRules, SubrangeBoundsFitTheirBaseType) {
  const std::string text =
      "TYPE Small : SINT(-5..200); END_TYPE\n"
      "PROGRAM Main\nVAR\n"
      "  ok : INT(1..7) := 3;\n"
      "  range1 : UINT(-1..1000);\n"
      "  range2 : INT(-1..36000);\n"
      "  range3 : INT(10..1);\n"
      "END_VAR\nEND_PROGRAM\n";
  EXPECT_EQ(found(text, Profile::Openpcs), (Found{"E102@1", "E102@5", "E102@6", "E109@7"}));  // S3036, S3037
}

TEST(DeclarationRules, EnumeratorsFitTheBaseType) {
  const std::string text = "TYPE Big : (yellow, green := 16#8000); Fits : (a, b := 16#8000) DINT; END_TYPE\n";
  EXPECT_EQ(found(text, Profile::Codesys), Found{"E102@1"});
}

TEST(DeclarationRules, OpenpcsStringLengths) {
  const std::string text =
      "PROGRAM Main\nVAR\n  s : STRING;\n  long : STRING(254);\nEND_VAR\n"
      "s := '123456789012345678901234567890123';\nEND_PROGRAM\n";
  // STRING holds 32 characters, STRING(n) at most 253 (L4363-4389, C10049).
  EXPECT_EQ(found(text, Profile::Openpcs), (Found{"E106@4?", "E106@6?"}));
  EXPECT_EQ(found(text, Profile::Codesys), Found{});
}

// --- Names ---------------------------------------------------------------------------------------

TEST(DeclarationRules, PouAndTypeNamesAreUniqueInAFileAndAProject) {
  const std::string one = "TYPE Motor : STRUCT speed : INT; END_STRUCT END_TYPE\nPROGRAM Motor\nEND_PROGRAM\n";
  EXPECT_EQ(found(one, Profile::Codesys), Found{"E003@2"});
  const std::string two = "FUNCTION Twice : INT\nVAR_INPUT x : INT; END_VAR\nTwice := 2 * x;\nEND_FUNCTION\n";
  EXPECT_EQ(found({{"A.st", two}, {"B.st", two}}, Profile::Codesys), Found{"E003@1"});
}

TEST(DeclarationRules, DerivedBlockCannotRedeclareAnInheritedVariable) {
  const std::string text =
      "FUNCTION_BLOCK fbA\nVAR_INPUT x : INT; END_VAR\nEND_FUNCTION_BLOCK\n"
      "FUNCTION_BLOCK fbB EXTENDS fbA\nVAR_INPUT ivar : INT; END_VAR\nVAR x : INT; END_VAR\nEND_FUNCTION_BLOCK\n";
  EXPECT_EQ(found(text, Profile::Codesys), Found{"E003@6"});
}

TEST(DeclarationRules, EnumeratorsOfOnePouDiffer) {
  const std::string text =
      "PROGRAM P\nVAR\n  signal : (red, yellow, green);\n  colour : (blue, white, red);\n  a, b : (on, off);\n"
      "END_VAR\nEND_PROGRAM\n";
  EXPECT_EQ(found(text, Profile::Codesys), Found{"E003@4"});
}

TEST(DeclarationRules, OpenpcsHasOneNamespaceForPousTypesAndVariables) {
  const std::string text =
      "VAR_GLOBAL level : INT; END_VAR\n"
      "FUNCTION Power : REAL\nVAR_INPUT x : REAL; END_VAR\nPower := x * x;\nEND_FUNCTION\n"
      "PROGRAM Main\nVAR\n  Power : REAL;\n  level : INT;\n  energy : REAL;\nEND_VAR\nEND_PROGRAM\n";
  // S3046 and the linker's L10001; CODESYS lets locals hide both.
  EXPECT_EQ(found(text, Profile::Openpcs), (Found{"E004@8", "E003@9"}));
  EXPECT_EQ(found(text, Profile::Codesys), Found{});
}

}  // namespace
}  // namespace rung::check
