// Random well-typed ST programs for the runner's property test and fuzzer: a choice source (a
// seed, or the fuzzer's bytes) picks statements and expressions over a fixed set of variables of
// every elementary kind, nested IF/CASE/FOR/WHILE, arrays, strings, TIME, standard functions and
// a TON. Every generated program must check clean; running it may end in a run-time error only
// of the kinds a program can cause (division by zero, an index out of bounds, the watchdog).
#pragma once

#include <cstdint>
#include <random>
#include <string>
#include <string_view>

namespace rung::run::testing {

// Where the generator's choices come from.
class Choices {
 public:
  explicit Choices(uint64_t seed) : random_(seed) {}
  Choices(const uint8_t* data, size_t size) : data_(data), size_(size), from_bytes_(true) {}
  // A number in 0 .. count-1.
  uint32_t pick(uint32_t count);
  bool exhausted() const { return from_bytes_ && at_ >= size_; }

 private:
  std::mt19937_64 random_{0};
  const uint8_t* data_ = nullptr;
  size_t size_ = 0;
  size_t at_ = 0;
  bool from_bytes_ = false;
};

// One PROGRAM PLC_PRG (with its variables) of about `statements` statements.
std::string random_program(Choices& choices, int statements);

}  // namespace rung::run::testing
