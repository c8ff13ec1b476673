// POUs: functions, function blocks (state, formal and informal calls, outputs), programs calling
// programs, methods, properties, interfaces with dynamic dispatch, inheritance, actions.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "tests/runner/run_support.hpp"
#include "tests/support/test_paths.hpp"

namespace rung::run::testing {
namespace {

TEST(RunPous, FunctionBlockKeepsItsStateBetweenCalls) {
  // CODESYS V3 textbook example 2.4: FB_Counter, level-triggered, reset evaluated last.
  auto run = run_text(R"(
FUNCTION_BLOCK FB_Counter
VAR_INPUT
  bUp : BOOL;
  bDown : BOOL;
  bReset : BOOL;
END_VAR
VAR_OUTPUT
  nValue : INT;
END_VAR
IF bUp THEN nValue := nValue + 1; END_IF
IF bDown THEN nValue := nValue - 1; END_IF
IF bReset THEN nValue := 0; END_IF
END_FUNCTION_BLOCK

PROGRAM Main
VAR
  counter : FB_Counter;
  other : FB_Counter;
  up : BOOL := TRUE;
  value, second : INT;
END_VAR
counter(bUp := up, nValue => value);
other(TRUE, FALSE, FALSE);
second := other.nValue;
END_PROGRAM
)", {.cycles = 3});
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("value"), "3");
  EXPECT_EQ(run->text("second"), "3");
  run->set("counter.bReset", "TRUE");
  run->cycles(1);
  EXPECT_EQ(run->text("value"), "0");
}

TEST(RunPous, FunctionsWithOutputsInOutsAndStructuredResults) {
  auto run = run_text(R"(
TYPE Pair : STRUCT a, b : INT; END_STRUCT END_TYPE

FUNCTION Swap : BOOL
VAR_IN_OUT x, y : INT; END_VAR
VAR tmp : INT; END_VAR
tmp := x; x := y; y := tmp;
Swap := TRUE;
END_FUNCTION

FUNCTION MakePair : Pair
VAR_INPUT a, b : INT; END_VAR
MakePair.a := a;
MakePair.b := b;
END_FUNCTION

FUNCTION Divide : INT
VAR_INPUT n, d : INT; END_VAR
VAR_OUTPUT rest : INT; END_VAR
Divide := n / d;
rest := n MOD d;
END_FUNCTION

FUNCTION Greeting : STRING
VAR_INPUT name : STRING; END_VAR
Greeting := CONCAT('hello ', name);
END_FUNCTION

PROGRAM Main
VAR
  p, q : INT;
  ok : BOOL;
  pair : Pair;
  quotient, remainder : INT;
  text : STRING;
END_VAR
p := 1; q := 2;
ok := Swap(p, q);
pair := MakePair(b := 4, a := 3);
quotient := Divide(17, 5, rest => remainder);
text := Greeting('PLC');
END_PROGRAM
)");
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("p"), "2");
  EXPECT_EQ(run->text("q"), "1");
  EXPECT_EQ(run->text("ok"), "TRUE");
  EXPECT_EQ(run->text("pair"), "(a := 3, b := 4)");
  EXPECT_EQ(run->text("quotient"), "3");
  EXPECT_EQ(run->text("remainder"), "2");
  EXPECT_EQ(run->text("text"), "'hello PLC'");
}

TEST(RunPous, NestedCallsUseAFramePerCall) {
  // A call in another call's arguments runs in its own frame, above the outer call's.
  auto run = run_text(R"(
FUNCTION Twice : DINT
VAR_INPUT n : DINT; END_VAR
VAR local : DINT; END_VAR
local := n;
Twice := local * 2;
END_FUNCTION

FUNCTION Sum3 : DINT
VAR_INPUT a, b, c : DINT; END_VAR
Sum3 := a + b + c;
END_FUNCTION

PROGRAM Main
VAR f : DINT; END_VAR
f := Sum3(Twice(1), Twice(Twice(2)), Sum3(1, 2, Twice(3)));
END_PROGRAM
)");
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("f"), "19");
}

TEST(RunPous, MethodsPropertiesInterfacesAndInheritance) {
  auto run = run_text(R"(
INTERFACE IShape
METHOD Area : REAL
END_METHOD
END_INTERFACE

FUNCTION_BLOCK Rect IMPLEMENTS IShape
VAR
  w, h : REAL;
END_VAR
METHOD Area : REAL
Area := w * h;
END_METHOD
METHOD Init
VAR_INPUT width, height : REAL; END_VAR
w := width;
h := height;
END_METHOD
PROPERTY Width : REAL
GET
  Width := w;
END_GET
SET
  w := Width;
END_SET
END_PROPERTY
END_FUNCTION_BLOCK

FUNCTION_BLOCK Square EXTENDS Rect
METHOD Area : REAL
Area := SUPER^.Area() + 1;
END_METHOD
END_FUNCTION_BLOCK

PROGRAM Main
VAR
  r : Rect;
  s : Square;
  shape : IShape;
  a1, a2, a3, width : REAL;
END_VAR
r.Init(2, 3);
s.Init(width := 4, height := 4);
shape := r;
a1 := shape.Area();
shape := s;
a2 := shape.Area();
r.Width := 10;
a3 := r.Area();
width := r.Width;
END_PROGRAM
)");
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("a1"), "6");
  EXPECT_EQ(run->text("a2"), "17");
  EXPECT_EQ(run->text("a3"), "30");
  EXPECT_EQ(run->text("width"), "10");
}

TEST(RunPous, ActionsAndProgramsCallingPrograms) {
  auto run = run_text(R"(
PROGRAM Helper
VAR_INPUT step : INT; END_VAR
VAR_OUTPUT total : INT; END_VAR
total := total + step;
END_PROGRAM

FUNCTION_BLOCK Machine
VAR count : INT; END_VAR
ACTION Bump:
count := count + 10;
END_ACTION
count := count + 1;
END_FUNCTION_BLOCK

PROGRAM Main
VAR
  m : Machine;
  seen, got : INT;
END_VAR
m();
m.Bump();
Helper(step := 5, total => got);
seen := Helper.total;
END_PROGRAM
)", {.program = "Main"});
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("m.count"), "11");
  EXPECT_EQ(run->text("got"), "5");
  EXPECT_EQ(run->text("seen"), "5");
}

// Every PROGRAM of the example projects runs without a run-time error.
TEST(RunPous, ExampleProjectRuns) {
  const std::filesystem::path main_file = rung::test::source_dir() / "examples" / "run" / "tank.st";
  std::ifstream in(main_file);
  ASSERT_TRUE(in) << main_file;
  std::stringstream text;
  text << in.rdbuf();
  auto run = run_text(text.str(), {.cycles = 200});
  ASSERT_CLEAN(run);
}

}  // namespace
}  // namespace rung::run::testing
