// Random well-typed programs (random_program.hpp) through check, compile and run: each checks
// clean, compiles, and runs a few cycles either cleanly or into a run-time error a program can
// cause; two runs of one program end in the same state (the runner is deterministic). The same
// generator drives fuzz/run_fuzzer.cpp with the fuzzer's bytes.
#include "tests/runner/random_program.hpp"

#include <gtest/gtest.h>

#include "runner/inspect.hpp"
#include "tests/runner/run_support.hpp"

namespace rung::run::testing {
namespace {

constexpr const char* kObserved[] = {"i1", "i2", "d1", "d2", "u1", "b1", "b2",  "r1",
                                     "r2", "l1", "w1", "s1", "s2", "t1", "arr", "timer.ET"};

std::string state_of(const Run& run) {
  std::string state;
  for (const char* name : kObserved) state += std::string(name) + "=" + run.text(name) + "\n";
  return state;
}

bool expected_trap(const std::optional<RunError>& error) {
  if (!error) return true;
  return error->kind == TrapKind::DivisionByZero || error->kind == TrapKind::IndexOutOfBounds ||
         error->kind == TrapKind::Watchdog;
}

// Each program is checked with the standard library and run twice: about 0.2 s a program here.
constexpr uint64_t kPrograms = 50;

TEST(RunRandomPrograms, CheckCompileAndRunDeterministically) {
  int clean_runs = 0;
  int trapped_runs = 0;
  for (uint64_t seed = 1; seed <= kPrograms; ++seed) {
    Choices choices(seed);
    const std::string source = random_program(choices, 12);
    auto first = run_text(source, {.cycles = 3, .tick_ns = 20'000'000});
    ASSERT_TRUE(first->check_errors.empty()) << "seed " << seed << ":\n" << joined(first->check_errors) << source;
    ASSERT_TRUE(first->compile_errors.empty()) << "seed " << seed << ":\n" << joined(first->compile_errors) << source;
    ASSERT_TRUE(first->engine);
    const auto& error = first->engine->machine().error();
    ASSERT_TRUE(expected_trap(error)) << "seed " << seed << ": " << first->described_error() << "\n" << source;
    (error ? trapped_runs : clean_runs) += 1;
    auto second = run_text(source, {.cycles = 3, .tick_ns = 20'000'000});
    ASSERT_TRUE(second->engine);
    EXPECT_EQ(first->error(), second->error()) << "seed " << seed;
    EXPECT_EQ(state_of(*first), state_of(*second)) << "seed " << seed << "\n" << source;
  }
  // The generator must mostly produce programs that run: a generator whose programs all trap
  // tests nothing past the first error.
  EXPECT_GT(clean_runs, static_cast<int>(kPrograms / 2))
      << trapped_runs << " of " << kPrograms << " programs ended in a run-time error";
}

}  // namespace
}  // namespace rung::run::testing
