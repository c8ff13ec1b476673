// The interpreter: executes a Program over one flat byte-addressed memory (image, call-frame
// stack, heap). Nothing here reads the host clock: the caller sets the time before each cycle.
#pragma once

#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

#include "runner/vm/program.hpp"

namespace rung::run {

union Slot {
  int64_t i;
  uint64_t u;
  float f32;
  double f64;
};

struct StackEntry {
  uint32_t callable = kNoCallable;
  uint32_t pc = 0;  // the instruction running in it (the call, for callers)
};

// A run-time error: what happened, where, and the calls that led there (innermost first).
struct RunError {
  TrapKind kind = TrapKind::Unsupported;
  std::string message;
  std::vector<StackEntry> stack;
};

class Machine {
 public:
  explicit Machine(const Program& program);

  const Program& program() const { return program_; }

  // Calls `callable` with THIS = `instance` (0 for none) and no arguments: a program's cycle, an
  // init routine. False after a run-time error (see error()).
  bool call(uint32_t callable, uint64_t instance);

  // Virtual or wall time, in nanoseconds since the start; read by TIME(), LTIME() and the timers.
  void set_time_ns(uint64_t now) { now_ns_ = now; }
  uint64_t time_ns() const { return now_ns_; }
  // Backward jumps allowed in one call() before the watchdog stops the run.
  void set_loop_budget(uint64_t budget) { loop_budget_ = budget; }

  const std::optional<RunError>& error() const { return error_; }

  // Memory access for the outside (reports, --set, tests).
  uint8_t* memory() { return memory_.data(); }
  const uint8_t* memory() const { return memory_.data(); }
  uint64_t memory_size() const { return memory_.size(); }
  bool valid(uint64_t address, uint64_t bytes) const {
    return address >= kNullGuard && address <= memory_.size() && bytes <= memory_.size() - address;
  }

  // --- for natives --------------------------------------------------------------------------
  Slot pop() { return *--sp_; }
  void push(Slot value) { *sp_++ = value; }
  void push_i(int64_t value) { (sp_++)->i = value; }
  void push_f32(float value) { (sp_++)->f32 = value; }
  void push_f64(double value) { (sp_++)->f64 = value; }
  Slot& top() { return sp_[-1]; }
  // Stops the run with an error at the current instruction.
  void trap(TrapKind kind, std::string message);
  // A pointer into memory for `bytes` bytes at `address`, or nullptr after a trap.
  uint8_t* checked(uint64_t address, uint64_t bytes);
  // __NEW / __DELETE: a block of the heap, zeroed; 0 when the heap is exhausted.
  uint64_t allocate(uint64_t bytes);
  void release(uint64_t address);

 private:
  bool execute(uint32_t entry_pc);

  const Program& program_;
  std::vector<uint8_t> memory_;
  uint64_t stack_begin_ = 0;
  uint64_t stack_end_ = 0;
  uint64_t heap_begin_ = 0;
  uint64_t heap_top_ = 0;
  std::vector<std::pair<uint64_t, uint64_t>> free_blocks_;  // address, size
  std::vector<std::pair<uint64_t, uint64_t>> live_blocks_;  // address, size (sorted)

  std::vector<Slot> values_;
  Slot* sp_ = nullptr;
  Slot* values_limit_ = nullptr;

  uint64_t call_instance_ = 0;
  uint64_t now_ns_ = 0;
  uint64_t loop_budget_ = 100'000'000;
  uint32_t current_pc_ = 0;
  std::vector<StackEntry> call_stack_;
  std::optional<RunError> error_;

  // The interpreter's return stack and the frames opened by FRAME whose CALL has not come yet:
  // members, so that their memory is kept from call to call (a cycle allocates nothing).
  struct Return {
    const Instr* pc;
    uint64_t inst;
    uint64_t frame;
  };
  std::vector<Return> returns_;
  std::vector<uint64_t> pending_;
};

}  // namespace rung::run
