// Literal ranges (E102), the implementation limits of a profile (E704), addresses written in
// code (E505) and a FUNCTION calling a PROGRAM (E212). The OpenPCS rules quote the manual's
// message numbers (003.md), the CODESYS ones the textbook (000a.md) and the AK800 manual (001.md).
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

Found found(const std::string& text, Profile profile, std::string addressing = {}) {
  project::ProjectConfig config = testing::config_for(profile);
  config.addressing = std::move(addressing);
  return testing::codes_at_lines({{"P.st", text}}, config);
}

// The message of the first diagnostic with `code`, or "" when there is none.
std::string message_of(const std::string& text, Profile profile, std::string_view code) {
  const auto messages = testing::messages_with_code({{"P.st", text}}, testing::config_for(profile), code);
  return messages.empty() ? std::string() : messages.front();
}

// A PROGRAM with `declarations` in its VAR block and `body` as its statements.
std::string program(const std::string& declarations, const std::string& body) {
  return "PROGRAM P\nVAR\n" + declarations + "END_VAR\n" + body + "END_PROGRAM\n";
}

// --- REAL range (003.md#12, S1010) ------------------------------------------------------------

TEST(LiteralRange, RealLiteralBeyondRealIsAnError) {
  const std::string text = program(
      "  ok : REAL := 1.0E38;\n"     // 3
      "  bad : REAL := 1.0E39;\n"    // 4
      "  wide : LREAL := 1.0E39;\n"  // 5
      "  typed : LREAL;\n",          // 6
      "ok := -3.5E38;\n"             // 8
      "typed := REAL#1.0E39;\n"      // 9
      "typed := LREAL#1.0E300;\n"    // 10
      "typed := 1.0E400;\n");        // 11
  for (Profile profile : {Profile::Openpcs, Profile::Codesys}) {
    EXPECT_EQ(found(text, profile), (Found{"E102@4", "E102@8", "E102@9", "E102@11"}));
  }
  EXPECT_NE(message_of(text, Profile::Codesys, "E102").find("3.4028235E38"), std::string::npos);
}

// --- TIME literals (001.md#17, 003.md#8-#10, 003.md#112) --------------------------------------

TEST(LiteralRange, OpenpcsBoundsEveryTimeUnitAfterTheFirst) {
  const std::string text = program("  t : TIME;\n",
                                   "t := T#25h_15m;\n"     // 5: the first unit may overflow
                                   "t := T#75m;\n"         // 6
                                   "t := T#2d_1h_15m;\n"   // 7
                                   "t := T#1d_25h_15m;\n"  // 8: S1013
                                   "t := T#5h_75m;\n"      // 9: S1014
                                   "t := T#5m_75s;\n"      // 10: S1015
                                   "t := T#1s_1200ms;\n"   // 11: S1016
                                   "t := T#12.3ms;\n");    // 12
  EXPECT_EQ(found(text, Profile::Openpcs), (Found{"E102@8", "E102@9", "E102@10", "E102@11"}));
  EXPECT_NE(message_of(text, Profile::Openpcs, "E102").find("25h after a larger unit"), std::string::npos);
}

TEST(LiteralRange, CodesysBoundsOnlyTheSmallestTimeUnit) {
  // The textbook normalises T#3d29h27m41s1ms (L5009-5013) but rejects t#5m68s (L4198).
  const std::string text = program("  t : TIME;\n",
                                   "t := T#1d_25h_15m;\n"      // 5
                                   "t := T#3d29h27m41s1ms;\n"  // 6
                                   "t := t#5m68s;\n"           // 7
                                   "t := T#100s12ms;\n");      // 8
  EXPECT_EQ(found(text, Profile::Codesys), (Found{"E102@7"}));
  EXPECT_EQ(found(text, Profile::Iec), (Found{"E102@5", "E102@6", "E102@7"}));
}

TEST(LiteralRange, TimeRangeFollowsTheProfile) {
  // OpenPCS: 32 signed bits of ms, +/- 24.85 days (C10108); CODESYS: 32 unsigned bits.
  const std::string text = program("  t : TIME;\n",
                                   "t := T#24d;\n"                 // 5
                                   "t := T#25d;\n"                 // 6
                                   "t := T#-25d;\n"                // 7
                                   "t := T#49d17h2m47s295ms;\n"    // 8
                                   "t := T#49d17h2m47s296ms;\n");  // 9
  EXPECT_EQ(found(text, Profile::Openpcs), (Found{"E102@6", "E102@7", "E102@8", "E102@9"}));
  EXPECT_EQ(found(text, Profile::Codesys), (Found{"E102@9"}));
  EXPECT_NE(message_of(text, Profile::Openpcs, "E102").find("T#24d20h31m23s647ms"), std::string::npos);
  EXPECT_NE(message_of(text, Profile::Codesys, "E102").find("T#49d17h2m47s295ms"), std::string::npos);
}

