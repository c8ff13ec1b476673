// Name resolution beyond "declared or not": {attribute 'qualified_only'} lists and enumerations
// (E006), enum values two enumerations define (E007), the global scope operator `.x`, obsolete
// types in declarations (E601), CONSTANT globals written through VAR_EXTERNAL (E401) and members
// of values that have none (E005). Sources: MP300 manual (002.md facts 15-17, 29), OpenPCS
// manual (003.md facts 46, 68).
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
using Files = std::vector<std::pair<std::string, std::string>>;
using project::Profile;

using testing::Finding;

std::vector<Finding> findings(const Files& files, Profile profile) {
  return testing::project_findings(files, testing::config_for(profile));
}

Found found(const Files& files, Profile profile = Profile::Codesys) {
  Found result;
  for (const Finding& finding : findings(files, profile)) result.push_back(finding.at);
  return result;
}

Found found(const std::string& text, Profile profile = Profile::Codesys) {
  return found({{"P.st", text}}, profile);
}

// --- qualified_only (E006) ---------------------------------------------------------------------

const std::string kQualifiedList =
    "{attribute 'qualified_only'}\n"
    "VAR_GLOBAL\n"
    "  iVar : INT;\n"
    "END_VAR\n";

TEST(NameRules, QualifiedOnlyListVariableNeedsItsListName) {
  const Files files = {{"GVL.st", kQualifiedList},
                       {"P.st",
                        "PROGRAM P\n"
                        "VAR n : INT; END_VAR\n"
                        "GVL.iVar := 5;\n"
                        "iVar := 5;\n"
                        "n := iVar + GVL.iVar;\n"
                        "END_PROGRAM\n"}};
  EXPECT_EQ(found(files), (Found{"E006@4", "E006@5"}));
  const auto all = findings(files, Profile::Codesys);
  ASSERT_FALSE(all.empty());
  EXPECT_EQ(all[0].help, "write GVL.iVar");
  EXPECT_NE(all[0].message.find("qualified_only"), std::string::npos);
}

TEST(NameRules, ListOfAFileNameThatIsNoIdentifierIsCalledGvl) {
  // 057_example.st cannot be written as a qualifier: CODESYS's default list name stands in.
  EXPECT_EQ(found({{"057_example.st", kQualifiedList + "PROGRAM P\nGVL.iVar := 1;\niVar := 2;\nEND_PROGRAM\n"}}),
            (Found{"E006@7"}));
}

TEST(NameRules, UndeclaredNameNextToQualifiedOnlyListIsStillE001) {
  EXPECT_EQ(found({{"GVL.st", kQualifiedList}, {"P.st", "PROGRAM P\niVra := 5;\nEND_PROGRAM\n"}}), (Found{"E001@2"}));
}

TEST(NameRules, QualifiedOnlyEnumValueNeedsItsTypeName) {
  const std::string text =
      "{attribute 'qualified_only'}\n"
      "TYPE E_Mode : (Off, Auto); END_TYPE\n"
      "PROGRAM P\n"
      "VAR m : E_Mode; n : INT; END_VAR\n"
      "m := E_Mode.Auto;\n"
      "m := Auto;\n"
      "n := Off;\n"
      "END_PROGRAM\n";
  EXPECT_EQ(found(text), (Found{"E006@6", "E006@7"}));
  const auto all = findings({{"P.st", text}}, Profile::Codesys);
  ASSERT_EQ(all.size(), 2u);
  EXPECT_EQ(all[0].help, "write E_Mode.Auto");
}

// --- ambiguous enum values (E007) ---------------------------------------------------------------

const std::string kTwoColorEnums =
    "TYPE COLORS_1 : (red, blue); END_TYPE\n"
    "TYPE COLORS_2 : (green, blue, yellow); END_TYPE\n";

