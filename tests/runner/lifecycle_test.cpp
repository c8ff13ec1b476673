// FB_init / FB_exit and computed initial values of FB instances, ARRAY[*] parameters with
// LOWER_BOUND / UPPER_BOUND, and the implicit checks CheckRangeSigned/Unsigned and CheckPointer.
#include <gtest/gtest.h>

#include "tests/runner/run_support.hpp"

namespace rung::run::testing {
namespace {

constexpr std::string_view kAxis = R"(
FUNCTION_BLOCK FB_Base
VAR_OUTPUT
  log : STRING(80);
END_VAR
METHOD FB_init : BOOL
VAR_INPUT
  bInitRetains : BOOL;
  bInCopyCode : BOOL;
END_VAR
log := CONCAT(log, 'base;');
END_METHOD
METHOD FB_exit : BOOL
VAR_INPUT
  bInCopyCode : BOOL;
END_VAR
gExits := CONCAT(gExits, 'base;');
END_METHOD
END_FUNCTION_BLOCK

FUNCTION_BLOCK FB_Axis EXTENDS FB_Base
VAR_OUTPUT
  id : INT;
  retains : BOOL;
  copy : BOOL := TRUE;
  calls : INT;
END_VAR
METHOD FB_init : BOOL
VAR_INPUT
  bInitRetains : BOOL;
  bInCopyCode : BOOL;
  nId : INT;
END_VAR
id := nId;
retains := bInitRetains;
copy := bInCopyCode;
log := CONCAT(log, 'axis;');
END_METHOD
METHOD FB_exit : BOOL
VAR_INPUT
  bInCopyCode : BOOL;
END_VAR
gExits := CONCAT(gExits, 'axis;');
END_METHOD
calls := calls + 1;
END_FUNCTION_BLOCK

VAR_GLOBAL
  gExits : STRING(200);
END_VAR
)";

TEST(RunLifecycle, FbInitRunsBeforeTheFirstCycleBaseFirstWithTheDeclarationsArguments) {
  // TwinCAT PLC manual, FB_init with derived function blocks: the base's FB_init runs first, then
  // the derived one; a first download passes bInitRetains TRUE and bInCopyCode FALSE (CODESYS
  // help, "First download").
  auto run = run_text(std::string(kAxis) + R"(
PROGRAM PLC_PRG
VAR
  axis1 : FB_Axis(nId := 7);
  axes : ARRAY[1..2] OF FB_Axis[(nId := 11), (nId := 12)];
END_VAR
axis1();
END_PROGRAM
)");
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("PLC_PRG.axis1.id"), "7");
  EXPECT_EQ(run->text("PLC_PRG.axis1.log"), "'base;axis;'");
  EXPECT_EQ(run->text("PLC_PRG.axis1.retains"), "TRUE");
  EXPECT_EQ(run->text("PLC_PRG.axis1.copy"), "FALSE");
  EXPECT_EQ(run->text("PLC_PRG.axis1.calls"), "1");
  EXPECT_EQ(run->text("PLC_PRG.axes[1].id"), "11");
  EXPECT_EQ(run->text("PLC_PRG.axes[2].id"), "12");
  EXPECT_EQ(run->text("PLC_PRG.axes[2].log"), "'base;axis;'");
  // Once, not per cycle.
  ASSERT_TRUE(run->cycles(3));
  EXPECT_EQ(run->text("PLC_PRG.axis1.log"), "'base;axis;'");
  EXPECT_EQ(run->text("PLC_PRG.axis1.calls"), "4");
}

TEST(RunLifecycle, FbExitRunsWhenTheRunEndsDerivedFirst) {
  // TwinCAT PLC manual: FB_exit of the derived block first, then the base's.
  auto run = run_text(std::string(kAxis) + R"(
PROGRAM PLC_PRG
VAR
  axis1 : FB_Axis(nId := 1);
  axis2 : FB_Axis(nId := 2);
END_VAR
axis1();
END_PROGRAM
)");
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("gExits"), "''");
  ASSERT_TRUE(run->engine->finish());
  // The last declared instance first.
  EXPECT_EQ(run->text("gExits"), "'axis;base;axis;base;'");
  ASSERT_TRUE(run->engine->finish());  // once
  EXPECT_EQ(run->text("gExits"), "'axis;base;axis;base;'");
}