TEST(LiteralRange, MicrosecondsNeedAnLtimeLiteralInCodesys) {
  // AK800 table 4.4-1 assigns t#3us2ns to an LTIME; T# is a millisecond TIME (MP300 L17797-17852).
  const std::string text = program("  lt : LTIME;\n",
                                   "lt := t#3us2ns;\n"                           // 5
                                   "lt := LTIME#3us2ns;\n"                       // 6
                                   "lt := LTIME#1000d15h23m12s34ms2us44ns;\n");  // 7
  EXPECT_EQ(found(text, Profile::Codesys), (Found{"E102@5"}));
  EXPECT_EQ(found(text, Profile::Twincat), (Found{"E102@5"}));
  EXPECT_EQ(found(text, Profile::Iec), Found{});  // IEC 3rd edition TIME has us and ns
  EXPECT_NE(message_of(text, Profile::Codesys, "E102").find("needs an LTIME literal"), std::string::npos);
}

TEST(LiteralRange, InitialValuesAreCheckedLikeAssignments) {
  const std::string text = program(
      "  bad : TIME := T#1d_25h_15m;\n"  // 3
      "  far : TIME := T#25d;\n"         // 4
      "  r : REAL := 1.0E39;\n",         // 5
      "r := 1.0;\n");
  EXPECT_EQ(found(text, Profile::Openpcs), (Found{"E102@3", "E102@4", "E102@5"}));
  EXPECT_EQ(found(text, Profile::Codesys), (Found{"E102@5"}));
}

// --- String escapes (003.md#14, S1022) ---------------------------------------------------------

TEST(LiteralRange, UnknownStringEscapeIsAnError) {
  const std::string text = program("  s : STRING(20);\n  w : WSTRING(20);\n",
                                   "s := '$R$L$N$P$T$r$l$n$p$t';\n"  // 6
                                   "s := '$$$'$0D$0a';\n"            // 7
                                   "s := 'a$Qb';\n"                  // 8
                                   "s := '$0G';\n"                   // 9
                                   "w := \"$\"x$0041\";\n");         // 10
  for (Profile profile : {Profile::Openpcs, Profile::Codesys}) {
    EXPECT_EQ(found(text, profile), (Found{"E102@8", "E102@9"}));
  }
  EXPECT_NE(message_of(text, Profile::Openpcs, "E102").find("'$Q' is not an escape"), std::string::npos);
}

// --- Implementation limits (E704, OpenPCS) ------------------------------------------------------

TEST(ImplementationLimits, IdentifiersHaveAtMost64Characters) {
  const std::string name64(64, 'a');
  const std::string name65 = "b" + std::string(64, 'c');
  const std::string text = program("  " + name64 + " : INT;\n  " + name65 + " : INT;\n", name64 + " := 1;\n");
  EXPECT_EQ(found(text, Profile::Openpcs), (Found{"E704@4"}));
  EXPECT_EQ(found(text, Profile::Codesys), Found{});
  EXPECT_NE(message_of(text, Profile::Openpcs, "E704").find("65 characters"), std::string::npos);
}

TEST(ImplementationLimits, ArraysHaveAtMostSixSubscripts) {
  const std::string text = program(
      "  six : ARRAY[0..1, 0..1, 0..1, 0..1, 0..1, 0..1] OF BOOL;\n"              // 3
      "  seven : ARRAY[0..1, 0..1, 0..1, 0..1, 0..1, 0..1, 0..1] OF BOOL;\n"      // 4
      "  nested : ARRAY[0..1, 0..1, 0..1] OF ARRAY[0..1, 0..1, 0..1] OF INT;\n",  // 5
      "six[0, 0, 0, 0, 0, 0] := TRUE;\n");
  EXPECT_EQ(found(text, Profile::Openpcs), (Found{"E704@4"}));
  EXPECT_EQ(found(text, Profile::Iec), Found{});
}

TEST(ImplementationLimits, OneDeclarationListsAtMost60Names) {
  auto names = [](char prefix, int count) {
    std::string list;
    for (int i = 0; i < count; ++i) list += (i ? ", " : "") + std::string(1, prefix) + std::to_string(i);
    return list;
  };
  const std::string text = program("  " + names('w', 60) + " : INT;\n  " + names('v', 61) + " : INT;\n", "w0 := 1;\n");
  EXPECT_EQ(found(text, Profile::Openpcs), (Found{"E704@4"}));
  EXPECT_EQ(found(text, Profile::Codesys), Found{});
}

