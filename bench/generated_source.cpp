#include "bench/generated_source.hpp"

#include <random>

namespace rung::bench {

std::string generate_st(size_t lines, unsigned seed) {
  std::mt19937 rng(seed);
  std::string out;
  size_t emitted = 0;
  size_t pou = 0;
  auto line = [&](const std::string& s) {
    out += s;
    out += '\n';
    ++emitted;
  };
  while (emitted < lines) {
    std::string name = "FB_Generated" + std::to_string(pou++);
    line("{attribute 'reflection'}");
    line("FUNCTION_BLOCK " + name);
    line("VAR_INPUT");
    line("    bEnable : BOOL;          // enables the block");
    line("    rSetpoint : REAL := 12.5;");
    line("    tDelay : TIME := T#250MS;");
    line("END_VAR");
    line("VAR_OUTPUT");
    line("    bDone : BOOL;");
    line("    iState : INT;");
    line("END_VAR");
    line("VAR");
    line("    aBuffer : ARRAY[0..15] OF INT;");
    line("    tonDelay : TON;");
    line("    i : INT;");
    line("    rSum : REAL;");
    line("END_VAR");
    size_t body = 20 + rng() % 40;
    for (size_t s = 0; s < body; ++s) {
      switch (rng() % 5) {
        case 0:
          line("IF bEnable AND (iState < " + std::to_string(rng() % 100) + ") THEN");
          line("    iState := iState + 1;");
          line("ELSIF NOT bEnable THEN");
          line("    iState := 0; (* reset *)");
          line("END_IF");
          break;
        case 1:
          line("CASE iState OF");
          line("    0: bDone := FALSE;");
          line("    1..5: rSum := rSum + rSetpoint * 2.0;");
          line("ELSE");
          line("    bDone := TRUE;");
          line("END_CASE");
          break;
        case 2:
          line("FOR i := 0 TO 15 BY 1 DO");
          line("    aBuffer[i] := aBuffer[i] + i MOD 3;");
          line("END_FOR");
          break;
        case 3:
          line("tonDelay(IN := bEnable, PT := tDelay);");
          line("bDone := tonDelay.Q OR (rSum > 100.0);");
          break;
        default:
          line("rSum := LIMIT(0.0, rSum + INT_TO_REAL(aBuffer[" + std::to_string(rng() % 16) + "]), 1000.0);");
          break;
      }
    }
    line("END_FUNCTION_BLOCK");
    line("");
  }
  return out;
}

}  // namespace rung::bench
