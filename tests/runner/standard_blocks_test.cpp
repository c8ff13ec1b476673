// The standard function blocks cycle by cycle: timers on the virtual clock, counters, edges and
// bistables, as the manuals state them (CODESYS V3 textbook, ch. 5 "Standard library").
#include <gtest/gtest.h>

#include "tests/runner/run_support.hpp"

namespace rung::run::testing {
namespace {

const char* kEdges = R"(
PROGRAM Main
VAR
  clk : BOOL;
  rise : R_TRIG;
  fall : F_TRIG;
  r, f : BOOL;
END_VAR
rise(CLK := clk);
fall(CLK := clk);
r := rise.Q;
f := fall.Q;
END_PROGRAM
)";

TEST(RunStandardBlocks, RisingEdgeIsTrueForExactlyOneCycle) {
  // Textbook fact: R_TRIG CLK F,T,T,T,F,T gives Q F,T,F,F,F,T.
  auto run = run_text(kEdges, {.cycles = 0});
  ASSERT_TRUE(run->engine) << (run->check_errors.empty() ? "" : run->check_errors.front());
  EXPECT_EQ(sequence(*run, "clk", {"FALSE", "TRUE", "TRUE", "TRUE", "FALSE", "TRUE"}, "r"), "FALSE,TRUE,FALSE,FALSE,FALSE,TRUE");
}

TEST(RunStandardBlocks, FallingEdgeGivesNoPulseOnTheFirstCall) {
  // Textbook fact: F_TRIG CLK T,T,F,F,T,F gives Q F,F,T,F,F,T; no pulse on the first call.
  auto run = run_text(kEdges, {.cycles = 0});
  ASSERT_TRUE(run->engine);
  EXPECT_EQ(sequence(*run, "clk", {"TRUE", "TRUE", "FALSE", "FALSE", "TRUE", "FALSE"}, "f"), "FALSE,FALSE,TRUE,FALSE,FALSE,TRUE");
  auto fresh = run_text(kEdges, {.cycles = 1});
  EXPECT_EQ(fresh->text("f"), "FALSE");
  EXPECT_EQ(fresh->text("r"), "FALSE");
}

TEST(RunStandardBlocks, BistablesSetOrResetDominant) {
  auto run = run_text(R"(
PROGRAM Main
VAR
  s, r : BOOL;
  sr1 : SR;
  rs1 : RS;
  qsr, qrs : BOOL;
END_VAR
sr1(SET1 := s, RESET := r, Q1 => qsr);
rs1(SET := s, RESET1 := r, Q1 => qrs);
END_PROGRAM
)", {.cycles = 0});
  ASSERT_TRUE(run->engine);
  run->set("s", "TRUE");
  run->set("r", "TRUE");
  run->cycles(1);
  EXPECT_EQ(run->text("qsr"), "TRUE");   // SR: set dominant
  EXPECT_EQ(run->text("qrs"), "FALSE");  // RS: reset dominant
  run->set("s", "FALSE");
  run->set("r", "FALSE");
  run->cycles(1);
  EXPECT_EQ(run->text("qsr"), "TRUE");  // both keep their state
  EXPECT_EQ(run->text("qrs"), "FALSE");
}

TEST(RunStandardBlocks, OnDelayTimerElapsesOnTheExactCycle) {
  // TON: Q becomes TRUE when IN has been TRUE for PT; ET counts up to PT and holds; IN FALSE
  // resets both at once. The virtual clock advances 10 ms per cycle; the first cycle runs at 0.
  auto run = run_text(R"(
PROGRAM Main
VAR
  start : BOOL;
  t : TON;
  q : BOOL;
  et : TIME;
END_VAR
t(IN := start, PT := T#30ms, Q => q, ET => et);
END_PROGRAM
)", {.cycles = 0});
  ASSERT_TRUE(run->engine);
  EXPECT_EQ(sequence(*run, "start", {"TRUE", "TRUE", "TRUE", "TRUE", "TRUE"}, "q"), "FALSE,FALSE,FALSE,TRUE,TRUE");
  EXPECT_EQ(run->text("et"), "T#30ms");
  run->set("start", "FALSE");
  run->cycles(1);
  EXPECT_EQ(run->text("q"), "FALSE");
  EXPECT_EQ(run->text("et"), "T#0ms");
}

TEST(RunStandardBlocks, OnDelayWithZeroPresetIsTrueAtOnce) {
  auto run = run_text(R"(
PROGRAM Main
VAR
  t : TON;
  q : BOOL;
END_VAR
t(IN := TRUE, PT := T#0s);
q := t.Q;
END_PROGRAM
)");
  ASSERT_TRUE(run->engine);
  EXPECT_EQ(run->text("q"), "TRUE");
}

TEST(RunStandardBlocks, OffDelayAndPulseTimers) {
  auto run = run_text(R"(
PROGRAM Main
VAR
  in : BOOL;
  off : TOF;
  pulse : TP;
  qoff, qpulse : BOOL;
END_VAR
off(IN := in, PT := T#20ms, Q => qoff);
pulse(IN := in, PT := T#20ms, Q => qpulse);
END_PROGRAM
)", {.cycles = 0});
  ASSERT_TRUE(run->engine);
  // TOF: TRUE with IN, stays TRUE for PT after IN falls.
  EXPECT_EQ(sequence(*run, "in", {"TRUE", "FALSE", "FALSE", "FALSE", "FALSE"}, "qoff"), "TRUE,TRUE,TRUE,FALSE,FALSE");
  auto run2 = run_text(R"(
PROGRAM Main
VAR
  in : BOOL;
  pulse : TP;
  qpulse : BOOL;
END_VAR
pulse(IN := in, PT := T#20ms, Q => qpulse);
END_PROGRAM
)", {.cycles = 0});
  // TP: a pulse of PT from the rising edge, not retriggered while it runs.
  EXPECT_EQ(sequence(*run2, "in", {"TRUE", "FALSE", "TRUE", "TRUE", "TRUE"}, "qpulse"), "TRUE,TRUE,FALSE,FALSE,FALSE");
}

TEST(RunStandardBlocks, LongTimersRunInMicrosecondsOfWallTime) {
  // A TON with PT = 10 minutes on a 100 ms tick: 6000 cycles.
  auto run = run_text(R"(
PROGRAM Main
VAR
  t : TON;
  q : BOOL;
END_VAR
t(IN := TRUE, PT := T#10m, Q => q);
END_PROGRAM
)", {.cycles = 6000, .tick_ns = 100'000'000});
  ASSERT_TRUE(run->engine);
  EXPECT_EQ(run->text("q"), "FALSE");
  run->cycles(1);
  EXPECT_EQ(run->text("q"), "TRUE");
  EXPECT_EQ(run->text("t.ET"), "T#10m");
}

TEST(RunStandardBlocks, UpCounterCountsEdgesAndResets) {
  // Textbook fact: CTU PV=2: two CU edges -> CV=2, Q=TRUE; a third -> CV=3; RESET -> CV=0 and edges
  // are ignored while RESET is TRUE.
  auto run = run_text(R"(
PROGRAM Main
VAR
  cu, reset : BOOL;
  c : CTU;
END_VAR
c(CU := cu, RESET := reset, PV := 2);
END_PROGRAM
)", {.cycles = 0});
  ASSERT_TRUE(run->engine);
  EXPECT_EQ(sequence(*run, "cu", {"TRUE", "FALSE", "TRUE", "FALSE", "TRUE"}, "c.CV"), "1,1,2,2,3");
  EXPECT_EQ(run->text("c.Q"), "TRUE");
  run->set("reset", "TRUE");
  EXPECT_EQ(sequence(*run, "cu", {"FALSE", "TRUE"}, "c.CV"), "0,0");
  EXPECT_EQ(run->text("c.Q"), "FALSE");
}

TEST(RunStandardBlocks, DownCounterLoadsAndStopsAtZero) {
  auto run = run_text(R"(
PROGRAM Main
VAR
  cd, load : BOOL;
  c : CTD;
END_VAR
c(CD := cd, LOAD := load, PV := 2);
END_PROGRAM
)", {.cycles = 1});
  ASSERT_TRUE(run->engine);
  EXPECT_EQ(run->text("c.Q"), "TRUE");  // CV starts at 0
  run->set("load", "TRUE");
  run->cycles(1);
  EXPECT_EQ(run->text("c.CV"), "2");
  run->set("load", "FALSE");
  EXPECT_EQ(sequence(*run, "cd", {"TRUE", "FALSE", "TRUE", "FALSE", "TRUE"}, "c.CV"), "1,1,0,0,0");
  EXPECT_EQ(run->text("c.Q"), "TRUE");
}

TEST(RunStandardBlocks, UpDownCounterIgnoresSimultaneousEdges) {
  auto run = run_text(R"(
PROGRAM Main
VAR
  up, down : BOOL;
  c : CTUD;
END_VAR
c(CU := up, CD := down, PV := 2);
END_PROGRAM
)", {.cycles = 0});
  ASSERT_TRUE(run->engine);
  run->set("up", "TRUE");
  run->cycles(1);
  EXPECT_EQ(run->text("c.CV"), "1");
  run->set("up", "FALSE");
  run->cycles(1);
  run->set("up", "TRUE");
  run->set("down", "TRUE");
  run->cycles(1);
  EXPECT_EQ(run->text("c.CV"), "1");
  EXPECT_EQ(run->text("c.QU"), "FALSE");
  EXPECT_EQ(run->text("c.QD"), "FALSE");
}

}  // namespace
}  // namespace rung::run::testing
