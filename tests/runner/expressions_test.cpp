// Expressions and statements, run cycle by cycle, compared with exact values. Each rule names its
// source: a manual (CODESYS V3 textbook, AK800 / MP300 manuals, OpenPCS manual) or IEC 61131-3.
#include <gtest/gtest.h>

#include "tests/runner/run_support.hpp"

namespace rung::run::testing {
namespace {

TEST(RunExpressions, IntegerArithmeticWrapsAtTheTypesWidth) {
  // CODESYS: integer overflow wraps (no exception); INT 32767 + 1 = -32768.
  auto run = run_text(R"(
PROGRAM Main
VAR
  i : INT := 32767;
  b : BYTE := 255;
  u : UINT := 0;
  s : SINT := -128;
  d : DINT := 2147483647;
END_VAR
i := i + 1;
b := b + 1;
u := u - 1;
s := -s;
d := d + 1;
END_PROGRAM
)");
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("i"), "-32768");
  EXPECT_EQ(run->text("b"), "0");
  EXPECT_EQ(run->text("u"), "65535");
  EXPECT_EQ(run->text("s"), "-128");
  EXPECT_EQ(run->text("d"), "-2147483648");
}

TEST(RunExpressions, IntArithmeticInDintContextFollowsTheProfile) {
  const char* source = R"(
PROGRAM Main
VAR
  a : INT := 30000;
  b : INT := 30000;
  wide : DINT;
END_VAR
wide := a + b;
END_PROGRAM
)";
  // CODESYS computes INT + INT in 32-bit registers: the DINT receives 60000.
  auto codesys = run_text(source);
  ASSERT_CLEAN(codesys);
  EXPECT_EQ(codesys->text("wide"), "60000");
  // IEC 61131-3: INT + INT is an INT and wraps before the widening assignment.
  RunOptions iec;
  iec.profile = project::Profile::Iec;
  auto strict = run_text(R"(
PROGRAM Main
VAR
  a : INT := 30000;
  b : INT := 30000;
  wide : DINT;
END_VAR
wide := INT_TO_DINT(a + b);
END_PROGRAM
)", iec);
  ASSERT_CLEAN(strict);
  EXPECT_EQ(strict->text("wide"), "-5536");
}

TEST(RunExpressions, DivisionTruncatesTowardZeroAndModKeepsTheDividendsSign) {
  auto run = run_text(R"(
PROGRAM Main
VAR
  q1, q2, m1, m2 : INT;
  r : REAL;
END_VAR
q1 := 7 / 2;
q2 := -7 / 2;
m1 := 44 MOD 9;
m2 := -7 MOD 2;
r := 7.0 / 2.0;
END_PROGRAM
)");
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("q1"), "3");
  EXPECT_EQ(run->text("q2"), "-3");
  EXPECT_EQ(run->text("m1"), "8");  // OpenPCS manual: 44 MOD 9 = 8
  EXPECT_EQ(run->text("m2"), "-1");
  EXPECT_EQ(run->text("r"), "3.5");
}

TEST(RunExpressions, RealToIntRoundsHalfAwayFromZero) {
  // CODESYS V3 textbook, conversions: REAL_TO_INT rounds to the nearest integer, .5 away from 0.
  auto run = run_text(R"(
PROGRAM Main
VAR
  a, b, c, d, t : INT;
END_VAR
a := REAL_TO_INT(2.5);
b := REAL_TO_INT(-2.5);
c := REAL_TO_INT(1.4);
d := REAL_TO_INT(-1.6);
t := TRUNC(-1.6);
END_PROGRAM
)");
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("a"), "3");
  EXPECT_EQ(run->text("b"), "-3");
  EXPECT_EQ(run->text("c"), "1");
  EXPECT_EQ(run->text("d"), "-2");
  EXPECT_EQ(run->text("t"), "-1");
}

TEST(RunExpressions, ConversionsKeepTheLowBitsWhenNarrowing) {
  // IEC conversions: INT_TO_SINT(4223) keeps the low-order 8 bits = 127.
  auto run = run_text(R"(
PROGRAM Main
VAR
  s : SINT;
  w : WORD;
  i : INT;
  b : BOOL;
  r : REAL;
END_VAR
s := INT_TO_SINT(4223);
w := INT_TO_WORD(-1);
i := WORD_TO_INT(16#FFFF);
b := INT_TO_BOOL(5);
r := INT_TO_REAL(-3);
END_PROGRAM
)");
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("s"), "127");
  EXPECT_EQ(run->text("w"), "65535");
  EXPECT_EQ(run->text("i"), "-1");
  EXPECT_EQ(run->text("b"), "TRUE");
  EXPECT_EQ(run->text("r"), "-3");
}