TEST(NameRules, EnumValueOfTwoEnumerationsMustBeQualifiedInCodesys) {
  // MP300 L14551-14561: even assigned to a COLORS_1 variable a bare blue is an error.
  const std::string text = kTwoColorEnums +
                           "PROGRAM P\n"
                           "VAR c1 : COLORS_1; c2 : COLORS_2; i : INT; END_VAR\n"
                           "c1 := COLORS_1.blue;\n"
                           "c2 := colors_2.blue;\n"
                           "c1 := blue;\n"
                           "i := blue + 1;\n"
                           "c1 := red;\n"
                           "END_PROGRAM\n";
  EXPECT_EQ(found(text), (Found{"E007@7", "E007@8"}));
  const auto all = findings({{"P.st", text}}, Profile::Codesys);
  ASSERT_FALSE(all.empty());
  EXPECT_NE(all[0].message.find("COLORS_1"), std::string::npos);
  EXPECT_NE(all[0].message.find("COLORS_2"), std::string::npos);
}

TEST(NameRules, IecEnumValueIsTypedByTheAssignedVariable) {
  // IEC (MatIEC's candidate types): the variable's enum decides; without an enum context the
  // name stays ambiguous.
  const std::string text = kTwoColorEnums +
                           "PROGRAM P\n"
                           "VAR c1 : COLORS_1; c2 : COLORS_2; i : INT; END_VAR\n"
                           "c1 := blue;\n"
                           "c2 := blue;\n"
                           "IF blue = c1 THEN c1 := red; END_IF;\n"
                           "END_PROGRAM\n";
  EXPECT_EQ(found(text, Profile::Iec), (Found{"E007@7"}));
}

// Found on IronPLC's and Beremiz's test files: an enumeration's default names its own value, and a
// type declared twice (E003) does not make its values ambiguous.
TEST(NameRules, EnumDefaultNamesItsOwnValueAndDuplicateTypesAreNoAmbiguity) {
  EXPECT_EQ(found(kTwoColorEnums + "TYPE COLORS_3 : (blue, red) := blue; END_TYPE\n"), Found{});
  EXPECT_EQ(found("TYPE L : (INFO, WARN); END_TYPE\nTYPE L : (INFO, WARN); END_TYPE\n"
                  "PROGRAM P\nVAR x : L := INFO; END_VAR\nEND_PROGRAM\n"),
            Found{"E003@2"});
}

TEST(NameRules, LocalVariableHidesEnumValuesOfTheSameName) {
  EXPECT_EQ(found(kTwoColorEnums + "PROGRAM P\nVAR blue : INT; END_VAR\nblue := 1;\nEND_PROGRAM\n"), Found{});
}

TEST(NameRules, ImplicitEnumerationValuesAreNamesOfTheirPou) {
  // TwinCAT/CODESYS: `eState : (WAITING, RUNNING);` declares the values where the variable is
  // declared; the block's methods see them, and they have the variable's type.
  const std::string text =
      "FUNCTION_BLOCK FB_Machine\n"                             // 1
      "VAR\n"                                                   // 2
      "  eState : (WAITING, RUNNING := 5, DONE) := WAITING;\n"  // 3
      "  eOther, eCopy : (IDLE, BUSY);\n"                       // 4
      "  n : INT;\n"                                            // 5
      "END_VAR\n"                                               // 6
      "CASE eState OF\n"                                        // 7
      "  WAITING: eState := RUNNING;\n"                         // 8
      "  RUNNING, DONE: eState := WAITING;\n"                   // 9
      "END_CASE\n"                                              // 10
      "eOther := BUSY;\n"                                       // 11
      "eCopy := IDLE;\n"                                        // 12
      "METHOD Start : BOOL\n"                                   // 13
      "Start := eState = WAITING;\n"                            // 14
      "eState := RUNNING;\n"                                    // 15
      "END_METHOD\n"                                            // 16
      "END_FUNCTION_BLOCK\n"                                    // 17
      "PROGRAM P\n"                                             // 18
      "VAR b : BOOL; END_VAR\n"                                 // 19
      "b := WAITING = RUNNING;\n"                               // 20
      "END_PROGRAM\n";
  EXPECT_EQ(found(text), (Found{"E001@20", "E001@20"}));
}

