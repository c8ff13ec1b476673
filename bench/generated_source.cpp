#include "bench/generated_source.hpp"

namespace rung::bench {

void write_mixed_statement_variables(LineWriter& out) {
  out.line("VAR_INPUT");
  out.line("    bEnable : BOOL;          // enables the block");
  out.line("    rSetpoint : REAL := 12.5;");
  out.line("    tDelay : TIME := T#250MS;");
  out.line("END_VAR");
  out.line("VAR_OUTPUT");
  out.line("    bDone : BOOL;");
  out.line("    iState : INT;");
  out.line("END_VAR");
  out.line("VAR");
  out.line("    aBuffer : ARRAY[0..15] OF INT;");
  out.line("    tonDelay : TON;");
  out.line("    i : INT;");
  out.line("    rSum : REAL;");
  out.line("END_VAR");
}

void write_mixed_statement(LineWriter& out, std::mt19937& rng) {
  switch (rng() % 5) {
    case 0:
      out.line("IF bEnable AND (iState < " + std::to_string(rng() % 100) + ") THEN");
      out.line("    iState := iState + 1;");
      out.line("ELSIF NOT bEnable THEN");
      out.line("    iState := 0; (* reset *)");
      out.line("END_IF");
      break;
    case 1:
      out.line("CASE iState OF");
      out.line("    0: bDone := FALSE;");
      out.line("    1..5: rSum := rSum + rSetpoint * 2.0;");
      out.line("ELSE");
      out.line("    bDone := TRUE;");
      out.line("END_CASE");
      break;
    case 2:
      out.line("FOR i := 0 TO 15 BY 1 DO");
      out.line("    aBuffer[i] := aBuffer[i] + i MOD 3;");
      out.line("END_FOR");
      break;
    case 3:
      out.line("tonDelay(IN := bEnable, PT := tDelay);");
      out.line("bDone := tonDelay.Q OR (rSum > 100.0);");
      break;
    default:
      out.line("rSum := LIMIT(0.0, rSum + INT_TO_REAL(aBuffer[" + std::to_string(rng() % 16) + "]), 1000.0);");
      break;
  }
}

std::string generate_st(size_t lines, unsigned seed) {
  std::mt19937 rng(seed);
  LineWriter out;
  size_t pou = 0;
  while (out.lines() < lines) {
    out.line("{attribute 'reflection'}");
    out.line("FUNCTION_BLOCK FB_Generated" + std::to_string(pou++));
    write_mixed_statement_variables(out);
    const size_t body = 20 + rng() % 40;
    for (size_t s = 0; s < body; ++s) write_mixed_statement(out, rng);
    out.line("END_FUNCTION_BLOCK");
    out.line("");
  }
  return out.take();
}

}  // namespace rung::bench