TEST(RunLifecycle, MemberInstancesAreBuiltBeforeTheirContainersFbInit) {
  auto run = run_text(R"(
FUNCTION_BLOCK FB_Counter
VAR_OUTPUT
  start : INT;
END_VAR
METHOD FB_init : BOOL
VAR_INPUT
  bInitRetains : BOOL;
  bInCopyCode : BOOL;
  nStart : INT;
END_VAR
start := nStart;
END_METHOD
END_FUNCTION_BLOCK

FUNCTION_BLOCK FB_Station
VAR
  counter : FB_Counter(nStart := 40);
END_VAR
VAR_OUTPUT
  seen : INT;
END_VAR
METHOD FB_init : BOOL
VAR_INPUT
  bInitRetains : BOOL;
  bInCopyCode : BOOL;
END_VAR
seen := counter.start + 2;
END_METHOD
END_FUNCTION_BLOCK

PROGRAM PLC_PRG
VAR
  station : FB_Station;
END_VAR
END_PROGRAM
)");
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("PLC_PRG.station.seen"), "42");
}

TEST(RunLifecycle, ComputedInitialValuesOfFbInstancesAndArgumentsAsInputs) {
  // An FB variable initialised with ADR() of another member, per instance; an FB without FB_init
  // takes the declaration's arguments as input values (TON(PT := T#1S)).
  auto run = run_text(R"(
FUNCTION_BLOCK FB_Buffer
VAR
  data : ARRAY[0..3] OF INT := [1, 2, 3, 4];
  pData : POINTER TO INT := ADR(data[2]);
END_VAR
VAR_OUTPUT
  third : INT;
END_VAR
third := pData^;
END_FUNCTION_BLOCK

PROGRAM PLC_PRG
VAR
  a, b : FB_Buffer;
  t : TON(PT := T#1S);
  third : INT;
END_VAR
b.data[2] := 30;
a();
b();
END_PROGRAM
)");
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("PLC_PRG.a.third"), "3");
  EXPECT_EQ(run->text("PLC_PRG.b.third"), "30");  // b's pointer points into b
  EXPECT_EQ(run->text("PLC_PRG.t.PT"), "T#1s");
}

TEST(RunLifecycle, NewCallsFbInitAndDeleteCallsFbExit) {
  auto run = run_text(std::string(kAxis) + R"(
PROGRAM PLC_PRG
VAR
  p : POINTER TO FB_Axis;
  log : STRING(80);
  done : BOOL;
END_VAR
IF NOT done THEN
  p := __NEW(FB_Axis);
  log := p^.log;
  __DELETE(p);
  done := TRUE;
END_IF
END_PROGRAM
)");
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("PLC_PRG.log"), "'base;axis;'");
  EXPECT_EQ(run->text("gExits"), "'axis;base;'");
}

TEST(RunLifecycle, InstancesInArraysAndBehindPointersAreCalled) {
  // timers[i](...) and pFb^(...): the instance is an element or a dereference, not a name.
  auto run = run_text(R"(
PROGRAM PLC_PRG
VAR
  timers : ARRAY[1..3] OF TON;
  counters : ARRAY[0..1] OF CTU;
  pCounter : POINTER TO CTU;
  i : INT;
  done : INT;
END_VAR
done := 0;
FOR i := 1 TO 3 DO
  timers[i](IN := TRUE, PT := INT_TO_TIME(i * 20));
  IF timers[i].Q THEN
    done := done + 1;
  END_IF
END_FOR
pCounter := ADR(counters[1]);
pCounter^(CU := NOT pCounter^.CU, PV := 100);
END_PROGRAM
)",
                      {.cycles = 5});
  ASSERT_CLEAN(run);
  // Cycle 5 is at T#40ms: timers 1 (20 ms) and 2 (40 ms) have elapsed, timer 3 (60 ms) not.
  EXPECT_EQ(run->text("done"), "2");
  EXPECT_EQ(run->text("timers[2].ET"), "T#40ms");
  EXPECT_EQ(run->text("counters[1].CV"), "3");
  EXPECT_EQ(run->text("counters[0].CV"), "0");
}