TEST(NameRules, SystemNamespaceOfTheCompilers) {
  // CODESYS V3 and TwinCAT 3 provide __SYSTEM.IQueryInterface, __SYSTEM.TYPE_CLASS,
  // __SYSTEM.AnyType and __SYSTEM.ExceptionCode without a library; only with the prefix.
  const std::string text =
      "INTERFACE I_Drive EXTENDS __SYSTEM.IQueryInterface\n"               // 1
      "END_INTERFACE\n"                                                    // 2
      "FUNCTION F_Kind : BOOL\n"                                           // 3
      "VAR\n"                                                              // 4
      "  eClass : __SYSTEM.TYPE_CLASS := __SYSTEM.TYPE_CLASS.TYPE_INT;\n"  // 5
      "  stAny : __SYSTEM.AnyType;\n"                                      // 6
      "  exc : __SYSTEM.ExceptionCode;\n"                                  // 7
      "END_VAR\n"                                                          // 8
      "eClass := stAny.TypeClass;\n"                                       // 9
      "F_Kind := eClass = __SYSTEM.TYPE_CLASS.TYPE_LREAL;\n"               // 10
      "exc := __SYSTEM.ExceptionCode.RTSEXCPT_ARRAYBOUNDS;\n"              // 11
      "eClass := __SYSTEM.TYPE_CLASS.TYPE_NOPE;\n"                         // 12
      "eClass := TYPE_INT;\n"                                              // 13
      "END_FUNCTION\n";
  for (Profile profile : {Profile::Codesys, Profile::Twincat}) {
    EXPECT_EQ(found(text, profile), (Found{"E005@12", "E001@13"}));
  }
}

// --- global scope operator `.x` -------------------------------------------------------------------

TEST(NameRules, LeadingDotNamesTheGlobalEvenWhenALocalHidesIt) {
  const std::string text =
      "VAR_GLOBAL\n"
      "  ivar : INT;\n"
      "END_VAR\n"
      "PROGRAM P\n"
      "VAR ivar : BOOL; END_VAR\n"
      "ivar := TRUE;\n"
      ".ivar := 5;\n"
      ".ivar := TRUE;\n"  // the global is an INT: BOOL does not convert
      "ivar := .ivar;\n"  // nor does INT into the BOOL local
      "END_PROGRAM\n";
  EXPECT_EQ(found(text), (Found{"E101@8", "E101@9"}));
}

TEST(NameRules, LeadingDotWithoutGlobalIsUndeclared) {
  const std::string text =
      "PROGRAM P\n"
      "VAR x : INT; END_VAR\n"
      "x := .x;\n"
      "END_PROGRAM\n";
  EXPECT_EQ(found(text), (Found{"E001@3"}));
}

TEST(NameRules, LeadingDotReachesAQualifiedOnlyVariableOnlyThroughItsList) {
  EXPECT_EQ(found({{"GVL.st", kQualifiedList}, {"P.st", "PROGRAM P\n.iVar := 1;\n.GVL.iVar := 2;\nEND_PROGRAM\n"}}),
            (Found{"E006@2"}));
}

// --- obsolete types in declarations (E601) ------------------------------------------------------

TEST(NameRules, InstanceOfObsoleteFunctionBlockWarns) {
  const std::string text =
      "{attribute 'obsolete' := 'datatype fb1 not valid!'}\n"
      "FUNCTION_BLOCK fb1\n"
      "VAR_INPUT i : INT; END_VAR\n"
      "END_FUNCTION_BLOCK\n"
      "FUNCTION_BLOCK fb2 EXTENDS fb1\n"
      "END_FUNCTION_BLOCK\n"
      "PROGRAM P\n"
      "VAR\n"
      "  fbinst : fb1;\n"
      "  many : ARRAY[1..3] OF fb1;\n"
      "  fine : fb2;\n"
      "END_VAR\n"
      "fbinst(i := 1);\n"
      "END_PROGRAM\n";
  EXPECT_EQ(found(text), (Found{"E601@5?", "E601@9?", "E601@10?"}));
  const auto all = findings({{"P.st", text}}, Profile::Codesys);
  ASSERT_FALSE(all.empty());
  EXPECT_EQ(all[0].message, "'fb1' is obsolete: datatype fb1 not valid!");
}

