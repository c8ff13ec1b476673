// Instruction List bodies run: the current result (CR) through LD, ST, S, R, the logic,
// arithmetic and comparison operators with their N modifier, parentheses, jumps, CAL and RET with
// their C modifier, and functions called with the CR as first argument. The rules are IEC
// 61131-3 2nd ed. 3.2 (tables 51-53) as the CODESYS V2.3 manual states them (seed 002.md, IL,
// L253-365 and L7081-7746); examples of the manuals are read from the seed corpus.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "tests/runner/run_support.hpp"
#include "tests/support/test_paths.hpp"

namespace rung::run::testing {
namespace {

// A seed example of the manuals (../shared/corpus/seeds), or "" when the corpus is not there.
std::string seed(const std::string& relative) {
  std::ifstream in(rung::test::shared_dir() / "corpus" / "seeds" / relative);
  if (!in) return {};
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(RunIl, OperatorsApplyStrictlyLeftToRight) {
  // Seed 001/025 (CODESYS manual L4234-4243): LD 2 / MUL 2 / ADD 3 / ST ERG gives 7.
  const std::string code = seed("001/025_il_mul_add.il");
  if (code.empty()) GTEST_SKIP() << "the seed corpus is not available";
  auto run = run_text("PROGRAM Main\nVAR ERG : INT; END_VAR\n" + code + "\nEND_PROGRAM\n");
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("Main.ERG"), "7");
}

TEST(RunIl, ParenthesesDeferTheOperator) {
  // Seed 001/026 (CODESYS manual L4243-4251): MUL (2 ADD 3) multiplies by 5 at ')': ERG = 10.
  const std::string code = seed("001/026_il_mul_paren.il");
  if (code.empty()) GTEST_SKIP() << "the seed corpus is not available";
  auto run = run_text("PROGRAM Main\nVAR ERG : INT; END_VAR\n" + code + "\nEND_PROGRAM\n");
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("Main.ERG"), "10");
}

TEST(RunIl, DeferredOperatorOnItsOwnLines) {
  // CODESYS V2.3 L338-365: `MUL (` ... `)` over several lines; AND( with N negates the result of
  // the parentheses (IEC table 52: N negates the operand).
  auto run = run_text(R"(
PROGRAM Main
VAR a : INT := 4; b : INT := 3; x : INT; c : BOOL; d : BOOL := TRUE; e : BOOL; r1, r2 : BOOL; END_VAR
LD a
MUL (
  LD b
  ADD 2
)
ST x
LD d
AND( c
  OR e
)
ST r1
LD d
ANDN( c
  OR e
)
ST r2
END_PROGRAM
)");
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("Main.x"), "20");
  EXPECT_EQ(run->text("Main.r1"), "FALSE");
  EXPECT_EQ(run->text("Main.r2"), "TRUE");
}

TEST(RunIl, ConditionalJumpChoosesTheBranch) {
  // Seed 001/023 (CODESYS manual L4180-4209) with the JMPC it means (the book prints JMPCL):
  // IF 10 + A >= B THEN C := A - B ELSE C := A + B.
  auto run = run_text(R"(
PROGRAM Main
VAR A : REAL := 1; B : REAL := 20; C : REAL; END_VAR
LD 10
ADD A
GE B
JMPC Next1
LD A
ADD B
ST C
JMP Next2
Next1:
LD A
SUB B
ST C
Next2:
END_PROGRAM
)");
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("Main.C"), "21");
  run->set("Main.B", "5");
  ASSERT_TRUE(run->cycles(1));
  EXPECT_EQ(run->text("Main.C"), "-4");
}