TEST(ImplementationLimits, ArrayBoundsLieInPlusMinus32767) {
  const std::string text =
      "TYPE Big : ARRAY[0..40000] OF BYTE; END_TYPE\n"  // 1
      "PROGRAM P\n"
      "VAR CONSTANT\n"
      "  N : DINT := 32768;\n"
      "END_VAR\n"
      "VAR\n"
      "  widest : ARRAY[-32767..32767] OF BYTE;\n"  // 7
      "  toolow : ARRAY[-32768..0] OF BYTE;\n"      // 8
      "  toohigh : ARRAY[0..N] OF BYTE;\n"          // 9
      "END_VAR\n"
      "widest[0] := 1;\n"
      "END_PROGRAM\n";
  EXPECT_EQ(found(text, Profile::Openpcs), (Found{"E704@1", "E704@8", "E704@9"}));
  EXPECT_EQ(found(text, Profile::Codesys), Found{});
  EXPECT_NE(message_of(text, Profile::Openpcs, "E704").find("40000"), std::string::npos);
}

TEST(ImplementationLimits, OpenpcsCompilesNoCallAsArgumentOfACall) {
  const std::string text = program("  a : INT;\n  b : INT;\n  tmp : INT;\n",
                                   "tmp := ABS(b);\n"                      // 7
                                   "a := MAX(tmp, 3);\n"                   // 8
                                   "a := MAX(ABS(b), 3);\n"                // 9
                                   "a := MAX(ABS(ABS(b)), 3) + ABS(a);\n"  // 10: one finding
                                   "a := ABS(b) + ABS(a);\n");             // 11
  EXPECT_EQ(found(text, Profile::Openpcs), (Found{"E704@9", "E704@10"}));
  EXPECT_EQ(found(text, Profile::Codesys), Found{});
}

// --- Direct addresses in code (001.md#4) --------------------------------------------------------

TEST(AddressesInCode, BitNumberAboveSevenIsAnErrorUnderByteAddressing) {
  const std::string text = program("  w : WORD;\n  b : BOOL;\n",
                                   "%MX2.7 := TRUE;\n"  // 6
                                   "%MX0.8 := TRUE;\n"  // 7
                                   "b := %IX1.9;\n"     // 8
                                   "b := w.%X15;\n"     // 9: a bit of a variable, not an address
                                   "%MW3 := w;\n");     // 10
  EXPECT_EQ(found(text, Profile::Codesys), (Found{"E505@7", "E505@8"}));
  EXPECT_EQ(found(text, Profile::Codesys, "word"), Found{});  // %MX0.8 is bit 8 of word 0
}

// --- A FUNCTION calling a PROGRAM (001.md#27) ---------------------------------------------------

TEST(CallTargets, FunctionCannotCallAProgram) {
  const std::string text =
      "PROGRAM AlarmHandle\n"
      "VAR\n"
      "  bAlarm : BOOL;\n"
      "END_VAR\n"
      "bAlarm := NOT bAlarm;\n"
      "END_PROGRAM\n"
      "FUNCTION Helper : BOOL\n"
      "VAR_INPUT\n"
      "  x : BOOL;\n"
      "END_VAR\n"
      "Helper := x;\n"
      "END_FUNCTION\n"
      "FUNCTION CheckAlarms : BOOL\n"
      "VAR_INPUT\n"
      "  bEnable : BOOL;\n"
      "END_VAR\n"
      "AlarmHandle();\n"  // 17
      "CheckAlarms := Helper(bEnable);\n"
      "END_FUNCTION\n"
      "PROGRAM Main\n"
      "VAR\n"
      "  bOk : BOOL;\n"
      "END_VAR\n"
      "AlarmHandle();\n"
      "bOk := CheckAlarms(TRUE);\n"
      "END_PROGRAM\n";
  for (Profile profile : {Profile::Codesys, Profile::Iec, Profile::Openpcs}) {
    EXPECT_EQ(found(text, profile), (Found{"E212@17"})) << static_cast<int>(profile);
  }
  EXPECT_EQ(message_of(text, Profile::Codesys, "E212"), "FUNCTION 'CheckAlarms' cannot call the PROGRAM 'AlarmHandle'");
}

}  // namespace
}  // namespace rung::check
