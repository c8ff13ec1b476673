// Strings, durations, structures, arrays, pointers and references: values in the flat memory.
#include <gtest/gtest.h>

#include "tests/runner/run_support.hpp"

namespace rung::run::testing {
namespace {

TEST(RunStrings, StandardStringFunctions) {
  // CODESYS Standard library: INSERT('SUSI','XY',2)='SUXYSI', DELETE('SUXYSI',2,3)='SUSI',
  // REPLACE('SUXYSI','K',2,2)='SKYSI', FIND('SUXYSI','XY')=3; textbook: INSERT('CoDe','Sys',2).
  auto run = run_text(R"(
PROGRAM Main
VAR
  ins, ins2, del, rep, cat, l, r, m, rot : STRING;
  pos, len1 : INT;
  s : STRING := 'abcd';
END_VAR
ins := INSERT('SUSI', 'XY', 2);
ins2 := INSERT(IN1 := 'CoDe', IN2 := 'Sys', P := 2);
del := DELETE('SUXYSI', 2, 3);
rep := REPLACE('SUXYSI', 'K', 2, 2);
pos := FIND('SUXYSI', 'XY');
cat := CONCAT('hallo', 'world', '!');
l := LEFT('abcdef', 2);
r := RIGHT('abc', LEN('abc') - 1);
m := MID('abcdef', 3, 2);
len1 := LEN('');
s := CONCAT(RIGHT(s, LEN(s) - 1), LEFT(s, 1));
END_PROGRAM
)");
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("ins"), "'SUXYSI'");
  EXPECT_EQ(run->text("ins2"), "'CoSysDe'");
  EXPECT_EQ(run->text("del"), "'SUSI'");
  EXPECT_EQ(run->text("rep"), "'SKYSI'");
  EXPECT_EQ(run->text("pos"), "3");
  EXPECT_EQ(run->text("cat"), "'halloworld!'");
  EXPECT_EQ(run->text("l"), "'ab'");
  EXPECT_EQ(run->text("r"), "'bc'");
  EXPECT_EQ(run->text("m"), "'bcd'");
  EXPECT_EQ(run->text("len1"), "0");
  EXPECT_EQ(run->text("s"), "'bcda'");  // textbook: rotate left by one character
}

TEST(RunStrings, AssignmentTruncatesToTheCapacity) {
  auto run = run_text(R"(
PROGRAM Main
VAR
  short : STRING(5);
  copy : STRING(5);
  equal, less : BOOL;
  n : INT;
  text : STRING;
END_VAR
short := 'abcdefgh';
copy := short;
equal := short = 'abcde';
less := 'abc' < 'abd';
n := STRING_TO_INT('123');
text := INT_TO_STRING(-42);
END_PROGRAM
)");
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("short"), "'abcde'");
  EXPECT_EQ(run->text("copy"), "'abcde'");
  EXPECT_EQ(run->text("equal"), "TRUE");
  EXPECT_EQ(run->text("less"), "TRUE");
  EXPECT_EQ(run->text("n"), "123");
  EXPECT_EQ(run->text("text"), "'-42'");
}