TEST(RunIl, NegatingModifiersAndSetReset) {
  // IEC 61131-3 table 52: LDN, STN, ANDN, ORN, XORN negate the operand (STN the stored CR); S and
  // R write TRUE/FALSE only when the CR is TRUE; NOT complements the CR (bitwise on a WORD).
  auto run = run_text(R"(
PROGRAM Main
VAR
  t : BOOL := TRUE; f : BOOL;
  a1, a2, a3, a4, a5 : BOOL;
  latch : BOOL; cleared : BOOL := TRUE; untouched : BOOL := TRUE;
  w : WORD := 16#00FF; nw : WORD; mask : WORD;
END_VAR
LDN f
ST a1
LD t
ANDN f
ST a2
LD f
ORN f
ST a3
LD t
XORN f
ST a4
LD t
STN a5
LD t
S latch
R cleared
LD f
R untouched
LD w
NOT
ST nw
LD w
ANDN 16#0F0F
ST mask
END_PROGRAM
)");
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("Main.a1"), "TRUE");
  EXPECT_EQ(run->text("Main.a2"), "TRUE");
  EXPECT_EQ(run->text("Main.a3"), "TRUE");
  EXPECT_EQ(run->text("Main.a4"), "FALSE");
  EXPECT_EQ(run->text("Main.a5"), "FALSE");
  EXPECT_EQ(run->text("Main.latch"), "TRUE");
  EXPECT_EQ(run->text("Main.cleared"), "FALSE");
  EXPECT_EQ(run->text("Main.untouched"), "TRUE");
  EXPECT_EQ(run->text("Main.nw"), "65280");
  EXPECT_EQ(run->text("Main.mask"), "240");
}

TEST(RunIl, ComparisonsAndArithmeticTypedAsInSt) {
  // The CR takes the type ST would give the same expression: INT + INT wraps at 16 bits when
  // stored into an INT; a REAL compares with a literal as a REAL; DIV and MOD on integers.
  auto run = run_text(R"(
PROGRAM Main
VAR i : INT := 32767; j : INT; r : REAL := 2.75; big, eq, ne : BOOL; q, m : DINT; END_VAR
LD i
ADD 1
ST j
LD r
GT 2.5
ST big
LD 7
DIV 2
ST q
LD 7
MOD 4
ST m
LD q
EQ 3
ST eq
LD q
NE 3
ST ne
END_PROGRAM
)");
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("Main.j"), "-32768");
  EXPECT_EQ(run->text("Main.big"), "TRUE");
  EXPECT_EQ(run->text("Main.q"), "3");
  EXPECT_EQ(run->text("Main.m"), "3");
  EXPECT_EQ(run->text("Main.eq"), "TRUE");
  EXPECT_EQ(run->text("Main.ne"), "FALSE");
}

TEST(RunIl, FunctionCallsTakeTheCurrentResultFirst) {
  // CODESYS V2.3 L7670-7688: the function's name in the operator column, its first argument the
  // CR, the others after the name; the result is the new CR (LIMIT(MN := 0, IN := a, MX := 10)).
  auto run = run_text(R"(
FUNCTION Scale : INT
VAR_INPUT x : INT; factor : INT; END_VAR
Scale := x * factor;
END_FUNCTION

PROGRAM Main
VAR a : INT := 4; scaled, limited, biggest : INT; real_value : REAL; END_VAR
LD a
ADD 1
Scale 3
ST scaled
LD 0
LIMIT a, 10
ST limited
LD a
MAX 9
ST biggest
LD a
INT_TO_REAL
ST real_value
END_PROGRAM
)");
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("Main.scaled"), "15");
  EXPECT_EQ(run->text("Main.limited"), "4");
  EXPECT_EQ(run->text("Main.biggest"), "9");
  EXPECT_EQ(run->text("Main.real_value"), "4");
}

