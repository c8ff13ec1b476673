// IEC textual SFC bodies run: steps and transitions cycle by cycle, selective and simultaneous
// branches, action qualifiers with their times, step flags step.X / step.T, and CODESYS's SFC
// flags SFCInit, SFCReset, SFCPause. Rules: IEC 61131-3 2nd ed. 2.6 (action control, Fig. 21)
// and the CODESYS V2.3 manual's SFC chapter (seed 002.md, L808-1071) and the Kinco manual's
// (seed 001.md, L4508-4602). docs/runner.md states the order within one cycle.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "tests/runner/run_support.hpp"

namespace rung::run::testing {
namespace {

constexpr uint64_t k100ms = 100'000'000;

TEST(RunSfc, StepsAdvanceAndActionsRunOnceMoreWhenLeft) {
  // CODESYS V2.3 L868-879: in one cycle the actions of the active steps run; when the following
  // transition is TRUE the next step is active (and runs) from the next cycle. L945: an action
  // runs once more when it becomes inactive. Step T: time since activation, kept when left.
  auto run = run_text(R"(
PROGRAM Chart
VAR go, back : BOOL; fills, works : INT; END_VAR
INITIAL_STEP Init: Fill(N); END_STEP
TRANSITION FROM Init TO Run := go; END_TRANSITION
STEP Run: Work(N); END_STEP
TRANSITION FROM Run TO Init := back; END_TRANSITION
ACTION Fill: fills := fills + 1; END_ACTION
ACTION Work: works := works + 1; END_ACTION
END_PROGRAM
)");
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("Chart.fills"), "1");
  EXPECT_EQ(run->text("Chart.Init.X"), "TRUE");
  EXPECT_EQ(run->text("Chart.Run.X"), "FALSE");
  ASSERT_TRUE(run->cycles(1));  // t = 10 ms
  EXPECT_EQ(run->text("Chart.fills"), "2");
  EXPECT_EQ(run->text("Chart.Init.T"), "T#10ms");
  run->set("Chart.go", "TRUE");
  ASSERT_TRUE(run->cycles(1));  // t = 20 ms: Fill runs, then Init -> Run
  EXPECT_EQ(run->text("Chart.fills"), "3");
  EXPECT_EQ(run->text("Chart.works"), "0");
  EXPECT_EQ(run->text("Chart.Init.X"), "FALSE");
  EXPECT_EQ(run->text("Chart.Run.X"), "TRUE");
  ASSERT_TRUE(run->cycles(1));  // t = 30 ms: Fill's final run, Work's first
  EXPECT_EQ(run->text("Chart.fills"), "4");
  EXPECT_EQ(run->text("Chart.works"), "1");
  EXPECT_EQ(run->text("Chart.Init.T"), "T#20ms");
  EXPECT_EQ(run->text("Chart.Run.T"), "T#10ms");
  ASSERT_TRUE(run->cycles(1));
  EXPECT_EQ(run->text("Chart.fills"), "4");
  EXPECT_EQ(run->text("Chart.works"), "2");
}

TEST(RunSfc, SelectiveBranchTakesTheFirstTrueTransition) {
  // CODESYS V2.3 L1043-1053: alternative branches are evaluated left to right (in the text: in
  // source order); the first TRUE transition wins.
  auto run = run_text(R"(
PROGRAM Chart
VAR c1, c2 : BOOL := TRUE; back : BOOL; END_VAR
INITIAL_STEP Init: END_STEP
TRANSITION FROM Init TO A := c1; END_TRANSITION
TRANSITION FROM Init TO B := c2; END_TRANSITION
STEP A: END_STEP
STEP B: END_STEP
TRANSITION FROM A TO Init := back; END_TRANSITION
TRANSITION FROM B TO Init := back; END_TRANSITION
END_PROGRAM
)");
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("Chart.A.X"), "TRUE");
  EXPECT_EQ(run->text("Chart.B.X"), "FALSE");
  EXPECT_EQ(run->text("Chart.Init.X"), "FALSE");
  run->set("Chart.back", "TRUE");
  run->set("Chart.c1", "FALSE");
  ASSERT_TRUE(run->cycles(1));
  EXPECT_EQ(run->text("Chart.Init.X"), "TRUE");
  run->set("Chart.back", "FALSE");
  ASSERT_TRUE(run->cycles(1));
  EXPECT_EQ(run->text("Chart.A.X"), "FALSE");
  EXPECT_EQ(run->text("Chart.B.X"), "TRUE");
}

