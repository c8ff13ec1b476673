// Runs a compiled project cycle by cycle: the tasks of its configuration (or its one program) on
// a clock. The virtual clock advances by a fixed tick per cycle, so every run is reproducible and
// timers are exact; the on-target runtime will drive the same engine from the wall clock.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "runner/compile/compile.hpp"
#include "runner/vm/machine.hpp"

namespace rung::run {

class Engine {
 public:
  // `tick_ns` 0: the shortest task interval, else 10 ms.
  Engine(const CompiledProject& project, uint64_t tick_ns = 0);

  // One cycle: every task due at the current time runs its programs (highest priority first);
  // then the clock advances by one tick. False after a run-time error (machine().error()).
  bool cycle();
  // The end of the run: FB_exit of every instance that declares it (once; later calls do
  // nothing). False after a run-time error in one of them.
  bool finish();

  uint64_t cycles() const { return cycles_; }
  uint64_t now_ns() const { return now_ns_; }
  uint64_t tick_ns() const { return tick_ns_; }
  Machine& machine() { return *machine_; }
  const Machine& machine() const { return *machine_; }
  const CompiledProject& project() const { return project_; }

 private:
  const CompiledProject& project_;
  std::unique_ptr<Machine> machine_;
  uint64_t tick_ns_ = 10'000'000;
  uint64_t now_ns_ = 0;
  uint64_t cycles_ = 0;
  bool finished_ = false;
};

// A run-time error as people read it: "error: division by zero\n  --> file:line:col\n  in ...".
std::string describe_error(const CompiledProject& project, const RunError& error);

}  // namespace rung::run