TEST(NameRules, AttributeValuesMayHoldApostrophesAndSpanLines) {
  // A pytmc-style value over several lines with "we're" in it once swallowed the STRUCT after it.
  const std::string text =
      "TYPE ST_Axis :\n"                                       // 1
      "STRUCT\n"                                               // 2
      "  {attribute 'pytmc' := '\n"                            // 3
      "    pv: AXIS\n"                                         // 4
      "    field: DESC the axis we're moving\n"                // 5
      "  '}\n"                                                 // 6
      "  fPos : LREAL;\n"                                      // 7
      "END_STRUCT\n"                                           // 8
      "END_TYPE\n"                                             // 9
      "{attribute 'obsolete' := 'use FB_New, it's faster'}\n"  // 10
      "FUNCTION_BLOCK FB_Old\n"                                // 11
      "END_FUNCTION_BLOCK\n"                                   // 12
      "PROGRAM P\n"                                            // 13
      "VAR st : ST_Axis; fb : FB_Old; END_VAR\n"               // 14
      "st.fPos := 1.0;\n"                                      // 15
      "END_PROGRAM\n";
  const auto all = findings({{"P.st", text}}, Profile::Twincat);
  ASSERT_EQ(all.size(), 1u);
  EXPECT_EQ(all[0].at, "E601@14?");
  EXPECT_EQ(all[0].message, "'FB_Old' is obsolete: use FB_New, it's faster");
}

// --- CONSTANT globals through VAR_EXTERNAL (E401) -------------------------------------------------

TEST(NameRules, ConstantGlobalCannotBeWrittenThroughExternal) {
  const std::string text =
      "VAR_GLOBAL CONSTANT\n"
      "  ceiling : INT := 10;\n"
      "END_VAR\n"
      "VAR_GLOBAL\n"
      "  level : INT;\n"
      "END_VAR\n"
      "PROGRAM Main\n"
      "VAR_EXTERNAL\n"
      "  ceiling : INT;\n"
      "  level : INT;\n"
      "END_VAR\n"
      "level := ceiling;\n"
      "ceiling := 5;\n"
      "END_PROGRAM\n";
  EXPECT_EQ(found(text, Profile::Openpcs), (Found{"E401@13"}));
  EXPECT_EQ(found(text, Profile::Codesys), (Found{"E401@13"}));
}

// --- members of values without members (E005) ----------------------------------------------------

TEST(NameRules, MemberOfElementaryVariableIsUnknown) {
  const std::string text =
      "PROGRAM P\n"
      "VAR\n"
      "  i : INT;\n"
      "  w : WORD;\n"
      "  s : STRING;\n"
      "  a : ARRAY[1..2] OF INT;\n"
      "  b : BOOL;\n"
      "END_VAR\n"
      "VAR CONSTANT\n"
      "  cBit : INT := 3;\n"
      "END_VAR\n"
      "i.a := 1;\n"
      "b := w.3;\n"
      "b := w.cBit;\n"
      "b := w.i;\n"
      "s.len := 2;\n"
      "a.x := 1;\n"
      "END_PROGRAM\n";
  EXPECT_EQ(found(text), (Found{"E005@12", "E005@15", "E005@16", "E005@17"}));
}

TEST(NameRules, ConstantBitNumberIsCheckedAgainstTheWidth) {
  const std::string text =
      "PROGRAM P\n"
      "VAR b : BOOL; x : BYTE; END_VAR\n"
      "VAR CONSTANT cHigh : INT := 9; END_VAR\n"
      "b := x.cHigh;\n"
      "END_PROGRAM\n";
  EXPECT_EQ(found(text), (Found{"E107@4"}));
}

}  // namespace
}  // namespace rung::check
