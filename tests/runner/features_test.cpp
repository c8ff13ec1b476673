// Implicit check functions, the process image, computed initial values and VAR_IN_OUT CONSTANT.
#include <gtest/gtest.h>

#include "tests/runner/run_support.hpp"

namespace rung::run::testing {
namespace {

TEST(RunChecks, CheckBoundsClampsTheIndex) {
  // CODESYS V3 textbook, implicit checks: with a CheckBounds that clamps, a[10] := TRUE on
  // ARRAY[0..7] writes a[7].
  auto run = run_text(R"(
FUNCTION CheckBounds : DINT
VAR_INPUT
  index, lower, upper : DINT;
END_VAR
IF index < lower THEN
  CheckBounds := lower;
ELSIF index > upper THEN
  CheckBounds := upper;
ELSE
  CheckBounds := index;
END_IF
END_FUNCTION

PROGRAM PLC_PRG
VAR
  a : ARRAY[0..7] OF BOOL;
  b : INT := 10;
END_VAR
a[b] := TRUE;
END_PROGRAM
)");
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("a[7]"), "TRUE");
}

TEST(RunChecks, CheckDivRealReplacesAZeroDivisor) {
  // CODESYS V3 textbook: CheckDivReal turns 799.0 / 0.0 into 799.0 / 1.0.
  auto run = run_text(R"(
FUNCTION CheckDivReal : REAL
VAR_INPUT divisor : REAL; END_VAR
IF divisor = 0 THEN
  CheckDivReal := 1;
ELSE
  CheckDivReal := divisor;
END_IF
END_FUNCTION

PROGRAM PLC_PRG
VAR
  erg, v1 : REAL := 799;
  d : REAL;
END_VAR
erg := v1 / d;
END_PROGRAM
)");
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("erg"), "799");
}

TEST(RunChecks, NoCheckAttributeTurnsTheChecksOff) {
  auto run = run_text(R"(
FUNCTION CheckBounds : DINT
VAR_INPUT index, lower, upper : DINT; END_VAR
CheckBounds := upper;
END_FUNCTION

{attribute 'no_check'}
PROGRAM PLC_PRG
VAR
  a : ARRAY[0..7] OF INT;
END_VAR
a[2] := 5;
END_PROGRAM
)");
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("a[2]"), "5");
  EXPECT_EQ(run->text("a[7]"), "0");
}

TEST(RunImage, LocatedVariablesOverlapAsOnTheController) {
  // CODESYS addressing: %MW1 is bytes 2..3 of the memory area, %MX2.1 bit 1 of byte 2.
  auto run = run_text(R"(
PROGRAM PLC_PRG
VAR
  w AT %MW1 : WORD;
  bit1 AT %MX2.1 : BOOL;
  low AT %MB2 : BYTE;
  out : BOOL;
END_VAR
w := 16#0102;
%QX0.0 := bit1;
out := %QX0.0;
END_PROGRAM
)");
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("low"), "2");
  EXPECT_EQ(run->text("bit1"), "TRUE");
  EXPECT_EQ(run->text("out"), "TRUE");
}

TEST(RunInitialValues, ComputedAtStartInDeclarationOrder) {
  auto run = run_files({{"gvl.st", R"(
VAR_GLOBAL
  gBase : INT := 7;
  gPointer : POINTER TO INT := ADR(gBase);
END_VAR
)"},
                        {"main.st", R"(
FUNCTION Twice : INT
VAR_INPUT x : INT; END_VAR
VAR doubled : INT := x * 2; END_VAR
Twice := doubled;
END_FUNCTION

PROGRAM PLC_PRG
VAR
  n : INT := 3;
  p : POINTER TO INT := ADR(n);
  viaGlobal, viaLocal, result : INT;
END_VAR
viaGlobal := gPointer^;
viaLocal := p^;
result := Twice(21);
END_PROGRAM
)"}});
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("viaGlobal"), "7");
  EXPECT_EQ(run->text("viaLocal"), "3");
  EXPECT_EQ(run->text("result"), "42");
}

TEST(RunCalls, InOutConstantAndEmptyActualParameters) {
  auto run = run_text(R"(
FUNCTION Area : REAL
VAR_IN_OUT CONSTANT w, h : REAL; END_VAR
Area := w * h;
END_FUNCTION

PROGRAM PLC_PRG
VAR
  side : REAL := 3;
  a : REAL;
  counter : CTUD;
END_VAR
a := Area(side, side);
counter(CU := TRUE, PV := , QU => , CV => );
END_PROGRAM
)");
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("a"), "9");
  EXPECT_EQ(run->text("counter.CV"), "1");
}

}  // namespace
}  // namespace rung::run::testing