TEST(RunExpressions, ShiftsAndRotatesUseTheWidthOfTheInputType) {
  auto run = run_text(R"(
PROGRAM Main
VAR
  a, b, c, d : BYTE;
  w : WORD;
END_VAR
a := SHL(BYTE#16#81, 1);
b := ROL(BYTE#16#81, 1);
c := ROR(BYTE#16#81, 1);
d := SHR(BYTE#16#81, 4);
w := ROL(WORD#16#8001, 4);
END_PROGRAM
)");
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("a"), "2");
  EXPECT_EQ(run->text("b"), "3");
  EXPECT_EQ(run->text("c"), "192");
  EXPECT_EQ(run->text("d"), "8");
  EXPECT_EQ(run->text("w"), "24");
}

TEST(RunExpressions, ShrOfASignedIntegerIsArithmetic) {
  // CODESYS V3 textbook, example 5.37: SHR on an INT fills with the sign bit (16#F100 -> 16#FF10);
  // a count at or beyond the width leaves only sign bits.
  auto run = run_text(R"(
PROGRAM Main
VAR
  i, big, pos : INT;
  s : SINT;
  d : DINT;
  iIn : INT := -3840;
  iPos : INT := 16384;
  sIn : SINT := -128;
  dIn : DINT := -8;
END_VAR
i := SHR(iIn, 4);
big := SHR(iIn, 40);
pos := SHR(iPos, 2);
s := SHR(sIn, 7);
d := SHR(dIn, 1);
END_PROGRAM
)");
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("i"), "-240");
  EXPECT_EQ(run->text("big"), "-1");
  EXPECT_EQ(run->text("pos"), "4096");
  EXPECT_EQ(run->text("s"), "-1");
  EXPECT_EQ(run->text("d"), "-4");
}

TEST(RunExpressions, SignedTypedLiterals) {
  auto run = run_text(R"(
PROGRAM Main
VAR
  x, y : INT;
  z : DINT;
END_VAR
x := INT#-3840;
y := SHR(INT#-3840, 4);
z := DINT#-5 + 1;
END_PROGRAM
)");
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("x"), "-3840");
  EXPECT_EQ(run->text("y"), "-240");
  EXPECT_EQ(run->text("z"), "-4");
}

TEST(RunExpressions, BooleanLogicAndComparisons) {
  auto run = run_text(R"(
PROGRAM Main
VAR
  x : BOOL := TRUE;
  y : BOOL;
  a, b, c, d : BOOL;
  n : INT := -5;
  u : UDINT := 4000000000;
END_VAR
a := x AND NOT y;
b := x XOR TRUE;
c := n < 0 AND u > 3000000000;
d := (n >= -5) = TRUE;
END_PROGRAM
)");
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("a"), "TRUE");
  EXPECT_EQ(run->text("b"), "FALSE");
  EXPECT_EQ(run->text("c"), "TRUE");
  EXPECT_EQ(run->text("d"), "TRUE");
}

TEST(RunExpressions, SelectionFunctions) {
  auto run = run_text(R"(
PROGRAM Main
VAR
  s, m, l, x, n : INT;
  r : REAL;
END_VAR
s := SEL(TRUE, 1, 2);
m := MUX(2, 10, 20, 30);
l := LIMIT(0, 150, 100);
x := MAX(3, 9, 4);
n := MIN(3, -9, 4);
r := MAX(1.5, 2.5);
END_PROGRAM
)");
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("s"), "2");
  EXPECT_EQ(run->text("m"), "30");
  EXPECT_EQ(run->text("l"), "100");
  EXPECT_EQ(run->text("x"), "9");
  EXPECT_EQ(run->text("n"), "-9");
  EXPECT_EQ(run->text("r"), "2.5");
}

TEST(RunStatements, LoopsExitAndContinue) {
  // CODESYS V3 textbook, FOR/EXIT/CONTINUE examples.
  auto run = run_text(R"(
PROGRAM Main
VAR
  i, sum, evens, j, k : INT;
  arr : ARRAY[1..10] OF INT := [1, 2, 3, 70, 5, 6, 7, 8, 9, 10];
  found : INT := 101;
END_VAR
sum := 0;
FOR i := 1 TO 10 DO
  sum := sum + i;
END_FOR
FOR i := 10 TO 1 BY -2 DO
  IF i MOD 4 = 0 THEN CONTINUE; END_IF
  evens := evens + i;
END_FOR
FOR i := 1 TO 10 DO
  IF arr[i] = 70 THEN found := i; EXIT; END_IF
END_FOR
j := 1;
WHILE j < 100 DO j := j * 2; END_WHILE
REPEAT k := k + 3; UNTIL k > 10 END_REPEAT
END_PROGRAM
)");
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("sum"), "55");
  EXPECT_EQ(run->text("evens"), "18");  // 10 + 6 + 2: 8 and 4 are skipped
  EXPECT_EQ(run->text("found"), "4");
  EXPECT_EQ(run->text("j"), "128");
  EXPECT_EQ(run->text("k"), "12");
}

