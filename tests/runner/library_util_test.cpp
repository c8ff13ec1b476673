// CODESYS Util (library/codesys/Util), run as programs: BCD, bit and byte helpers, Gray code, math
// helpers, controllers, signal generators, curves, ramps and analog monitors. Each test states its
// rule and its source: the AK800 CODESYS manual's Util.lib chapter (002.md section 13, "L" lines of
// the manual) and the CODESYS V3 textbook (000b.md). Where the manuals leave a detail open, the test
// says "rung's choice" and pins what the ST body in library/ does.
#include <gtest/gtest.h>

#include "tests/runner/run_support.hpp"

namespace rung::run::testing {
namespace {

TEST(LibraryUtil, BcdConversions) {
  // AK800 Util.lib (L19717-19746): BCD_TO_INT(73) = 49, (151) = 97, (15) = -1 (not BCD);
  // INT_TO_BCD(49) = 73, (97) = 151, (100) = 255 (not representable). Textbook (000b.md
  // L14735-14743): BCD_TO_WORD(6466) = 1942 (16#1942); WORD_TO_BCD(2694) = 9876 (16#2694).
  auto run = run_text(R"(
PROGRAM Main
VAR
  a, b, c : INT;
  d, e, f, g : BYTE;
  w1, w2 : WORD;
  b1, b2 : BYTE;
  d1, d2 : DWORD;
END_VAR
a := BCD_TO_INT(73);
b := BCD_TO_INT(151);
c := BCD_TO_INT(15);
d := INT_TO_BCD(49);
e := INT_TO_BCD(97);
f := INT_TO_BCD(100);
g := INT_TO_BCD(-1);
w1 := BCD_TO_WORD(6466);
w2 := WORD_TO_BCD(2694);
b1 := BCD_TO_BYTE(16#99);
b2 := BYTE_TO_BCD(42);
d1 := BCD_TO_DWORD(16#12345678);
d2 := DWORD_TO_BCD(12345678);
END_PROGRAM
)");
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("a"), "49");
  EXPECT_EQ(run->text("b"), "97");
  EXPECT_EQ(run->text("c"), "-1");
  EXPECT_EQ(run->text("d"), "73");
  EXPECT_EQ(run->text("e"), "151");
  EXPECT_EQ(run->text("f"), "255");
  EXPECT_EQ(run->text("g"), "255");
  EXPECT_EQ(run->text("w1"), "1942");
  EXPECT_EQ(run->text("w2"), "9876");
  EXPECT_EQ(run->text("b1"), "99");
  EXPECT_EQ(run->text("b2"), "66");
  EXPECT_EQ(run->text("d1"), "12345678");
  EXPECT_EQ(run->text("d2"), "305419896");
}

TEST(LibraryUtil, BitsOfADword) {
  // AK800 Util.lib (L19763-19797): EXTRACT(X := 81, N := 4) = TRUE, EXTRACT(X := 33, N := 0) =
  // TRUE; PUTBIT(38, 4, TRUE) = 54, PUTBIT(38, 1, FALSE) = 36.
  auto run = run_text(R"(
PROGRAM Main
VAR
  e1, e2, e3, e4 : BOOL;
  p1, p2, p3 : DWORD;
END_VAR
e1 := EXTRACT(X := 81, N := 4);
e2 := EXTRACT(X := 33, N := 0);
e3 := EXTRACT(X := 33, N := 1);
e4 := EXTRACT(X := 16#80000000, N := 31);
p1 := PUTBIT(38, 4, TRUE);
p2 := PUTBIT(38, 1, FALSE);
p3 := PUTBIT(0, 31, TRUE);
END_PROGRAM
)");
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("e1"), "TRUE");
  EXPECT_EQ(run->text("e2"), "TRUE");
  EXPECT_EQ(run->text("e3"), "FALSE");
  EXPECT_EQ(run->text("e4"), "TRUE");
  EXPECT_EQ(run->text("p1"), "54");
  EXPECT_EQ(run->text("p2"), "36");
  EXPECT_EQ(run->text("p3"), "2147483648");
}

TEST(LibraryUtil, PackAndUnpack) {
  // AK800 Util.lib (L19772-19809): PACK puts B0 into bit 0 ... B7 into bit 7; UNPACK is its
  // inverse. The textbook's BIT_AS_* / *_AS_BIT (000b.md L33779-33799) do the same for BYTE, WORD
  // and DWORD.
  auto run = run_text(R"(
PROGRAM Main
VAR
  packed, byte1 : BYTE;
  word1 : WORD;
  dword1 : DWORD;
  u : UNPACK;
  wb : WORD_AS_BIT;
  db : DWORD_AS_BIT;
  bb : BYTE_AS_BIT;
END_VAR
packed := PACK(TRUE, FALSE, TRUE, FALSE, FALSE, FALSE, FALSE, TRUE);
u(B := 16#A5);
byte1 := BIT_AS_BYTE(B1 := TRUE, B6 := TRUE);
word1 := BIT_AS_WORD(B0 := TRUE, B15 := TRUE);
dword1 := BIT_AS_DWORD(B31 := TRUE, B8 := TRUE);
wb(IN := 16#8001);
db(IN := 16#40000002);
bb(IN := 16#80);
END_PROGRAM
)");
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("packed"), "133");
  EXPECT_EQ(run->text("u.B0") + run->text("u.B1") + run->text("u.B2") + run->text("u.B5") + run->text("u.B6") +
                run->text("u.B7"),
            "TRUEFALSETRUETRUEFALSETRUE");
  EXPECT_EQ(run->text("byte1"), "66");
  EXPECT_EQ(run->text("word1"), "32769");
  EXPECT_EQ(run->text("dword1"), "2147483904");
  EXPECT_EQ(run->text("wb.B0") + run->text("wb.B1") + run->text("wb.B15"), "TRUEFALSETRUE");
  EXPECT_EQ(run->text("db.B1") + run->text("db.B30") + run->text("db.B31"), "TRUETRUEFALSE");
  EXPECT_EQ(run->text("bb.B7") + run->text("bb.B0"), "TRUEFALSE");
}

TEST(LibraryUtil, GrayCodeRoundTrips) {
  // Gray code (000b.md L33819-33829): neighbouring values differ in one bit; GRAY_TO_* inverts.
  auto run = run_text(R"(
PROGRAM Main
VAR
  g1, b1 : BYTE;
  g2, b2 : WORD;
  g3 : DWORD;
  i : INT;
  bad, notonebit : INT;
  x : BYTE;
END_VAR
g1 := BYTE_TO_GRAY(5);
b1 := GRAY_TO_BYTE(7);
g2 := WORD_TO_GRAY(16#FFFF);
b2 := GRAY_TO_WORD(16#8000);
g3 := GRAY_TO_DWORD(DWORD_TO_GRAY(16#DEADBEEF));
FOR i := 0 TO 255 DO
  IF GRAY_TO_BYTE(BYTE_TO_GRAY(INT_TO_BYTE(i))) <> INT_TO_BYTE(i) THEN
    bad := bad + 1;
  END_IF
  IF i > 0 THEN
    x := BYTE_TO_GRAY(INT_TO_BYTE(i)) XOR BYTE_TO_GRAY(INT_TO_BYTE(i - 1));
    IF x <> 1 AND x <> 2 AND x <> 4 AND x <> 8 AND x <> 16 AND x <> 32 AND x <> 64 AND x <> 128 THEN
      notonebit := notonebit + 1;
    END_IF
  END_IF
END_FOR
END_PROGRAM
)");
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("g1"), "7");
  EXPECT_EQ(run->text("b1"), "5");
  EXPECT_EQ(run->text("g2"), "32768");
  EXPECT_EQ(run->text("b2"), "65535");
  EXPECT_EQ(run->text("g3"), "3735928559");
  EXPECT_EQ(run->text("bad"), "0");
  EXPECT_EQ(run->text("notonebit"), "0");
}

TEST(LibraryUtil, LinearTransformation) {
  // AK800 Util.lib (L19884-19895): 5 V in 0..10 V gives 10 in -20..40, ERROR FALSE; ERROR TRUE
  // when IN_MIN = IN_MAX or IN lies outside IN_MIN..IN_MAX. rung's choice: outside the range OUT
  // is still the straight line's value; with IN_MIN = IN_MAX it keeps its previous value.
  auto run = run_text(R"(
PROGRAM Main
VAR
  t1, t2, t3 : LIN_TRAFO;
END_VAR
t1(IN := 5, IN_MIN := 0, IN_MAX := 10, OUT_MIN := -20, OUT_MAX := 40);
t2(IN := 11, IN_MIN := 0, IN_MAX := 10, OUT_MIN := -20, OUT_MAX := 40);
t3(IN := 3, IN_MIN := 2, IN_MAX := 2, OUT_MIN := -20, OUT_MAX := 40);
END_PROGRAM
)");
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("t1.OUT"), "10");
  EXPECT_EQ(run->text("t1.ERROR"), "FALSE");
  EXPECT_EQ(run->text("t2.OUT"), "46");
  EXPECT_EQ(run->text("t2.ERROR"), "TRUE");
  EXPECT_EQ(run->text("t3.OUT"), "0");
  EXPECT_EQ(run->text("t3.ERROR"), "TRUE");
}

TEST(LibraryUtil, StatisticsAndVariance) {
  // AK800 Util.lib (L19899-19934): running minimum, maximum and mean since RESET; VARIANCE's OUT
  // is the variance (standard deviation = SQRT(OUT)). rung's choices: the INT mean truncates, the
  // variance divides by the number of values, RESET TRUE gives 0 outputs.
  auto run = run_text(R"(
PROGRAM Main
VAR
  x : INT;
  r : REAL;
  reset : BOOL;
  si : STATISTICS_INT;
  sr : STATISTICS_REAL;
  v : VARIANCE;
END_VAR
si(IN := x, RESET := reset);
sr(IN := r, RESET := reset);
v(IN := r, RESET := reset);
END_PROGRAM
)", {.cycles = 0});
  ASSERT_TRUE(run->engine) << joined(run->check_errors) << joined(run->compile_errors);
  EXPECT_EQ(sequence(*run, "x", {"3", "-2", "10"}, "si.AVG"), "3,0,3");
  EXPECT_EQ(run->text("si.MN") + "/" + run->text("si.MX"), "-2/10");
  run->set("reset", "TRUE");
  run->cycles(1);
  EXPECT_EQ(run->text("si.MN") + "/" + run->text("si.MX") + "/" + run->text("si.AVG"), "0/0/0");
  run->set("reset", "FALSE");
  // Population variance of 2, 4, 4, 4, 5, 5, 7, 9 after each value (mean 5, variance 4 at the end).
  const std::vector<std::string> values{"2", "4", "4", "4", "5", "5", "7", "9"};
  const std::vector<double> variances{0, 1, 0.888889, 0.75, 0.96, 1, 1.959184, 4};
  for (size_t i = 0; i < values.size(); ++i) {
    run->set("r", values[i]);
    ASSERT_TRUE(run->cycles(1)) << run->error();
    EXPECT_NEAR(std::stod(run->text("v.OUT")), variances[i], 1e-5) << "after " << i + 1 << " values";
  }
  EXPECT_EQ(run->text("v.OUT"), "4");
  EXPECT_EQ(run->text("sr.AVG") + "/" + run->text("sr.MN") + "/" + run->text("sr.MX"), "5/2/9");
  // x stayed 10 for the eight cycles after RESET.
  EXPECT_EQ(run->text("si.MN") + "/" + run->text("si.MX") + "/" + run->text("si.AVG"), "10/10/10");
}

TEST(LibraryUtil, DerivativeUsesTheLastFourValues) {
  // AK800 Util.lib (L19817-19832): DERIVATIVE approximates dIN/dt from the last four values (TM in
  // ms). rung's body: the least-squares slope through them, (3 (x0 - x3) + x1 - x2) / (10 dt);
  // the first call (and RESET) fills the history with IN and gives 0. A ramp of 1 per 100 ms
  // (10 per second) reads 0, 3, 7, then exactly 10.
  auto run = run_text(R"(
PROGRAM Main
VAR
  x : REAL;
  d : DERIVATIVE;
  i : INTEGRAL;
END_VAR
d(IN := x, TM := 100);
i(IN := 4.0, TM := 250);
x := x + 1.0;
END_PROGRAM
)", {.cycles = 0});
  ASSERT_TRUE(run->engine) << joined(run->check_errors) << joined(run->compile_errors);
  // INTEGRAL: the trapezoid between the last two values; 4.0 for 250 ms adds 1 per call.
  EXPECT_EQ(trace(*run, 5, {"d.OUT", "i.OUT"}), "0/0,3/1,7/2,10/3,10/4");
}

TEST(LibraryUtil, ProportionalControllerAndLimits) {
  // Textbook fact 66 (000b.md L20312-20390): PD with KP = 2, TV = 0, Y_OFFSET = 0, SET_POINT = 10,
  // ACTUAL = 4, Y_MIN = 0, Y_MAX = 100 gives Y = 12, LIMITS_ACTIVE FALSE; with Y_MAX = 10 Y = 10
  // and LIMITS_ACTIVE TRUE. MANUAL gives Y_MANUAL; RESET gives Y_OFFSET (AK800 L19968-20019). Here
  // Y_OFFSET = 1.5, so the unclamped Y is 13.5.
  auto run = run_text(R"(
PROGRAM Main
VAR
  ymax : REAL := 100;
  manual, reset : BOOL;
  c : PD;
END_VAR
c(ACTUAL := 4, SET_POINT := 10, KP := 2, TV := 0, Y_MANUAL := 33, Y_OFFSET := 1.5, Y_MIN := 0, Y_MAX := ymax,
  MANUAL := manual, RESET := reset);
END_PROGRAM
)");
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("c.Y"), "13.5");
  EXPECT_EQ(run->text("c.LIMITS_ACTIVE"), "FALSE");
  run->set("ymax", "10");
  run->cycles(1);
  EXPECT_EQ(run->text("c.Y"), "10");
  EXPECT_EQ(run->text("c.LIMITS_ACTIVE"), "TRUE");
  run->set("manual", "TRUE");
  run->cycles(1);
  EXPECT_EQ(run->text("c.Y"), "33");
  EXPECT_EQ(run->text("c.LIMITS_ACTIVE"), "FALSE");
  run->set("reset", "TRUE");
  run->cycles(1);
  EXPECT_EQ(run->text("c.Y"), "1.5");
}

TEST(LibraryUtil, FixedCyclePidIntegratesPerCycle) {
  // Textbook fact 66 (000b.md L20217-20310): PID_FIXCYCLE with TV = 0, KP = 1, TN = 1 s and a
  // constant error 1 adds CYCLE / TN to Y per call (rectangle rule, rung's choice): CYCLE = 0.5 s
  // gives 1.5, 2, 2.5 ... While Y is clamped (LIMITS_ACTIVE) the integral stops growing
  // (anti-windup, AK800 L20024-20128), so Y leaves the limit as soon as the error turns.
  auto run = run_text(R"(
PROGRAM Main
VAR
  actual : REAL := 9;
  c : PID_FIXCYCLE;
END_VAR
c(ACTUAL := actual, SET_POINT := 10, KP := 1, TN := 1, TV := 0, Y_MIN := 0, Y_MAX := 2.5, CYCLE := 0.5);
END_PROGRAM
)", {.cycles = 0});
  ASSERT_TRUE(run->engine) << joined(run->check_errors) << joined(run->compile_errors);
  EXPECT_EQ(trace(*run, 4, {"c.Y", "c.LIMITS_ACTIVE"}), "1.5/FALSE,2/FALSE,2.5/FALSE,2.5/TRUE");
  // Error -1 now: integral 1.5 (it stopped at 1.5) - 0.5 = 1.0; Y = -1 + 1 = 0.
  run->set("actual", "11");
  EXPECT_EQ(trace(*run, 1, {"c.Y", "c.LIMITS_ACTIVE"}), "0/FALSE");
}

TEST(LibraryUtil, PidMeasuresItsOwnCycle) {
  // AK800 Util.lib (L20024-20128), textbook L20300-20310: PID measures the time between calls
  // itself (here rung's clock, 500 ms per cycle; the first call has no interval).
  auto run = run_text(R"(
PROGRAM Main
VAR
  c : PID;
END_VAR
c(ACTUAL := 9, SET_POINT := 10, KP := 1, TN := 1, TV := 0);
END_PROGRAM
)", {.cycles = 0, .tick_ns = 500'000'000});
  ASSERT_TRUE(run->engine) << joined(run->check_errors) << joined(run->compile_errors);
  EXPECT_EQ(trace(*run, 3, {"c.Y", "c.OVERFLOW"}), "1/FALSE,1.5/FALSE,2/FALSE");
}

TEST(LibraryUtil, BlinkAlternatesAndFreezes) {
  // AK800 Util.lib (L20157-20165): ENABLE TRUE starts with OUT TRUE for TIMEHIGH, then FALSE for
  // TIMELOW, repeating; ENABLE FALSE freezes OUT. 10 ms per cycle, TIMEHIGH 30 ms, TIMELOW 20 ms.
  auto run = run_text(R"(
PROGRAM Main
VAR
  enable : BOOL;
  b : BLINK;
END_VAR
b(ENABLE := enable, TIMELOW := T#20ms, TIMEHIGH := T#30ms);
END_PROGRAM
)", {.cycles = 0});
  ASSERT_TRUE(run->engine) << joined(run->check_errors) << joined(run->compile_errors);
  EXPECT_EQ(sequence(*run, "enable", {"TRUE", "TRUE", "TRUE", "TRUE", "TRUE", "TRUE", "TRUE", "TRUE", "TRUE"}, "b.OUT"),
            "TRUE,TRUE,TRUE,FALSE,FALSE,TRUE,TRUE,TRUE,FALSE");
  EXPECT_EQ(sequence(*run, "enable", {"FALSE", "FALSE", "FALSE"}, "b.OUT"), "FALSE,FALSE,FALSE");
  EXPECT_EQ(sequence(*run, "enable", {"TRUE"}, "b.OUT"), "TRUE");
}

TEST(LibraryUtil, GeneratorWaveformsOverCycles) {
  // AK800 Util.lib (L20210-20248): BASE FALSE makes the period CYCLES calls; AMPLITUDE scales;
  // RESET sets OUT to 0. The waveforms are figures in the manual; rung's choice: SINE and the
  // triangles start at 0 rising, sawtooths and RECTANGLE span -AMPLITUDE..AMPLITUDE.
  auto run = run_text(R"(
PROGRAM Main
VAR
  mode : GEN_MODE;
  g : GEN;
END_VAR
g(MODE := mode, BASE := FALSE, CYCLES := 4, AMPLITUDE := 100);
END_PROGRAM
)", {.cycles = 0});
  ASSERT_TRUE(run->engine) << joined(run->check_errors) << joined(run->compile_errors);
  run->set("mode", "RECTANGLE");
  EXPECT_EQ(trace(*run, 5, {"g.OUT"}), "100,100,-100,-100,100");
  run->set("mode", "SAWTOOTH_RISE");
  EXPECT_EQ(trace(*run, 4, {"g.OUT"}), "-50,0,50,-100");
  run->set("mode", "TRIANGLE");
  EXPECT_EQ(trace(*run, 4, {"g.OUT"}), "100,0,-100,0");
  run->set("mode", "SINE");
  EXPECT_EQ(trace(*run, 4, {"g.OUT"}), "100,0,-100,0");
  run->set("mode", "COSINE");
  EXPECT_EQ(trace(*run, 4, {"g.OUT"}), "0,-100,0,100");
  run->set("mode", "TRIANGLE_POS");
  EXPECT_EQ(trace(*run, 4, {"g.OUT"}), "50,100,50,0");
}

TEST(LibraryUtil, FrequencyOfASignal) {
  // AK800 Util.lib (L20172-20205): the mean frequency in Hz over PERIODS periods, rising edge to
  // rising edge; VALID FALSE until the first measurement is complete and again when no edge came
  // for more than three measured periods. A signal toggled every 10 ms cycle is 50 Hz.
  auto run = run_text(R"(
PROGRAM Main
VAR
  in : BOOL;
  f : FREQ_MEASURE;
END_VAR
f(IN := in, PERIODS := 2);
END_PROGRAM
)", {.cycles = 0});
  ASSERT_TRUE(run->engine) << joined(run->check_errors) << joined(run->compile_errors);
  EXPECT_EQ(sequence(*run, "in", {"TRUE", "FALSE", "TRUE", "FALSE", "TRUE"}, "f.VALID"), "FALSE,FALSE,FALSE,FALSE,TRUE");
  EXPECT_EQ(run->text("f.OUT"), "50");
  EXPECT_EQ(sequence(*run, "in", {"FALSE", "FALSE", "FALSE", "FALSE", "FALSE", "FALSE", "FALSE"}, "f.VALID"),
            "TRUE,TRUE,TRUE,TRUE,TRUE,TRUE,FALSE");
}

TEST(LibraryUtil, CharacteristicCurve) {
  // AK800 Util.lib (L20257-20308) with the manual's example points (0,0), (250,50), (500,150),
  // (750,400), (1000,1000) and N = 5: linear between the points; ERR 2 outside with OUT clamped;
  // ERR 1 when the points are not sorted by X; ERR 4 when N is not 2..11.
  auto run = run_text(R"(
PROGRAM Main
VAR
  x : INT;
  n : BYTE := 5;
  kl : ARRAY[0..10] OF POINT := [(X := 0, Y := 0), (X := 250, Y := 50), (X := 500, Y := 150), (X := 750, Y := 400),
                                 7((X := 1000, Y := 1000))];
  c : CHARCURVE;
END_VAR
c(IN := x, N := n, P := kl);
END_PROGRAM
)", {.cycles = 0});
  ASSERT_TRUE(run->engine) << joined(run->check_errors) << joined(run->compile_errors);
  EXPECT_EQ(sequence(*run, "x", {"100", "250", "600", "1000", "0"}, "c.OUT"), "20,50,250,1000,0");
  EXPECT_EQ(run->text("c.ERR"), "0");
  EXPECT_EQ(sequence(*run, "x", {"1010"}, "c.OUT"), "1000");
  EXPECT_EQ(run->text("c.ERR"), "2");
  EXPECT_EQ(sequence(*run, "x", {"-5"}, "c.OUT"), "0");
  EXPECT_EQ(run->text("c.ERR"), "2");
  run->set("n", "12");
  run->cycles(1);
  EXPECT_EQ(run->text("c.ERR"), "4");
  run->set("n", "6");  // the 6th point repeats X = 1000: not sorted
  run->cycles(1);
  EXPECT_EQ(run->text("c.ERR"), "1");
}

TEST(LibraryUtil, RampsLimitTheSlope) {
  // AK800 Util.lib (L20314-20343): OUT follows IN rising by at most ASCEND and falling by at most
  // DESCEND per TIMEBASE, per call when TIMEBASE = T#0s; RESET re-initialises (rung: OUT := IN).
  auto run = run_text(R"(
PROGRAM Main
VAR
  x : INT;
  reset : BOOL;
  r : RAMP_INT;
  rr : RAMP_REAL;
END_VAR
r(IN := x, ASCEND := 10, DESCEND := 5, TIMEBASE := T#0s, RESET := reset);
rr(IN := 100.0, ASCEND := 10.0, DESCEND := 10.0, TIMEBASE := T#1s);
END_PROGRAM
)", {.cycles = 0, .tick_ns = 100'000'000});
  ASSERT_TRUE(run->engine) << joined(run->check_errors) << joined(run->compile_errors);
  EXPECT_EQ(sequence(*run, "x", {"25", "25", "25", "0", "0"}, "r.OUT"), "10,20,25,20,15");
  // RAMP_REAL: 10 per second on a 100 ms tick is 1 per cycle after the first call.
  EXPECT_EQ(run->text("rr.OUT"), "4");
  run->set("reset", "TRUE");
  EXPECT_EQ(sequence(*run, "x", {"-30"}, "r.OUT"), "-30");
}

TEST(LibraryUtil, HysteresisAndLimitAlarm) {
  // AK800 Util.lib (L20359-20382): HYSTERESIS: IN < LOW -> OUT TRUE, IN > HIGH -> FALSE, between
  // them OUT keeps its value. LIMITALARM: O = IN > HIGH, U = IN < LOW, IL = LOW <= IN <= HIGH.
  auto run = run_text(R"(
PROGRAM Main
VAR
  x : INT;
  h : HYSTERESIS;
  a : LIMITALARM;
END_VAR
h(IN := x, HIGH := 20, LOW := 10);
a(IN := x, HIGH := 20, LOW := 10);
END_PROGRAM
)", {.cycles = 0});
  ASSERT_TRUE(run->engine) << joined(run->check_errors) << joined(run->compile_errors);
  EXPECT_EQ(sequence(*run, "x", {"5", "15", "25", "15", "10", "9"}, "h.OUT"), "TRUE,TRUE,FALSE,FALSE,FALSE,TRUE");
  EXPECT_EQ(sequence(*run, "x", {"25", "20", "10", "5"}, "a.O"), "TRUE,FALSE,FALSE,FALSE");
  EXPECT_EQ(sequence(*run, "x", {"25", "20", "10", "5"}, "a.IL"), "FALSE,TRUE,TRUE,FALSE");
  EXPECT_EQ(sequence(*run, "x", {"25", "20", "10", "5"}, "a.U"), "FALSE,FALSE,FALSE,TRUE");
}

}  // namespace
}  // namespace rung::run::testing
