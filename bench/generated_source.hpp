// Realistic generated ST for benchmarks: function blocks with VAR blocks, IF/CASE/FOR, calls,
// comments and pragmas, in the proportions of real TwinCAT/CODESYS code.
#pragma once

#include <random>
#include <string>
#include <string_view>

namespace rung::bench {

// Collects generated ST line by line and counts the lines (benchmarks report lines per second).
class LineWriter {
 public:
  void line(std::string_view text) {
    text_ += text;
    text_ += '\n';
    ++lines_;
  }
  size_t lines() const { return lines_; }
  const std::string& text() const { return text_; }
  std::string take() { return std::move(text_); }

 private:
  std::string text_;
  size_t lines_ = 0;
};

// The VAR_INPUT, VAR_OUTPUT and VAR blocks that write_mixed_statement works on (bEnable,
// rSetpoint, tDelay, bDone, iState, aBuffer, tonDelay, i, rSum), for a FUNCTION_BLOCK.
void write_mixed_statement_variables(LineWriter& out);
// One statement of a typical FB body on those variables: IF/ELSIF, CASE, FOR, a TON call or a
// LIMIT assignment, chosen by `rng`.
void write_mixed_statement(LineWriter& out, std::mt19937& rng);

// About `lines` lines of ST (a little more: whole POUs are emitted).
std::string generate_st(size_t lines, unsigned seed = 1);

}  // namespace rung::bench
