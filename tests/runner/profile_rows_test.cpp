// The rows of docs/runner.md's "Semantics choices" table that had no test: each test states the
// rule and its source, and runs it under the profiles the row names.
#include <gtest/gtest.h>

#include "tests/runner/run_support.hpp"

namespace rung::run::testing {
namespace {

TEST(RunProfileRows, NegativeRealToUnsignedKeepsTheTwosComplementBits) {
  // The x86 conversion CODESYS uses: -1.0 to UINT is 65535, -3.7 to USINT is 252 (rounded to -4).
  for (const project::Profile profile : {project::Profile::Codesys, project::Profile::Iec}) {
    auto run = run_text(R"(
PROGRAM PLC_PRG
VAR
  r : REAL := -1.0;
  r2 : REAL := -3.7;
  u : UINT;
  us : USINT;
  ud : UDINT;
END_VAR
u := REAL_TO_UINT(r);
us := REAL_TO_USINT(r2);
ud := REAL_TO_UDINT(r);
END_PROGRAM
)",
                        {.profile = profile});
    ASSERT_CLEAN(run);
    EXPECT_EQ(run->text("u"), "65535");
    EXPECT_EQ(run->text("us"), "252");
    EXPECT_EQ(run->text("ud"), "4294967295");
  }
}

constexpr std::string_view kEvaluationOrder = R"(
FUNCTION Touch : BOOL
VAR_INPUT
  result : BOOL;
END_VAR
gTouched := gTouched + 1;
Touch := result;
END_FUNCTION

VAR_GLOBAL
  gTouched : INT;
END_VAR

PROGRAM PLC_PRG
VAR
  a, b, c, d : BOOL;
  touchedAnd, touchedOr, touchedAndThen : INT;
END_VAR
gTouched := 0;
a := FALSE AND Touch(TRUE);
touchedAnd := gTouched;
gTouched := 0;
b := TRUE OR Touch(FALSE);
touchedOr := gTouched;
gTouched := 0;
c := FALSE AND_THEN Touch(TRUE);
d := TRUE OR_ELSE Touch(TRUE);
touchedAndThen := gTouched;
END_PROGRAM
)";

TEST(RunProfileRows, AndOrEvaluateBothSidesInCodesysAndShortCircuitInIec) {
  // CODESYS V3 textbook, operators: only AND_THEN and OR_ELSE skip their right side; AND and OR
  // evaluate both. The iec profile short-circuits AND and OR too (the standard leaves it open).
  auto codesys = run_text(kEvaluationOrder, {.profile = project::Profile::Codesys});
  ASSERT_CLEAN(codesys);
  EXPECT_EQ(codesys->text("touchedAnd"), "1");
  EXPECT_EQ(codesys->text("touchedOr"), "1");
  EXPECT_EQ(codesys->text("touchedAndThen"), "0");
  EXPECT_EQ(codesys->text("a"), "FALSE");
  EXPECT_EQ(codesys->text("b"), "TRUE");

  auto iec = run_text(kEvaluationOrder, {.profile = project::Profile::Iec});
  ASSERT_CLEAN(iec);
  EXPECT_EQ(iec->text("touchedAnd"), "0");
  EXPECT_EQ(iec->text("touchedOr"), "0");
  EXPECT_EQ(iec->text("touchedAndThen"), "0");
}

TEST(RunProfileRows, CtuStopsCountingAt32767) {
  // CODESYS V3 textbook, ch. 5 counters: CV counts up to PVmax and stays there.
  auto run = run_text(R"(
PROGRAM PLC_PRG
VAR
  counter : CTU;
  pulse : BOOL;
END_VAR
pulse := NOT pulse;
counter(CU := pulse, PV := 10);
END_PROGRAM
)",
                      {.cycles = 0});
  run->set("counter.CV", "32765");
  ASSERT_TRUE(run->cycles(12)) << run->described_error();
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("counter.CV"), "32767");
  EXPECT_EQ(run->text("counter.Q"), "TRUE");
}

TEST(RunProfileRows, AStringWithoutALengthHoldsEightyCharacters) {
  // CODESYS V3 textbook, data types: STRING without a length is STRING(80); longer values are cut.
  auto run = run_text(R"(
PROGRAM PLC_PRG
VAR
  s : STRING;
  i : INT;
  n : INT;
END_VAR
s := '';
FOR i := 1 TO 10 DO
  s := CONCAT(s, '0123456789');
END_FOR
n := LEN(s);
END_PROGRAM
)");
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("n"), "80");
}

}  // namespace
}  // namespace rung::run::testing