TEST(RunTime, DurationArithmeticAndConversions) {
  // IEC ADD/SUB on durations: T#45s + T#50s = T#1m35s.
  auto run = run_text(R"(
PROGRAM Main
VAR
  a, b, c, d : TIME;
  ms : DINT;
  lt : LTIME;
  later : TOD;
  day : DATE;
  stamp : DT := DT#2024-02-28-23:59:30;
END_VAR
a := T#45s + T#50s;
b := T#1m35s - T#50s;
c := T#2s * 3;
d := DINT_TO_TIME(1500);
ms := TIME_TO_DINT(T#1m);
lt := TIME_TO_LTIME(T#2ms);
later := TOD#12:00:00 + T#90m;
day := DT_TO_DATE(stamp + T#1m);
END_PROGRAM
)");
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("a"), "T#1m35s");
  EXPECT_EQ(run->text("b"), "T#45s");
  EXPECT_EQ(run->text("c"), "T#6s");
  EXPECT_EQ(run->text("d"), "T#1s500ms");
  EXPECT_EQ(run->text("ms"), "60000");
  EXPECT_EQ(run->text("lt"), "LTIME#2ms");
  EXPECT_EQ(run->text("later"), "TOD#13:30:00");
  EXPECT_EQ(run->text("day"), "D#2024-02-29");
}

TEST(RunData, StructuresArraysAndInitialValues) {
  auto run = run_text(R"(
TYPE Point : STRUCT
  x : INT := 1;
  y : INT := 2;
END_STRUCT
END_TYPE
TYPE Color : (Red, Green := 5, Blue) := Blue;
END_TYPE
PROGRAM Main
VAR
  p : Point;
  q : Point := (y := 20);
  grid : ARRAY[1..2, 1..3] OF INT := [1, 2, 3, 4, 5, 6];
  rep : ARRAY[0..5] OF INT := [2(7), 3(9)];
  pts : ARRAY[1..2] OF Point;
  c : Color;
  g : Color := Color.Green;
  corner, sum : INT;
  i, j : INT;
END_VAR
pts[2] := q;
pts[2].x := pts[2].x + 10;
corner := grid[2, 3];
FOR i := 1 TO 2 DO
  FOR j := 1 TO 3 DO
    sum := sum + grid[i, j];
  END_FOR
END_FOR
END_PROGRAM
)");
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("p"), "(x := 1, y := 2)");
  EXPECT_EQ(run->text("q"), "(x := 1, y := 20)");
  EXPECT_EQ(run->text("pts[2].x"), "11");
  EXPECT_EQ(run->text("corner"), "6");
  EXPECT_EQ(run->text("sum"), "21");
  EXPECT_EQ(run->text("rep"), "[7, 7, 9, 9, 9, 0]");
  EXPECT_EQ(run->text("c"), "Blue");
  EXPECT_EQ(run->text("g"), "Green");
}

TEST(RunData, PointersReferencesAndUnions) {
  // CODESYS V3 textbook: ADR and ^; a pointer stepped byte by byte over an INT; REFERENCE TO.
  auto run = run_text(R"(
TYPE Word2 : UNION
  w : WORD;
  b : ARRAY[0..1] OF BYTE;
END_UNION
END_TYPE
PROGRAM Main
VAR
  x : INT := 5;
  p : POINTER TO INT;
  pb : POINTER TO BYTE;
  low, high : BYTE;
  r : REFERENCE TO INT;
  u : Word2;
  valid : BOOL;
  size : UDINT;
END_VAR
p := ADR(x);
p^ := p^ * 2;
x := x + 16#100;
pb := ADR(x);
low := pb^;
pb := pb + 1;
high := pb^;
r REF= x;
r := r + 1;
valid := __ISVALIDREF(r);
u.w := 16#1234;
size := SIZEOF(u);
END_PROGRAM
)");
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("x"), "267");
  EXPECT_EQ(run->text("low"), "10");
  EXPECT_EQ(run->text("high"), "1");
  EXPECT_EQ(run->text("valid"), "TRUE");
  EXPECT_EQ(run->text("u.b"), "[52, 18]");
  EXPECT_EQ(run->text("size"), "2");
}

TEST(RunData, BitAccess) {
  auto run = run_text(R"(
PROGRAM Main
VAR
  w : WORD := 16#00F0;
  b3, b4 : BOOL;
END_VAR
b3 := w.3;
b4 := w.4;
w.0 := TRUE;
w.7 := FALSE;
END_PROGRAM
)");
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("b3"), "FALSE");
  EXPECT_EQ(run->text("b4"), "TRUE");
  EXPECT_EQ(run->text("w"), "113");
}

TEST(RunData, GlobalsAreInitialisedBeforePrograms) {
  auto run = run_files({{"globals.st", R"(
VAR_GLOBAL
  gLimit : INT := 40;
  gCount : INT;
END_VAR
)"},
                        {"main.st", R"(
PROGRAM Main
gCount := gCount + gLimit;
END_PROGRAM
)"}},
                       {.cycles = 2});
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("gCount"), "80");
}

}  // namespace
}  // namespace rung::run::testing