TEST(RunIl, CalOfATimerWithArguments) {
  // Seed 001/014 (CODESYS manual L2777-2796): CAL T1(IN := Var1, PT := T#300MS, Q => Var2,
  // ET => et1); Var2 turns TRUE 300 ms after Var1 rises (a 100 ms tick: IN rises at 100 ms, Q in
  // the cycle at 400 ms).
  const std::string code = seed("001/014_il_call_ton_fb_il.il");
  if (code.empty()) GTEST_SKIP() << "the seed corpus is not available";
  auto run = run_text(code + "\nEND_PROGRAM\n", {.tick_ns = 100'000'000});
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("FB_IL.Var2"), "FALSE");
  run->set("FB_IL.Var1", "TRUE");
  const char* expected[] = {"FALSE", "FALSE", "FALSE", "TRUE"};
  for (const char* value : expected) {
    ASSERT_TRUE(run->cycles(1));
    EXPECT_EQ(run->text("FB_IL.Var2"), value) << run->text("FB_IL.et1");
  }
  EXPECT_EQ(run->text("FB_IL.et1"), "T#300ms");
}

TEST(RunIl, ConditionalCallsAndInputOperators) {
  // IEC 61131-3 table 52/53: CALC calls only when the CR is TRUE, CALCN only when FALSE (the
  // CR is undefined after a CAL: load it again); S1 and CLK with an instance as operand set that
  // input to the CR.
  auto run = run_text(R"(
FUNCTION_BLOCK Counter
VAR_INPUT step : INT := 1; END_VAR
VAR_OUTPUT n : INT; END_VAR
n := n + step;
END_FUNCTION_BLOCK

PROGRAM Main
VAR
  go : BOOL; yes : Counter; no : Counter; flip : SR; edge : R_TRIG; seen : BOOL; latched : BOOL;
END_VAR
LD go
CALC yes
LD go
CALCN no
LD TRUE
S1 flip
CAL flip
LD flip.Q1
ST latched
LD go
CLK edge
CAL edge
LD edge.Q
ST seen
END_PROGRAM
)");
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("Main.yes.n"), "0");
  EXPECT_EQ(run->text("Main.no.n"), "1");
  EXPECT_EQ(run->text("Main.latched"), "TRUE");
  EXPECT_EQ(run->text("Main.seen"), "FALSE");
  run->set("Main.go", "TRUE");
  ASSERT_TRUE(run->cycles(1));
  EXPECT_EQ(run->text("Main.yes.n"), "1");
  EXPECT_EQ(run->text("Main.no.n"), "1");
  EXPECT_EQ(run->text("Main.seen"), "TRUE");
  ASSERT_TRUE(run->cycles(1));
  EXPECT_EQ(run->text("Main.seen"), "FALSE");
}

TEST(RunIl, ConditionalReturnLeavesTheBody) {
  // IEC 61131-3 table 52: RETC returns when the CR is TRUE, RETCN when it is FALSE.
  auto run = run_text(R"(
FUNCTION Clamp : INT
VAR_INPUT x : INT; END_VAR
LD 100
ST Clamp
LD x
GT 100
RETC
LD x
ST Clamp
END_FUNCTION

PROGRAM Main
VAR low, high : INT; stop : BOOL := TRUE; after : INT; END_VAR
LD 5
Clamp
ST low
LD 500
Clamp
ST high
LD stop
NOT
RETCN
LD 1
ST after
END_PROGRAM
)");
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("Main.low"), "5");
  EXPECT_EQ(run->text("Main.high"), "100");
  EXPECT_EQ(run->text("Main.after"), "0");
}

TEST(RunIl, BackwardJumpsCountForTheWatchdog) {
  // A loop written with a conditional jump back runs to its end; the label leaves the CR
  // undefined, so the loop reloads it (IEC 3.2).
  auto run = run_text(R"(
PROGRAM Main
VAR i : INT; sum : INT; END_VAR
LD 0
ST i
ST sum
again:
LD sum
ADD i
ST sum
LD i
ADD 1
ST i
LT 5
JMPC again
END_PROGRAM
)");
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("Main.sum"), "10");
  EXPECT_EQ(run->text("Main.i"), "5");
}

}  // namespace
}  // namespace rung::run::testing
