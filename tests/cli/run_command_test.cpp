// `rung run` end to end: the real binary on temporary projects (exit codes, the JSON report, the
// table, --set/--watch/--until/--for/--trace, run-time errors with their place).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "tests/support/rung_process.hpp"

namespace rung {
namespace {

class RunCommand : public test::TempFolderTest {
 protected:
  test::RungRun run(const std::string& args) const { return test::run_rung_in(dir_, "run " + args); }
};

constexpr const char* kCounter = R"(TYPE E_Mode : (Idle, Busy); END_TYPE
TYPE ST_Stats : STRUCT
    nCalls : DINT;
    rMean : REAL := 0.5;
END_STRUCT
END_TYPE
PROGRAM Main
VAR
    bEnable : BOOL := TRUE;
    nCount : INT;
    rValue : REAL := 0.1;
    lrValue : LREAL := 0.1;
    sName : STRING(10) := 'pump';
    tElapsed : TIME;
    eMode : E_Mode;
    aHistory : ARRAY[0..2] OF INT;
    stStats : ST_Stats;
    fbDelay : TON;
END_VAR
IF bEnable THEN
    nCount := nCount + 1;
    eMode := Busy;
END_IF
aHistory[nCount MOD 3] := nCount;
tElapsed := tElapsed + T#10ms;
stStats.nCalls := stStats.nCalls + 1;
fbDelay(IN := bEnable, PT := T#20ms);
END_PROGRAM
)";

TEST_F(RunCommand, JsonReportHasTheDocumentedShape) {
  write("Main.st", kCounter);
  test::RungRun result = run("Main.st --cycles 4 --format json");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const nlohmann::ordered_json report = nlohmann::ordered_json::parse(result.out);
  EXPECT_EQ(report["cycles"], 4);
  EXPECT_EQ(report["time"], "T#40ms");
  const nlohmann::ordered_json& main = report["programs"]["Main"];
  EXPECT_EQ(main["bEnable"], true);
  EXPECT_EQ(main["nCount"], 4);
  EXPECT_EQ(main["rValue"].dump(), "0.1");  // a REAL as the shortest text that reads back
  EXPECT_EQ(main["lrValue"].dump(), "0.1");
  EXPECT_EQ(main["sName"], "pump");
  EXPECT_EQ(main["tElapsed"], "T#40ms");
  EXPECT_EQ(main["eMode"], "Busy");
  EXPECT_EQ(main["aHistory"].dump(), "[3,4,2]");
  EXPECT_EQ(main["stStats"].dump(), R"({"nCalls":4,"rMean":0.5})");
  // A standard block shows its interface, not its hidden state.
  EXPECT_EQ(main["fbDelay"].dump(), R"({"IN":true,"PT":"T#20ms","Q":true,"ET":"T#20ms"})");
  // Declaration order is kept.
  std::vector<std::string> names;
  for (const auto& item : main.items()) names.push_back(item.key());
  EXPECT_EQ(names, (std::vector<std::string>{"bEnable", "nCount", "rValue", "lrValue", "sName", "tElapsed", "eMode",
                                             "aHistory", "stStats", "fbDelay"}));
}

TEST_F(RunCommand, TableSetWatchAndTrace) {
  write("Main.st", kCounter);
  test::RungRun result = run("Main.st --cycles 2 --set Main.bEnable=FALSE --set nCount=10 --watch nCount,tElapsed --trace t.csv --color never");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.out.find("cycle    1  T#10ms  nCount=10  tElapsed=T#10ms"), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("after 2 cycles, T#20ms"), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("PROGRAM Main"), std::string::npos) << result.out;
  const size_t row = result.out.find("\n  sName     STRING(10)");
  ASSERT_NE(row, std::string::npos) << result.out;
  EXPECT_EQ(result.out.substr(result.out.find('\n', row + 1) - 6, 6), "'pump'") << result.out;
  EXPECT_EQ(read("t.csv"), "cycle,time,nCount,tElapsed\n1,T#10ms,10,T#10ms\n2,T#20ms,10,T#20ms\n");
}

TEST_F(RunCommand, UntilAndFor) {
  write("Main.st", kCounter);
  test::RungRun until = run("Main.st --until nCount=7 --format json");
  ASSERT_EQ(until.exit_code, 0) << until.err;
  EXPECT_EQ(nlohmann::json::parse(until.out)["cycles"], 7);
  test::RungRun timed = run("Main.st --for T#1s --tick T#100ms --format json");
  ASSERT_EQ(timed.exit_code, 0) << timed.err;
  EXPECT_EQ(nlohmann::json::parse(timed.out)["cycles"], 10);
}

TEST_F(RunCommand, RunTimeErrorExitsOneWithThePlace) {
  write("Main.st", R"(PROGRAM Main
VAR
    a : ARRAY[1..3] OF INT;
    i : INT;
END_VAR
i := i + 1;
a[i] := i;
END_PROGRAM
)");
  test::RungRun result = run("Main.st --cycles 5 --color never");
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_NE(result.err.find("run-time error: array index 4 is outside 1..3\n  --> Main.st:7:3 (in Main)"),
            std::string::npos)
      << result.err;
  EXPECT_NE(result.out.find("after 3 cycles"), std::string::npos) << result.out;
}

TEST_F(RunCommand, ProjectsThatDoNotCheckDoNotRun) {
  write("Main.st", "PROGRAM Main\nVAR x : INT; END_VAR\nx := y;\nEND_PROGRAM\n");
  test::RungRun result = run("Main.st --color never");
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("error[E001]"), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("fix it before running it"), std::string::npos) << result.err;
  test::RungRun unknown = run("Main.st --program Nope");
  EXPECT_EQ(unknown.exit_code, 2);
  test::RungRun missing = run("Missing.st");
  EXPECT_EQ(missing.exit_code, 2);
}

TEST_F(RunCommand, ConfigurationTasksRunAtTheirIntervals) {
  write("Main.st", R"(PROGRAM Fast
VAR n : INT; END_VAR
n := n + 1;
END_PROGRAM
PROGRAM Slow
VAR n : INT; END_VAR
n := n + 1;
END_PROGRAM
CONFIGURATION Plant
RESOURCE Cpu ON PLC
TASK FastTask(INTERVAL := T#10ms, PRIORITY := 1);
TASK SlowTask(INTERVAL := T#50ms, PRIORITY := 2);
PROGRAM fast WITH FastTask : Fast;
PROGRAM slow WITH SlowTask : Slow;
END_RESOURCE
END_CONFIGURATION
)");
  test::RungRun result = run("Main.st --cycles 10 --format json");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const nlohmann::json report = nlohmann::json::parse(result.out);
  EXPECT_EQ(report["programs"]["fast"]["n"], 10);
  EXPECT_EQ(report["programs"]["slow"]["n"], 2);
  EXPECT_EQ(report["time"], "T#100ms");
}

}  // namespace
}  // namespace rung
