// Call and type-compatibility rules: which parameters a FUNCTION call must give (E302), longer
// strings stored in shorter ones (E106), arithmetic on bit strings (E104), OpenPCS's UINT lengths
// of LEFT/RIGHT/MID (E101) and its formal arguments in declaration order (E309). The OpenPCS rules
// quote the manual's message numbers (003.md), the CODESYS ones the textbook (000a.md) and the
// MP300 manual (002.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "checker/check.hpp"
#include "tests/support/project_findings.hpp"

namespace rung::check {
namespace {

using Found = std::vector<std::string>;
using project::Profile;

Found found(const std::string& text, Profile profile) {
  return testing::codes_at_lines({{"P.st", text}}, testing::config_for(profile));
}

// The messages of the diagnostics with this code.
std::vector<std::string> messages(const std::string& text, Profile profile, std::string_view code) {
  return testing::messages_with_code({{"P.st", text}}, testing::config_for(profile), code);
}

const std::string kAdd2 =
    "FUNCTION Add2 : INT\n"  // 1
    "VAR_INPUT\n"            // 2
    "  a : INT;\n"           // 3
    "  b : INT;\n"           // 4
    "END_VAR\n"              // 5
    "Add2 := a + b;\n"       // 6
    "END_FUNCTION\n"         // 7
    "FUNCTION_BLOCK Keep\n"  // 8
    "VAR_INPUT\n"            // 9
    "  a : INT;\n"           // 10
    "  b : INT;\n"           // 11
    "END_VAR\n"              // 12
    "END_FUNCTION_BLOCK\n"   // 13
    "PROGRAM Main\n"         // 14
    "VAR\n"                  // 15
    "  k : Keep;\n"          // 16
    "  r : INT;\n"           // 17
    "END_VAR\n";             // 18

// --- E302: a FUNCTION call gives every input ------------------------------------------------

TEST(CallRules, FormalFunctionCallWithoutAnInputIsAnError) {
  // 000a.md fact 52, 003.md fact 80: a function has no previous values to fall back on.
  const std::string text = kAdd2 +
                           "r := Add2(a := 1, b := 2);\n"  // 19
                           "r := Add2(a := 1);\n"          // 20
                           "r := Add2(b := 1);\n"          // 21
                           "END_PROGRAM\n";
  for (Profile profile : {Profile::Codesys, Profile::Twincat, Profile::Iec, Profile::Openpcs}) {
    EXPECT_EQ(found(text, profile), (Found{"E302@20", "E302@21"}));
  }
  EXPECT_EQ(messages(text, Profile::Codesys, "E302"),
            (std::vector<std::string>{"the call of FUNCTION 'Add2' does not give the input 'b'",
                                      "the call of FUNCTION 'Add2' does not give the input 'a'"}));
}

TEST(CallRules, InformalFunctionCallWithTooFewArgumentsIsAnError) {
  const std::string text = kAdd2 +
                           "r := Add2(1, 2);\n"  // 19
                           "r := Add2(1);\n"     // 20
                           "r := Add2();\n"      // 21
                           "END_PROGRAM\n";
  EXPECT_EQ(found(text, Profile::Codesys), (Found{"E302@20", "E302@21"}));
  EXPECT_EQ(messages(text, Profile::Codesys, "E302").back(),
            "the call of FUNCTION 'Add2' does not give the inputs 'a', 'b'");
}

TEST(CallRules, FunctionBlockCallsMayLeaveInputsOut) {
  // The instance keeps the values of the previous call (000a.md L3212, 003.md L1436-1438).
  const std::string text = kAdd2 +
                           "k(a := 1);\n"
                           "k();\n"
                           "k(b := 2);\n"
                           "END_PROGRAM\n";
  EXPECT_EQ(found(text, Profile::Codesys), Found{});
  EXPECT_EQ(found(text, Profile::Openpcs), Found{});
}

TEST(CallRules, InputsWithAnInitialValueAndEnAreOptional) {
  const std::string text =
      "FUNCTION Scale : REAL\n"
      "VAR_INPUT\n"
      "  EN : BOOL;\n"
      "  x : REAL;\n"
      "  factor : REAL := 1.0;\n"
      "END_VAR\n"
      "Scale := x * factor;\n"
      "END_FUNCTION\n"
      "PROGRAM Main\n"
      "VAR r : REAL; END_VAR\n"
      "r := Scale(x := 2.0);\n"       // 11
      "r := Scale(2.0);\n"            // 12: positional arguments skip EN
      "r := Scale(2.0, 3.0);\n"       // 13
      "r := Scale(factor := 3.0);\n"  // 14: x is missing
      "END_PROGRAM\n";
  EXPECT_EQ(found(text, Profile::Codesys), Found{"E302@14"});
}

TEST(CallRules, FormalCallsBindTheAdditionalOutputsOfAFunction) {
  // MP300 manual L11195-11203 (002.md fact 22): fun(iIn1 := 1, iIn2 := 2, iOut1 => iLoc1, ...).
  const std::string text =
      "FUNCTION fun : INT\n"
      "VAR_INPUT iIn1, iIn2 : INT; END_VAR\n"
      "VAR_OUTPUT iOut1, iOut2 : INT; END_VAR\n"
      "fun := iIn1;\n"
      "END_FUNCTION\n"
      "PROGRAM Main\n"
      "VAR iLoc1, iLoc2, iRes : INT; END_VAR\n"
      "iRes := fun(iIn1 := 1, iIn2 := 2, iOut1 => iLoc1, iOut2 => iLoc2);\n"  // 8
      "iRes := fun(iIn1 := 1, iIn2 := 2, iOut1 => iLoc1);\n"                  // 9
      "iRes := fun(1, 2);\n"                                                  // 10: cannot name outputs
      "END_PROGRAM\n";
  EXPECT_EQ(found(text, Profile::Codesys), Found{"E302@9"});
  EXPECT_EQ(messages(text, Profile::Codesys, "E302"),
            std::vector<std::string>{"the call of FUNCTION 'fun' does not bind the output 'iOut2'"});
}

TEST(CallRules, StandardFunctionsKeepTheirShortForms) {
  // Extensible inputs, vendor parameter names (CODESYS LEFT(STR, SIZE)) and IL's first argument
  // from the current result.
  const std::string text =
      "PROGRAM Main\n"
      "VAR i : INT; s : STRING; w : WORD; END_VAR\n"
      "i := ADD(1, 2, 3, 4);\n"
      "i := MAX(i, 7, 3);\n"
      "i := MUX(1, 10, 20, 30);\n"
      "i := LIMIT(MN := 0, IN := i, MX := 9);\n"
      "s := LEFT(STR := s, SIZE := 3);\n"
      "s := CONCAT('a', 'b');\n"
      "w := SHL(w, 2);\n"
      "END_PROGRAM\n";
  EXPECT_EQ(found(text, Profile::Codesys), Found{});
  EXPECT_EQ(found("PROGRAM Main\nVAR i : INT; END_VAR\nLD i\nLIMIT 0, 9\nST i\nEND_PROGRAM\n", Profile::Codesys),
            Found{});
  // A standard function still needs its inputs.
  EXPECT_EQ(found("PROGRAM Main\nVAR i : INT; END_VAR\ni := LIMIT(0, i);\nEND_PROGRAM\n", Profile::Codesys),
            Found{"E302@3"});
}

// Found on real OpenPLC programs: the standard blocks' IEC input names (CTU R, SR S1/R, CTUD
// R/LD) are as valid as CODESYS's (RESET, SET1, LOAD); a name neither uses is still reported.
TEST(CallRules, StandardBlocksTakeTheirInputsUnderEitherDialectsName) {
  const std::string text =
      "PROGRAM Main\n"
      "VAR c : CTU; u : CTUD; l : SR; b : BOOL; END_VAR\n"
      "c(CU := b, R := b, PV := 3);\n"
      "c(CU := b, RESET := b, PV := 3);\n"
      "u(CU := b, CD := b, R := b, LD := b, PV := 3);\n"
      "u(CU := b, CD := b, RESET := b, LOAD := b, PV := 3);\n"
      "l(S1 := b, R := b);\n"
      "l(SET1 := b, RESET := b);\n"
      "c(CU := b, RST := b);\n"  // 9
      "END_PROGRAM\n";
  for (Profile profile : {Profile::Codesys, Profile::Iec}) EXPECT_EQ(found(text, profile), Found{"E301@9"});
}

// --- E106: a longer STRING variable in a shorter one ----------------------------------------

TEST(CallRules, LongerStringVariableInAShorterOneWarns) {
  // OpenPCS warning S3048 (003.md fact 43); the other direction is silent.
  const std::string text =
      "FUNCTION Show : BOOL\n"
      "VAR_INPUT text : STRING[10]; END_VAR\n"
      "Show := TRUE;\n"
      "END_FUNCTION\n"
      "PROGRAM Main\n"
      "VAR\n"
      "  short : STRING[10];\n"
      "  long : STRING[40];\n"
      "  names : ARRAY[1..2] OF STRING(40);\n"
      "  ok : BOOL;\n"
      "END_VAR\n"
      "long := short;\n"             // 12
      "short := long;\n"             // 13
      "short := names[1];\n"         // 14
      "ok := Show(text := long);\n"  // 15
      "ok := Show(text := short);\n"
      "short := 'abc';\n"
      "END_PROGRAM\n";
  for (Profile profile : {Profile::Codesys, Profile::Openpcs}) {
    EXPECT_EQ(found(text, profile), (Found{"E106@13?", "E106@14?", "E106@15?"}));
  }
  EXPECT_EQ(messages(text, Profile::Openpcs, "E106").front(),
            "STRING(40) is stored in STRING(10): up to 30 characters may be cut off");
}

TEST(CallRules, LongerStringOutputBoundToAShorterVariableWarns) {
  const std::string text =
      "FUNCTION_BLOCK Reader\n"
      "VAR_OUTPUT line : STRING(80); END_VAR\n"
      "END_FUNCTION_BLOCK\n"
      "PROGRAM Main\n"
      "VAR r : Reader; short : STRING(20); END_VAR\n"
      "r(line => short);\n"
      "END_PROGRAM\n";
  EXPECT_EQ(found(text, Profile::Codesys), Found{"E106@6?"});
}

TEST(CallRules, StringLengthsCountCharactersNotBytes) {
  // A STRING holds one byte per character in the target's code page, whatever the file's
  // encoding; a WSTRING counts UTF-16 units.
  const std::string utf8 =
      "PROGRAM Main\n"
      "VAR\n"
      "  s5 : STRING(5) := '\xC3\xA4\xC3\xB6\xC3\xBC\xC3\x9F\xC3\xA9';\n"  // 3: 'äöüßé'
      "  s4 : STRING(4) := '\xC3\xA4\xC3\xB6\xC3\xBC\xC3\x9F\xC3\xA9';\n"  // 4
      "  w3 : WSTRING(3) := \"\xE2\x82\xAC\xF0\x9F\x98\x80\";\n"           // 5: "€😀", 3 units
      "  w2 : WSTRING(2) := \"\xE2\x82\xAC\xF0\x9F\x98\x80\";\n"           // 6
      "END_VAR\n"
      "s5 := '\xC3\x84\xC3\x96\xC3\x9C$E4e';\n"  // 8: 'ÄÖÜ', a $E4 byte and e: 5 characters
      "s4 := '\xC3\x84\xC3\x96\xC3\x9C$E4e';\n"  // 9
      "END_PROGRAM\n";
  EXPECT_EQ(found(utf8, Profile::Codesys), (Found{"E106@4?", "E106@6?", "E106@9?"}));
  EXPECT_EQ(messages(utf8, Profile::Codesys, "E106"),
            (std::vector<std::string>{"the string has 5 characters; STRING(4) holds 4, the rest is cut off",
                                      "the string has 3 characters; WSTRING(2) holds 2, the rest is cut off",
                                      "the string has 5 characters; STRING(4) holds 4, the rest is cut off"}));
  // The same declarations in a cp1252 file.
  const std::string cp1252 =
      "PROGRAM Main\n"
      "VAR\n"
      "  s5 : STRING(5) := '\xE4\xF6\xFC\xDF\xE9';\n"
      "  s4 : STRING(4) := '\xE4\xF6\xFC\xDF\xE9';\n"
      "END_VAR\n"
      "END_PROGRAM\n";
  EXPECT_EQ(found(cp1252, Profile::Codesys), Found{"E106@4?"});
}

// --- SIZEOF, XSIZEOF and __NEW take type names ------------------------------------------------

TEST(CallRules, SizeofTakesElementaryTypeNames) {
  const std::string text =
      "TYPE T_Data : STRUCT a : INT; END_STRUCT END_TYPE\n"                // 1
      "PROGRAM Main\n"                                                     // 2
      "VAR n : UDINT; p : POINTER TO INT; l : INT; END_VAR\n"              // 3
      "n := SIZEOF(BOOL) + SIZEOF(lreal) + SIZEOF(T_Data) + SIZEOF(n);\n"  // 4
      "n := XSIZEOF(DINT);\n"                                              // 5
      "p := __NEW(INT);\n"                                                 // 6
      "n := SIZEOF(T_Bogus);\n"                                            // 7
      "n := UDINT;\n"                                                      // 8
      "l := LEN(INT);\n"                                                   // 9
      "END_PROGRAM\n";
  for (Profile profile : {Profile::Codesys, Profile::Twincat}) {
    EXPECT_EQ(found(text, profile), (Found{"E001@7", "E001@8", "E001@9"}));
  }
}

// --- E305/E106: VAR_IN_OUT CONSTANT takes constants, expressions and strings of any length ------

TEST(CallRules, InOutConstantTakesConstantsExpressionsAndLongerStrings) {
  // CODESYS and TwinCAT pass VAR_IN_OUT CONSTANT by reference without letting the callee write it.
  const std::string text =
      "FUNCTION Log : BOOL\n"                                                      // 1
      "VAR_IN_OUT CONSTANT\n"                                                      // 2
      "  sText : STRING(10);\n"                                                    // 3
      "  nLevel : INT;\n"                                                          // 4
      "END_VAR\n"                                                                  // 5
      "VAR_IN_OUT nCount : INT; END_VAR\n"                                         // 6
      "Log := TRUE;\n"                                                             // 7
      "END_FUNCTION\n"                                                             // 8
      "PROGRAM Main\n"                                                             // 9
      "VAR\n"                                                                      // 10
      "  sLong : STRING(80);\n"                                                    // 11
      "  n : INT;\n"                                                               // 12
      "  ok : BOOL; sWide : WSTRING(10);\n"                                        // 13
      "END_VAR\n"                                                                  // 14
      "ok := Log(sText := 'a text longer than ten', nLevel := 3, nCount := n);\n"  // 15
      "ok := Log(sText := sLong, nLevel := n + 1, nCount := n);\n"                 // 16
      "ok := Log(sText := sLong, nLevel := n, nCount := n + 1);\n"                 // 17
      "ok := Log(sText := sWide, nLevel := 1, nCount := n);\n"                     // 18
      "END_PROGRAM\n";
  for (Profile profile : {Profile::Codesys, Profile::Twincat}) {
    EXPECT_EQ(found(text, profile), (Found{"E305@17", "E105@18?"}));
  }
}

// --- E104: arithmetic on bit strings ---------------------------------------------------------

TEST(CallRules, ArithmeticOnBitStringsDependsOnTheProfile) {
  // OpenPCS S3035 (003.md fact 53): WORD - 3 is an error, WORD AND 16#00FF is fine. CODESYS and
  // TwinCAT compute with bit strings like with unsigned integers.
  const std::string text =
      "PROGRAM WordMath\n"
      "VAR bitMask : WORD; d : DWORD; END_VAR\n"
      "bitMask := bitMask AND 16#00FF;\n"
      "bitMask := bitMask - 3;\n"                // 4
      "d := d * d;\n"                            // 5
      "bitMask := WORD_TO_UINT(bitMask) + 1;\n"  // 6: E101 under IEC (UINT into WORD) only
      "END_PROGRAM\n";
  EXPECT_EQ(found(text, Profile::Codesys), Found{});
  EXPECT_EQ(found(text, Profile::Twincat), Found{});
  EXPECT_EQ(found(text, Profile::Iec), (Found{"E104@4", "E104@5", "E101@6"}));
  EXPECT_EQ(found(text, Profile::Openpcs), (Found{"E104@4", "E104@5", "E101@6"}));
  EXPECT_EQ(messages(text, Profile::Iec, "E104").front(), "'-' is not defined for the bit string WORD");
  // IL SUB goes through the same rule.
  EXPECT_EQ(found("PROGRAM P\nVAR w : WORD; END_VAR\nLD w\nSUB 3\nST w\nEND_PROGRAM\n", Profile::Openpcs),
            Found{"E104@4"});
}

// --- E101: OpenPCS LEFT/RIGHT/MID take UINT lengths -------------------------------------------

TEST(CallRules, OpenPcsStringLengthsAreUint) {
  // C10035 (003.md fact 65): LEFT's length must be UINT, although the reference pages say ANY_INT.
  const std::string text =
      "PROGRAM Lefts\n"
      "VAR s : STRING; lenU : UINT := 3; lenI : INT := 3; END_VAR\n"
      "s := LEFT('EXAMPLE', lenU);\n"
      "s := LEFT('EXAMPLE', lenI);\n"      // 4
      "s := RIGHT(IN := s, L := lenI);\n"  // 5
      "s := MID(s, lenU, lenI);\n"         // 6: P
      "s := MID(s, 2, 1);\n"
      "END_PROGRAM\n";
  EXPECT_EQ(found(text, Profile::Openpcs), (Found{"E101@4", "E101@5", "E101@6"}));
  EXPECT_EQ(found(text, Profile::Codesys), Found{});
  EXPECT_EQ(found(text, Profile::Iec), Found{});
}

// --- E309: OpenPCS formal arguments in declaration order ------------------------------------

TEST(CallRules, OpenPcsFormalArgumentsFollowTheDeclaration) {
  // S3047 (003.md fact 63): the ST compiler passes the arguments in the order written.
  const std::string text =
      "FUNCTION_BLOCK Example\n"
      "VAR_INPUT In1 : INT; In2 : INT; END_VAR\n"
      "VAR_OUTPUT Out1 : INT; Out2 : INT; END_VAR\n"
      "END_FUNCTION_BLOCK\n"
      "PROGRAM Main\n"
      "VAR Instance : Example; Local1, Local2 : INT; END_VAR\n"
      "Instance(In1 := Local1, In2 := Local2);\n"                                  // 7
      "Instance(In2 := Local2, In1 := Local1);\n"                                  // 8
      "Instance(In2 := Local2);\n"                                                 // 9
      "Instance(In1 := Local1, In2 := Local2, Out2 => Local1, Out1 => Local2);\n"  // 10
      "Instance(In2 := Local2, Out1 => Local1);\n"                                 // 11
      "END_PROGRAM\n";
  EXPECT_EQ(found(text, Profile::Openpcs), (Found{"E309@8", "E309@10"}));
  EXPECT_EQ(found(text, Profile::Codesys), Found{});
  EXPECT_EQ(messages(text, Profile::Openpcs, "E309").front(),
            "'In1' is declared before 'In2' in 'Example': give the formal arguments in that order");
}

}  // namespace
}  // namespace rung::check