TEST(RunStatements, CaseWithListsRangesAndElse) {
  auto run = run_text(R"(
PROGRAM Main
VAR
  a, b, c, d : INT;
  sel : INT;
END_VAR
FOR sel := 1 TO 4 DO
  CASE sel * 5 OF
    5, 10: a := a + 1;
    11..15: b := sel;
  ELSE
    c := c + 1;
  END_CASE
END_FOR
CASE 99 OF 1: d := 1; END_CASE
END_PROGRAM
)");
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("a"), "2");
  EXPECT_EQ(run->text("b"), "3");
  EXPECT_EQ(run->text("c"), "1");
  EXPECT_EQ(run->text("d"), "0");
}

TEST(RunStatements, JumpsAndReturn) {
  auto run = run_text(R"(
FUNCTION Clamp : INT
VAR_INPUT x : INT; END_VAR
IF x > 10 THEN
  Clamp := 10;
  RETURN;
END_IF
Clamp := x;
END_FUNCTION

PROGRAM Main
VAR
  n, a, b : INT;
END_VAR
a := Clamp(50);
b := Clamp(3);
start:
n := n + 1;
IF n < 5 THEN JMP start; END_IF
END_PROGRAM
)");
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("a"), "10");
  EXPECT_EQ(run->text("b"), "3");
  EXPECT_EQ(run->text("n"), "5");
}

TEST(RunStatements, StateIsKeptAcrossCycles) {
  auto run = run_text(R"(
PROGRAM Main
VAR
  count : INT;
END_VAR
VAR_TEMP
  scratch : INT := 7;
END_VAR
scratch := scratch + 1;
count := count + scratch;
END_PROGRAM
)", {.cycles = 3});
  ASSERT_CLEAN(run);
  // VAR_TEMP starts from its initial value on every call.
  EXPECT_EQ(run->text("count"), "24");
}

TEST(RunErrors, DivisionByZeroStopsTheRunWithItsPlace) {
  auto run = run_text(R"(
PROGRAM Main
VAR
  zero : INT;
  x : INT;
END_VAR
x := 10 / zero;
END_PROGRAM
)");
  ASSERT_TRUE(run->check_errors.empty()) << joined(run->check_errors);
  ASSERT_TRUE(run->engine);
  EXPECT_EQ(run->error(), "division by zero");
  const std::string described = describe_error(run->project, *run->engine->machine().error());
  EXPECT_NE(described.find("main.st:7:"), std::string::npos) << described;
}

TEST(RunErrors, IndexOutOfBounds) {
  auto run = run_text(R"(
PROGRAM Main
VAR
  a : ARRAY[1..3] OF INT;
  i : INT := 4;
END_VAR
a[i] := 1;
END_PROGRAM
)");
  ASSERT_TRUE(run->engine);
  EXPECT_EQ(run->error(), "array index 4 is outside 1..3");
}

TEST(RunErrors, EndlessLoopTripsTheWatchdog) {
  auto run = run_text(R"(
PROGRAM Main
VAR
  x : BOOL := TRUE;
  n : DINT;
END_VAR
WHILE x DO n := n + 1; END_WHILE
END_PROGRAM
)", {.cycles = 0});
  ASSERT_TRUE(run->engine);
  run->engine->machine().set_loop_budget(1000);
  EXPECT_FALSE(run->cycles(1));
  EXPECT_NE(run->error().find("watchdog"), std::string::npos) << run->error();
}

TEST(RunErrors, NullPointerDereference) {
  auto run = run_text(R"(
PROGRAM Main
VAR
  p : POINTER TO INT;
  x : INT;
END_VAR
x := p^;
END_PROGRAM
)");
  ASSERT_TRUE(run->engine);
  EXPECT_EQ(run->error(), "null pointer dereference");
}

}  // namespace
}  // namespace rung::run::testing