TEST(RunSfc, SimultaneousBranchesSplitAndJoin) {
  // CODESYS V2.3 L1055-1067: a parallel branch activates all its first steps together; the step
  // after the join activates when all last steps are active and the transition is TRUE.
  auto run = run_text(R"(
PROGRAM Chart
VAR go : BOOL := TRUE; next_left, join : BOOL; END_VAR
INITIAL_STEP Init: END_STEP
TRANSITION FROM Init TO (Left, Right) := go; END_TRANSITION
STEP Left: END_STEP
STEP Right: END_STEP
TRANSITION FROM Left TO Left2 := next_left; END_TRANSITION
STEP Left2: END_STEP
TRANSITION FROM (Left2, Right) TO Init := join; END_TRANSITION
END_PROGRAM
)");
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("Chart.Left.X"), "TRUE");
  EXPECT_EQ(run->text("Chart.Right.X"), "TRUE");
  run->set("Chart.join", "TRUE");  // Left2 is not active yet: no join
  ASSERT_TRUE(run->cycles(1));
  EXPECT_EQ(run->text("Chart.Right.X"), "TRUE");
  EXPECT_EQ(run->text("Chart.Init.X"), "FALSE");
  run->set("Chart.next_left", "TRUE");
  ASSERT_TRUE(run->cycles(1));
  EXPECT_EQ(run->text("Chart.Left.X"), "FALSE");
  EXPECT_EQ(run->text("Chart.Left2.X"), "TRUE");
  EXPECT_EQ(run->text("Chart.Right.X"), "TRUE");
  ASSERT_TRUE(run->cycles(1));
  EXPECT_EQ(run->text("Chart.Left2.X"), "FALSE");
  EXPECT_EQ(run->text("Chart.Right.X"), "FALSE");
  EXPECT_EQ(run->text("Chart.Init.X"), "TRUE");
}

// The values of the listed BOOL variables of Chart, as one string of 0 and 1.
std::string bits(const Run& run, const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& name : names) out += run.text("Chart." + name) == "TRUE" ? '1' : '0';
  return out;
}

TEST(RunSfc, QualifiersWhileTheStepStaysActive) {
  // IEC 61131-3 2nd ed. Fig. 21 (action control) and the qualifiers of CODESYS V2.3 L907-943:
  // N while active, S until R, L for its time, D after its time, P once, SD after its time and
  // on until R, DS after its time if still active and on until R, SL for its time and then off,
  // P0 once when the step goes. A 100 ms tick: cycle k runs at (k-1) * 100 ms.
  auto run = run_text(R"(
PROGRAM Chart
VAR go : BOOL; qN, qS, qL, qD, qP, qSD, qDS, qSL, qP0 : BOOL; END_VAR
INITIAL_STEP Init:
  qN(N); qS(S); qL(L, T#300ms); qD(D, T#200ms); qP(P); qSD(SD, T#200ms); qDS(DS, T#200ms);
  qSL(SL, T#300ms); qP0(P0);
END_STEP
TRANSITION FROM Init TO Done := go; END_TRANSITION
STEP Done: qS(R); qSD(R); qDS(R); END_STEP
TRANSITION FROM Done TO Init := FALSE; END_TRANSITION
END_PROGRAM
)",
                      {.tick_ns = k100ms});
  ASSERT_CLEAN(run);
  const std::vector<std::string> names = {"qN", "qS", "qL", "qD", "qP", "qSD", "qDS", "qSL", "qP0"};
  //                                       N  S  L  D  P  SD DS SL P0
  EXPECT_EQ(bits(*run, names), "111010010");  // t = 0
  ASSERT_TRUE(run->cycles(1));
  EXPECT_EQ(bits(*run, names), "111000010");  // t = 100 ms
  ASSERT_TRUE(run->cycles(1));
  EXPECT_EQ(bits(*run, names), "111101110");  // t = 200 ms: D, SD, DS on
  ASSERT_TRUE(run->cycles(1));
  EXPECT_EQ(bits(*run, names), "110101100");  // t = 300 ms: L and SL off
  run->set("Chart.go", "TRUE");
  ASSERT_TRUE(run->cycles(1));
  EXPECT_EQ(bits(*run, names), "110101100");  // t = 400 ms: still Init, then Init -> Done
  EXPECT_EQ(run->text("Chart.Done.X"), "TRUE");
  ASSERT_TRUE(run->cycles(1));
  EXPECT_EQ(bits(*run, names), "000000001");  // Done's R resets S, SD, DS; P0 pulses
  ASSERT_TRUE(run->cycles(1));
  EXPECT_EQ(bits(*run, names), "000000000");
}

TEST(RunSfc, StoredQualifiersOutliveTheirStep) {
  // Kinco manual L4562-4574 (seed 001.md fact 72): with T#200ms and the step left after one cycle,
  // D and DS never run, SD runs after its time anyway (until R), SL runs for its full time, L
  // stops with the step.
  auto run = run_text(R"(
PROGRAM Chart
VAR qL, qD, qSD, qDS, qSL : BOOL; END_VAR
INITIAL_STEP Init: qL(L, T#300ms); qD(D, T#200ms); qSD(SD, T#200ms); qDS(DS, T#200ms); qSL(SL, T#300ms); END_STEP
TRANSITION FROM Init TO Done := TRUE; END_TRANSITION
STEP Done: END_STEP
TRANSITION FROM Done TO Init := FALSE; END_TRANSITION
END_PROGRAM
)",
                      {.tick_ns = k100ms});
  ASSERT_CLEAN(run);
  const std::vector<std::string> names = {"qL", "qD", "qSD", "qDS", "qSL"};
  const char* expected[] = {"10001", "00001", "00101", "00100", "00100"};  // t = 0 .. 400 ms
  for (const char* row : expected) {
    EXPECT_EQ(bits(*run, names), row) << run->text("Chart.Init.T");
    ASSERT_TRUE(run->cycles(1));
  }
}

TEST(RunSfc, SfcInitResetAndPause) {
  // CODESYS V2.3 L964-1041 (seed 002.md): SFCInit TRUE returns the chart to its initial step and
  // holds it there (nothing runs); SFCReset does the same and goes on in that cycle; SFCPause TRUE
  // stops the chart. The flags are variables the POU declares.
  auto run = run_text(R"(
PROGRAM Chart
VAR SFCInit, SFCReset, SFCPause : BOOL; go : BOOL := TRUE; n : INT; END_VAR
INITIAL_STEP Init: Count(N); END_STEP
TRANSITION FROM Init TO Run := go; END_TRANSITION
STEP Run: END_STEP
TRANSITION FROM Run TO Init := FALSE; END_TRANSITION
ACTION Count: n := n + 1; END_ACTION
END_PROGRAM
)",
                      {.cycles = 3});
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("Chart.n"), "2");  // cycle 1 and the final run in cycle 2
  EXPECT_EQ(run->text("Chart.Run.X"), "TRUE");
  run->set("Chart.SFCInit", "TRUE");
  for (int cycle = 0; cycle < 2; ++cycle) {
    ASSERT_TRUE(run->cycles(1));
    EXPECT_EQ(run->text("Chart.Init.X"), "TRUE");
    EXPECT_EQ(run->text("Chart.Run.X"), "FALSE");
    EXPECT_EQ(run->text("Chart.n"), "2");
  }
  run->set("Chart.SFCInit", "FALSE");
  run->set("Chart.SFCPause", "TRUE");
  ASSERT_TRUE(run->cycles(2));
  EXPECT_EQ(run->text("Chart.Init.X"), "TRUE");
  EXPECT_EQ(run->text("Chart.n"), "2");
  run->set("Chart.SFCPause", "FALSE");
  ASSERT_TRUE(run->cycles(1));
  EXPECT_EQ(run->text("Chart.n"), "3");
  EXPECT_EQ(run->text("Chart.Run.X"), "TRUE");
  run->set("Chart.SFCReset", "TRUE");
  ASSERT_TRUE(run->cycles(1));  // back to Init, which runs and is left in the same cycle
  EXPECT_EQ(run->text("Chart.n"), "4");
  EXPECT_EQ(run->text("Chart.Run.X"), "TRUE");
  run->set("Chart.SFCReset", "FALSE");
  ASSERT_TRUE(run->cycles(1));
  EXPECT_EQ(run->text("Chart.n"), "5");  // Count's final run
}

