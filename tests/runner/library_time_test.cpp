// The time and date functions of library/iec/time.st, the LTIME timers of CODESYS Standard64, RTC
// and SEMA, run as programs. Each test states its rule and where it comes from. The stored forms
// are docs/runner.md's: TIME ms, LTIME ns, TOD ms since midnight, DATE and DT seconds since 1970.
#include <gtest/gtest.h>

#include "tests/runner/run_support.hpp"

namespace rung::run::testing {
namespace {

TEST(LibraryTime, AddAndSubtractDurations) {
  // CODESYS V3 textbook ch. 5.5.2 (000b.md L13837, L13879): T#45s + T#50s = T#1m35s and
  // T#1m35s - T#50s = T#45s; the typed names are what + and - mean (IEC 61131-3 table 30).
  auto run = run_text(R"(
PROGRAM Main
VAR
  sum, difference : TIME;
  lsum, ldifference : LTIME;
END_VAR
sum := ADD_TIME(T#45s, T#50s);
difference := SUB_TIME(T#1m35s, T#50s);
lsum := ADD_LTIME(LTIME#1us, LTIME#500ns);
ldifference := SUB_LTIME(LTIME#1ms, LTIME#1ns);
END_PROGRAM
)");
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("sum"), "T#1m35s");
  EXPECT_EQ(run->text("difference"), "T#45s");
  EXPECT_EQ(run->text("lsum"), "LTIME#1us500ns");
  EXPECT_EQ(run->text("ldifference"), "LTIME#999us999ns");
}

TEST(LibraryTime, PointsInTimeMoveByDurations) {
  // IEC 61131-3 table 30 (003.md L5109-5141): TOD +/- TIME is a TOD, DT +/- TIME a DT, and the
  // difference of two TODs, DTs or DATEs a TIME. Textbook fact (000b.md L13883): TOD#23:10:10 -
  // TOD#00:00:00 = T#1390m10s. A DT counts whole seconds, so the milliseconds of IN2 are dropped.
  auto run = run_text(R"(
PROGRAM Main
VAR
  tod1, tod2 : TOD;
  dt1, dt2, dt3 : DT;
  d1, d2, d3 : TIME;
  same : BOOL;
END_VAR
tod1 := ADD_TOD_TIME(TOD#12:00:00, T#1h30m);
tod2 := SUB_TOD_TIME(TOD#00:00:01, T#500ms);
dt1 := ADD_DT_TIME(DT#2024-02-28-23:00:00, T#2h);
dt2 := SUB_DT_TIME(DT#2024-03-01-00:00:00, T#1s);
dt3 := ADD_DT_TIME(DT#2024-01-01-00:00:00, T#1s999ms);
d1 := SUB_TOD_TOD(TOD#23:10:10, TOD#00:00:00);
d2 := SUB_DT_DT(DT#2024-03-01-00:00:00, DT#2024-02-28-12:00:00);
d3 := SUB_DATE_DATE(D#2024-03-01, D#2024-02-28);
same := d1 = T#1390m10s;
END_PROGRAM
)");
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("tod1"), "TOD#13:30:00");
  EXPECT_EQ(run->text("tod2"), "TOD#00:00:00.5");
  EXPECT_EQ(run->text("dt1"), "DT#2024-02-29-01:00:00");  // 2024 is a leap year
  EXPECT_EQ(run->text("dt2"), "DT#2024-02-29-23:59:59");
  EXPECT_EQ(run->text("dt3"), "DT#2024-01-01-00:00:01");
  EXPECT_EQ(run->text("same"), "TRUE");
  EXPECT_EQ(run->text("d2"), "T#1d12h");
  EXPECT_EQ(run->text("d3"), "T#2d");
}

TEST(LibraryTime, MultiplyAndDivideDurationsAsTheOperatorsDo) {
  // IEC 61131-3 table 30: MUL_TIME/DIV_TIME (ed.2 MULTIME, DIVTIME; 003.md L9422-9461, L8117-8137)
  // take any number. An integer factor scales the millisecond count (division truncates); a REAL
  // factor is applied and rounded like REAL_TO_<int>. Each equals the operator form.
  auto run = run_text(R"(
PROGRAM Main
VAR
  m1, m2, q1, q2, q3 : TIME;
  lm, lq : LTIME;
  same : BOOL;
  n : INT := 3;
END_VAR
m1 := MUL_TIME(T#1s500ms, 3);
m2 := MUL_TIME(T#1s, 2.5);
q1 := DIV_TIME(T#10s, 4);
q2 := DIV_TIME(T#1s, n);
q3 := DIV_TIME(T#1s, 0.3);
lm := MUL_LTIME(LTIME#1us, 1000);
lq := DIV_LTIME(LTIME#1ms, 3);
same := MUL_TIME(T#7ms, n) = T#7ms * n AND DIV_TIME(T#7ms, n) = T#7ms / n;
END_PROGRAM
)");
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("m1"), "T#4s500ms");
  EXPECT_EQ(run->text("m2"), "T#2s500ms");
  EXPECT_EQ(run->text("q1"), "T#2s500ms");
  EXPECT_EQ(run->text("q2"), "T#333ms");
  EXPECT_EQ(run->text("q3"), "T#3s333ms");
  EXPECT_EQ(run->text("lm"), "LTIME#1ms");
  EXPECT_EQ(run->text("lq"), "LTIME#333us333ns");
  EXPECT_EQ(run->text("same"), "TRUE");
}

TEST(LibraryTime, DivisionOfADurationByZeroStopsTheRun) {
  // As for integers (docs/runner.md, semantics table): division by zero is a run-time error.
  auto run = run_text(R"(
PROGRAM Main
VAR
  q : TIME;
  n : INT;
END_VAR
q := DIV_TIME(T#1s, n);
END_PROGRAM
)");
  ASSERT_TRUE(run->check_errors.empty()) << joined(run->check_errors);
  EXPECT_NE(run->error(), "");
}

TEST(LibraryTime, ConcatBuildsDatesAndTimes) {
  // IEC 61131-3 ed.3 table 36: CONCAT_DATE(year, month, day), CONCAT_TOD(hour, minute, second,
  // millisecond), CONCAT_DT (the seven fields), CONCAT_DATE_TOD(date, time of day). DT counts
  // seconds, so the milliseconds are dropped. Fields beyond their range carry over (rung's choice:
  // month 13 of 2023 is January 2024, 61 minutes are 1 h 1 min).
  auto run = run_text(R"(
PROGRAM Main
VAR
  d1, d2, d3 : DATE;
  t1, t2 : TOD;
  dt1, dt2 : DT;
END_VAR
d1 := CONCAT_DATE(2024, 2, 29);
d2 := CONCAT_DATE(YEAR := 2023, MONTH := 13, DAY := 1);
d3 := CONCAT_DATE(INT#1970, 1, 1);
t1 := CONCAT_TOD(12, 34, 56, 789);
t2 := CONCAT_TOD(0, 61, 0, 0);
dt1 := CONCAT_DT(2000, 1, 1, 23, 59, 59, 999);
dt2 := CONCAT_DATE_TOD(D#2024-02-29, TOD#12:34:56.789);
END_PROGRAM
)");
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("d1"), "D#2024-02-29");
  EXPECT_EQ(run->text("d2"), "D#2024-01-01");
  EXPECT_EQ(run->text("d3"), "D#1970-01-01");
  EXPECT_EQ(run->text("t1"), "TOD#12:34:56.789");
  EXPECT_EQ(run->text("t2"), "TOD#01:01:00");
  EXPECT_EQ(run->text("dt1"), "DT#2000-01-01-23:59:59");
  EXPECT_EQ(run->text("dt2"), "DT#2024-02-29-12:34:56");
}

TEST(LibraryTime, SplitTakesDatesAndTimesApart) {
  // IEC 61131-3 ed.3 table 36: SPLIT_DATE, SPLIT_TOD and SPLIT_DT give the fields as outputs; the
  // Gregorian calendar (2000 is a leap year, 2100 is not); a DT has no milliseconds.
  auto run = run_text(R"(
PROGRAM Main
VAR
  y1, m1, d1, y2, m2, d2, y3, m3, d3 : INT;
  h, mi, s, ms : INT;
  dy, dm, dd, dh, dmi, ds, dms : INT;
  ok : BOOL;
END_VAR
ok := SPLIT_DATE(IN := D#2024-02-29, YEAR => y1, MONTH => m1, DAY => d1);
SPLIT_DATE(IN := D#2000-03-01, YEAR => y2, MONTH => m2, DAY => d2);
SPLIT_DATE(IN := UDINT_TO_DATE(DATE_TO_UDINT(D#2100-02-28) + 86400), YEAR => y3, MONTH => m3, DAY => d3);
SPLIT_TOD(IN := TOD#23:59:59.999, HOUR => h, MINUTE => mi, SECOND => s, MILLISECOND => ms);
SPLIT_DT(IN := DT#1999-12-31-23:58:07, YEAR => dy, MONTH => dm, DAY => dd, HOUR => dh, MINUTE => dmi,
         SECOND => ds, MILLISECOND => dms);
END_PROGRAM
)");
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("ok"), "TRUE");
  EXPECT_EQ(run->text("y1") + "-" + run->text("m1") + "-" + run->text("d1"), "2024-2-29");
  EXPECT_EQ(run->text("y2") + "-" + run->text("m2") + "-" + run->text("d2"), "2000-3-1");
  EXPECT_EQ(run->text("y3") + "-" + run->text("m3") + "-" + run->text("d3"), "2100-3-1");
  EXPECT_EQ(run->text("h") + ":" + run->text("mi") + ":" + run->text("s") + "." + run->text("ms"), "23:59:59.999");
  EXPECT_EQ(run->text("dy") + "-" + run->text("dm") + "-" + run->text("dd") + "-" + run->text("dh") + ":" +
                run->text("dmi") + ":" + run->text("ds") + "." + run->text("dms"),
            "1999-12-31-23:58:7.0");
}

TEST(LibraryTime, SplitDateRoundTripsEveryDayOfFiveCenturies) {
  // CONCAT_DATE and SPLIT_DATE are inverse on every day DATE can hold (1970-01-01 .. 2106-02-07).
  auto run = run_text(R"(
PROGRAM Main
VAR
  d : DATE;
  y, m, dd : INT;
  days, bad : DINT;
  last : DATE;
END_VAR
FOR days := 0 TO 49709 DO
  d := UDINT_TO_DATE(DINT_TO_UDINT(days) * 86400);
  SPLIT_DATE(IN := d, YEAR => y, MONTH => m, DAY => dd);
  IF CONCAT_DATE(y, m, dd) <> d THEN
    bad := bad + 1;
  END_IF
  last := d;
END_FOR
END_PROGRAM
)");
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("bad"), "0");
  EXPECT_EQ(run->text("last"), "D#2106-02-06");
}

TEST(LibraryTime, DayOfWeekCountsFromSunday) {
  // IEC 61131-3 ed.3 table 36: DAY_OF_WEEK gives 0 for Sunday ... 6 for Saturday. 1970-01-01 was a
  // Thursday.
  auto run = run_text(R"(
PROGRAM Main
VAR
  a, b, c, d : INT;
END_VAR
a := DAY_OF_WEEK(D#1970-01-01);
b := DAY_OF_WEEK(D#2024-02-29);
c := DAY_OF_WEEK(D#2023-10-01);
d := DAY_OF_WEEK(D#2023-09-30);
END_PROGRAM
)");
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("a"), "4");
  EXPECT_EQ(run->text("b"), "4");
  EXPECT_EQ(run->text("c"), "0");
  EXPECT_EQ(run->text("d"), "6");
}

TEST(LibraryTime, LongTimersCountNanoseconds) {
  // CODESYS Standard64 LTON/LTOF/LTP behave as TON/TOF/TP (000b.md L12292-12366) with LTIME: on a
  // 250 us tick an LTON of 600 us elapses in the 4th cycle (clock 750 us), which a TIME (ms) timer
  // cannot resolve.
  auto run = run_text(R"(
PROGRAM Main
VAR
  in : BOOL;
  delay : LTON;
  offdelay : LTOF;
  pulse : LTP;
END_VAR
delay(IN := in, PT := LTIME#600us);
offdelay(IN := in, PT := LTIME#600us);
pulse(IN := in, PT := LTIME#600us);
END_PROGRAM
)", {.cycles = 0, .tick_ns = 250'000});
  ASSERT_TRUE(run->engine) << joined(run->check_errors) << joined(run->compile_errors);
  EXPECT_EQ(sequence(*run, "in", {"TRUE", "TRUE", "TRUE", "TRUE", "TRUE"}, "delay.Q"), "FALSE,FALSE,FALSE,TRUE,TRUE");
  EXPECT_EQ(run->text("delay.ET"), "LTIME#600us");
  EXPECT_EQ(run->text("pulse.Q"), "FALSE");
  EXPECT_EQ(run->text("pulse.ET"), "LTIME#600us");
  EXPECT_EQ(run->text("offdelay.Q"), "TRUE");
  EXPECT_EQ(sequence(*run, "in", {"FALSE", "FALSE", "FALSE", "FALSE"}, "offdelay.Q"), "TRUE,TRUE,TRUE,FALSE");
  EXPECT_EQ(run->text("offdelay.ET"), "LTIME#600us");
  EXPECT_EQ(run->text("delay.Q"), "FALSE");
  EXPECT_EQ(run->text("delay.ET"), "LTIME#0ms");
  EXPECT_EQ(run->text("pulse.ET"), "LTIME#0ms");
}

TEST(LibraryTime, LongTimeClockIsReadable) {
  // __LTIME(): rung's clock in nanoseconds (docs/library.md); cycle 1 runs at 0.
  auto run = run_text(R"(
PROGRAM Main
VAR
  now : LTIME;
  ms : TIME;
END_VAR
now := __LTIME();
ms := TIME();
END_PROGRAM
)", {.cycles = 3, .tick_ns = 1'500'000});
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("now"), "LTIME#3ms");
  EXPECT_EQ(run->text("ms"), "T#3ms");
}

TEST(LibraryTime, RealTimeClockRunsFromItsPreset) {
  // RTC (000b.md L12474-12496, fact 14): EN FALSE -> Q FALSE, CDT = DT#1970-01-01-00:00:00; the
  // rising edge of EN loads PDT, then CDT advances with the clock in whole seconds.
  auto run = run_text(R"(
PROGRAM Main
VAR
  en : BOOL;
  clock : RTC;
END_VAR
clock(EN := en, PDT := DT#2024-01-31-23:59:59);
END_PROGRAM
)", {.cycles = 1, .tick_ns = 500'000'000});
  ASSERT_CLEAN(run);
  EXPECT_EQ(run->text("clock.Q"), "FALSE");
  EXPECT_EQ(run->text("clock.CDT"), "DT#1970-01-01-00:00:00");
  EXPECT_EQ(sequence(*run, "en", {"TRUE", "TRUE", "TRUE", "TRUE", "TRUE"}, "clock.CDT"),
            "DT#2024-01-31-23:59:59,DT#2024-01-31-23:59:59,DT#2024-02-01-00:00:00,DT#2024-02-01-00:00:00,"
            "DT#2024-02-01-00:00:01");
  EXPECT_EQ(run->text("clock.Q"), "TRUE");
  EXPECT_EQ(sequence(*run, "en", {"FALSE"}, "clock.CDT"), "DT#1970-01-01-00:00:00");
  EXPECT_EQ(run->text("clock.Q"), "FALSE");
}

TEST(LibraryTime, SemaphoreReportsWhetherItWasTaken) {
  // SEMA (IEC 61131-3 ed.1 2.5.2.3.1; CODESYS Standard): BUSY is the state before the call, so the
  // first CLAIM gets it (BUSY FALSE), the next CLAIM finds it taken (TRUE); RELEASE frees it.
  auto run = run_text(R"(
PROGRAM Main
VAR
  claim, release : BOOL;
  s : SEMA;
END_VAR
s(CLAIM := claim, RELEASE := release);
END_PROGRAM
)", {.cycles = 0});
  ASSERT_TRUE(run->engine) << joined(run->check_errors) << joined(run->compile_errors);
  EXPECT_EQ(sequence(*run, "claim", {"TRUE", "TRUE", "FALSE"}, "s.BUSY"), "FALSE,TRUE,TRUE");
  run->set("release", "TRUE");
  EXPECT_EQ(sequence(*run, "claim", {"FALSE", "FALSE"}, "s.BUSY"), "FALSE,FALSE");
  run->set("release", "FALSE");
  EXPECT_EQ(sequence(*run, "claim", {"TRUE"}, "s.BUSY"), "FALSE");
}

}  // namespace
}  // namespace rung::run::testing