TEST(RunOpenArrays, ArrayStarInOutsIndexWithTheCallersBounds) {
  // CODESYS V3: ARRAY[*] in VAR_IN_OUT takes arrays of any bounds; LOWER_BOUND/UPPER_BOUND give
  // them (dimension from 1).
  auto run = run_text(R"(
FUNCTION SumOf : DINT
VAR_IN_OUT
  values : ARRAY[*] OF INT;
END_VAR
VAR
  i : DINT;
END_VAR
FOR i := LOWER_BOUND(values, 1) TO UPPER_BOUND(values, 1) DO
  SumOf := SumOf + values[i];
END_FOR
END_FUNCTION

FUNCTION_BLOCK FB_Grid
VAR_IN_OUT
  cells : ARRAY[*, *] OF INT;
END_VAR
VAR_OUTPUT
  corner : INT;
  rows, columns : DINT;
END_VAR
rows := UPPER_BOUND(cells, 1) - LOWER_BOUND(cells, 1) + 1;
columns := UPPER_BOUND(cells, 2) - LOWER_BOUND(cells, 2) + 1;
corner := cells[UPPER_BOUND(cells, 1), UPPER_BOUND(cells, 2)];
cells[LOWER_BOUND(cells, 1), LOWER_BOUND(cells, 2)] := 99;
END_FUNCTION_BLOCK

FUNCTION Forward : DINT
VAR_IN_OUT
  values : ARRAY[*] OF INT;
END_VAR
Forward := SumOf(values);
END_FUNCTION

PROGRAM PLC_PRG
VAR
  small : ARRAY[1..3] OF INT := [1, 2, 3];
  shifted : ARRAY[-2..2] OF INT := [10, 20, 30, 40, 50];
  grid : ARRAY[0..1, 5..7] OF INT := [1, 2, 3, 4, 5, 6];
  g : FB_Grid;
  s1, s2, s3 : DINT;
  lowerFixed : DINT;
END_VAR
s1 := SumOf(small);
s2 := SumOf(shifted);
s3 := Forward(shifted);
g(cells := grid);
lowerFixed := LOWER_BOUND(shifted, 1);
END_PROGRAM
)");
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("PLC_PRG.s1"), "6");
  EXPECT_EQ(run->text("PLC_PRG.s2"), "150");
  EXPECT_EQ(run->text("PLC_PRG.s3"), "150");
  EXPECT_EQ(run->text("PLC_PRG.g.rows"), "2");
  EXPECT_EQ(run->text("PLC_PRG.g.columns"), "3");
  EXPECT_EQ(run->text("PLC_PRG.g.corner"), "6");
  EXPECT_EQ(run->text("PLC_PRG.grid[0, 5]"), "99");
  EXPECT_EQ(run->text("PLC_PRG.lowerFixed"), "-2");
}

TEST(RunOpenArrays, AnIndexOutsideTheCallersBoundsStopsTheRun) {
  auto run = run_text(R"(
FUNCTION Pick : INT
VAR_IN_OUT
  values : ARRAY[*] OF INT;
END_VAR
VAR_INPUT
  i : DINT;
END_VAR
Pick := values[i];
END_FUNCTION

PROGRAM PLC_PRG
VAR
  a : ARRAY[1..3] OF INT;
  x : INT;
END_VAR
x := Pick(a, 4);
END_PROGRAM
)");
  ASSERT_TRUE(run->check_errors.empty()) << joined(run->check_errors);
  ASSERT_TRUE(run->compile_errors.empty()) << joined(run->compile_errors);
  EXPECT_EQ(run->error(), "array index 4 is outside 1..3");
}

TEST(RunChecks, CheckRangeSignedLimitsAssignmentsToSubranges) {
  // CODESYS help, POUs for implicit checks: CheckRangeSigned is called on assignments to a
  // variable of a signed subrange type; the value stored is its result.
  auto run = run_text(R"(
FUNCTION CheckRangeSigned : DINT
VAR_INPUT
  value, lower, upper : DINT;
END_VAR
IF value < lower THEN
  CheckRangeSigned := lower;
ELSIF value > upper THEN
  CheckRangeSigned := upper;
ELSE
  CheckRangeSigned := value;
END_IF
END_FUNCTION

FUNCTION CheckRangeUnsigned : UDINT
VAR_INPUT
  value, lower, upper : UDINT;
END_VAR
IF value > upper THEN
  CheckRangeUnsigned := upper;
ELSE
  CheckRangeUnsigned := value;
END_IF
END_FUNCTION

FUNCTION_BLOCK FB_Valve
VAR_INPUT
  percent : INT(0..100);
END_VAR
END_FUNCTION_BLOCK

PROGRAM PLC_PRG
VAR
  small : INT(-10..10);
  level : UINT(0..500);
  plain : INT;
  v : FB_Valve;
  big : INT := 25;
  bigger : UINT := 900;
  much : INT := 130;
END_VAR
small := big;
level := bigger;
plain := big;
v(percent := much);
END_PROGRAM
)");
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("PLC_PRG.small"), "10");
  EXPECT_EQ(run->text("PLC_PRG.level"), "500");
  EXPECT_EQ(run->text("PLC_PRG.plain"), "25");
  EXPECT_EQ(run->text("PLC_PRG.v.percent"), "100");
}