TEST(RunSfc, TransitionsInIlAndStepFlags) {
  // OpenPCS manual L2510-2545 (seed 003/014): a transition written in IL fires when the CR is
  // TRUE after its code (LD temperature / GT 70). step.T and step.X in conditions (CODESYS V2.3
  // L947-962).
  auto run = run_text(R"(
PROGRAM Chart
VAR temperature : INT; END_VAR
INITIAL_STEP Cold: END_STEP
TRANSITION FROM Cold TO Hot :
LD temperature
GT 70
END_TRANSITION
STEP Hot: END_STEP
TRANSITION FROM Hot TO Cold :
LD Hot.T
GE T#300ms
END_TRANSITION
INITIAL_STEP Watch: END_STEP
TRANSITION FROM Watch TO Seen := Hot.X; END_TRANSITION
STEP Seen: END_STEP
TRANSITION FROM Seen TO Watch := Cold.X; END_TRANSITION
END_PROGRAM
)",
                      {.tick_ns = k100ms});
  ASSERT_CLEAN(run);
  run->set("Chart.temperature", "70");
  ASSERT_TRUE(run->cycles(1));
  EXPECT_EQ(run->text("Chart.Cold.X"), "TRUE");
  run->set("Chart.temperature", "71");
  ASSERT_TRUE(run->cycles(1));  // t = 200 ms: Cold -> Hot
  EXPECT_EQ(run->text("Chart.Hot.X"), "TRUE");
  EXPECT_EQ(run->text("Chart.Seen.X"), "FALSE");
  ASSERT_TRUE(run->cycles(1));  // t = 300 ms: Hot.T = 100 ms; Watch sees Hot.X
  EXPECT_EQ(run->text("Chart.Hot.T"), "T#100ms");
  EXPECT_EQ(run->text("Chart.Seen.X"), "TRUE");
  ASSERT_TRUE(run->cycles(1));  // t = 400 ms
  EXPECT_EQ(run->text("Chart.Hot.X"), "TRUE");
  ASSERT_TRUE(run->cycles(1));  // t = 500 ms: Hot.T = 300 ms -> Cold
  EXPECT_EQ(run->text("Chart.Hot.X"), "FALSE");
  EXPECT_EQ(run->text("Chart.Cold.X"), "TRUE");
}

}  // namespace
}  // namespace rung::run::testing