TEST(RunChecks, CheckPointerSeesEveryDereferenceWithSizeAndAccess) {
  // CODESYS help, POU CheckPointer: called on every dereference with the target's size, its
  // largest elementary type and whether it writes; the pointer used is its result.
  auto run = run_text(R"(
TYPE ST_Pair :
STRUCT
  a : INT;
  b : LREAL;
END_STRUCT
END_TYPE

FUNCTION CheckPointer : POINTER TO BYTE
VAR_INPUT
  ptToTest : POINTER TO BYTE;
  iSize : DINT;
  iGran : DINT;
  bWrite : BOOL;
END_VAR
gCalls := gCalls + 1;
gLastSize := iSize;
gLastGran := iGran;
gLastWrite := bWrite;
IF ptToTest = 0 THEN
  CheckPointer := ADR(gSpare);
ELSE
  CheckPointer := ptToTest;
END_IF
END_FUNCTION

VAR_GLOBAL
  gCalls : INT;
  gLastSize, gLastGran : DINT;
  gLastWrite : BOOL;
  gSpare : ST_Pair;
END_VAR

PROGRAM PLC_PRG
VAR
  pair : ST_Pair;
  p : POINTER TO ST_Pair;
  pNull : POINTER TO ST_Pair;
  x : LREAL;
  readSize, readGran : DINT;
  readWrite : BOOL;
END_VAR
p := ADR(pair);
x := p^.b;
readSize := gLastSize;
readGran := gLastGran;
readWrite := gLastWrite;
p^.a := 5;
pNull^.a := 7;
END_PROGRAM
)");
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("gCalls"), "3");
  EXPECT_EQ(run->text("PLC_PRG.readSize"), "16");
  EXPECT_EQ(run->text("PLC_PRG.readGran"), "8");
  EXPECT_EQ(run->text("PLC_PRG.readWrite"), "FALSE");
  EXPECT_EQ(run->text("gLastWrite"), "TRUE");
  EXPECT_EQ(run->text("PLC_PRG.pair.a"), "5");
  EXPECT_EQ(run->text("gSpare.a"), "7");  // the NULL write went where CheckPointer said
}

TEST(RunChecks, CheckPointerSeesReferenceAccessesToo) {
  // CODESYS help, POU CheckPointer: from compiler 3.5.7.40 on, REFERENCE variables are checked as
  // pointers are.
  auto run = run_text(R"(
FUNCTION CheckPointer : POINTER TO BYTE
VAR_INPUT
  ptToTest : POINTER TO BYTE;
  iSize : DINT;
  iGran : DINT;
  bWrite : BOOL;
END_VAR
gCalls := gCalls + 1;
gLastSize := iSize;
gLastWrite := bWrite;
CheckPointer := ptToTest;
END_FUNCTION

VAR_GLOBAL
  gCalls : INT;
  gLastSize : DINT;
  gLastWrite : BOOL;
END_VAR

PROGRAM PLC_PRG
VAR
  target : LREAL := 2.5;
  r : REFERENCE TO LREAL REF= target;
  x : LREAL;
  readCalls : INT;
END_VAR
x := r;
readCalls := gCalls;
r := 4.0;
END_PROGRAM
)");
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("PLC_PRG.x"), "2.5");
  EXPECT_EQ(run->text("PLC_PRG.readCalls"), "1");
  EXPECT_EQ(run->text("gCalls"), "2");
  EXPECT_EQ(run->text("gLastSize"), "8");
  EXPECT_EQ(run->text("gLastWrite"), "TRUE");
  EXPECT_EQ(run->text("PLC_PRG.target"), "4");
}

}  // namespace
}  // namespace rung::run::testing
