#include "tests/runner/random_program.hpp"

#include <array>
#include <vector>

namespace rung::run::testing {

uint32_t Choices::pick(uint32_t count) {
  if (count <= 1) return 0;
  if (!from_bytes_) return static_cast<uint32_t>(random_() % count);
  if (at_ >= size_) return 0;  // out of bytes: always the first (simplest) choice
  return data_[at_++] % count;
}

namespace {

enum class Kind { Int, Dint, Uint, Bool, Real, Lreal, Word, String, Time };

struct Variable {
  std::string_view name;
  Kind kind;
};

// The program's variables; `k0`..`k3` are FOR counters, never assigned elsewhere.
constexpr std::array kVariables = {
    Variable{"i1", Kind::Int},    Variable{"i2", Kind::Int},   Variable{"d1", Kind::Dint}, Variable{"d2", Kind::Dint},
    Variable{"u1", Kind::Uint},   Variable{"b1", Kind::Bool},  Variable{"b2", Kind::Bool}, Variable{"r1", Kind::Real},
    Variable{"r2", Kind::Real},   Variable{"l1", Kind::Lreal}, Variable{"w1", Kind::Word}, Variable{"s1", Kind::String},
    Variable{"s2", Kind::String}, Variable{"t1", Kind::Time},
};

constexpr std::string_view kDeclarations = R"(PROGRAM PLC_PRG
VAR
  i1 : INT := 3;
  i2 : INT := -7;
  d1 : DINT := 100000;
  d2 : DINT;
  u1 : UINT := 65000;
  b1 : BOOL := TRUE;
  b2 : BOOL;
  r1 : REAL := 1.5;
  r2 : REAL := -0.25;
  l1 : LREAL := 2.0;
  w1 : WORD := 16#F0F0;
  s1 : STRING(20) := 'abc';
  s2 : STRING(20);
  t1 : TIME := T#1S;
  arr : ARRAY[0..9] OF INT := [1, 2, 3, 4, 5, 6, 7, 8, 9, 10];
  k0, k1, k2, k3 : INT;
  n : DINT;
  timer : TON;
END_VAR
)";

class Generator {
 public:
  explicit Generator(Choices& choices) : choices_(choices) {}

  std::string program(int statements) {
    std::string out(kDeclarations);
    for (int i = 0; i < statements && !choices_.exhausted(); ++i) out += statement(1);
    out += "timer(IN := b1, PT := T#50MS);\nEND_PROGRAM\n";
    return out;
  }

 private:
  uint32_t pick(uint32_t count) { return choices_.pick(count); }

  std::string variable_of(Kind kind) {
    std::vector<std::string_view> names;
    for (const Variable& v : kVariables) {
      if (v.kind == kind) names.emplace_back(v.name);
    }
    return std::string(names[pick(static_cast<uint32_t>(names.size()))]);
  }

  std::string indent(int depth) { return std::string(static_cast<size_t>(depth) * 2, ' '); }

  std::string statement(int depth) {
    const uint32_t limit = depth >= 3 ? 2 : 8;
    switch (pick(limit)) {
      case 0: {
        const Variable& target = kVariables[pick(static_cast<uint32_t>(kVariables.size()))];
        return indent(depth) + std::string(target.name) + " := " + expression(target.kind, 0) + ";\n";
      }
      case 1: return indent(depth) + "arr[" + index() + "] := " + expression(Kind::Int, 0) + ";\n";
      case 2: {
        std::string out = indent(depth) + "IF " + expression(Kind::Bool, 0) + " THEN\n" + block(depth + 1);
        if (pick(2)) out += indent(depth) + "ELSIF " + expression(Kind::Bool, 0) + " THEN\n" + block(depth + 1);
        if (pick(2)) out += indent(depth) + "ELSE\n" + block(depth + 1);
        return out + indent(depth) + "END_IF\n";
      }
      case 3: {
        const std::string counter = "k" + std::to_string(depth);
        return indent(depth) + "FOR " + counter + " := " + std::to_string(pick(3)) + " TO " + std::to_string(pick(6)) +
               (pick(2) ? " BY 2" : "") + " DO\n" + block(depth + 1) + indent(depth) + "END_FOR\n";
      }
      case 4: {
        std::string out = indent(depth) + "CASE " + expression(Kind::Int, 1) + " OF\n";
        out += indent(depth + 1) + "0: " + simple() + indent(depth + 1) + "1, 2: " + simple();
        out += indent(depth + 1) + "3..10: " + simple();
        if (pick(2)) out += indent(depth + 1) + "ELSE\n" + block(depth + 2);
        return out + indent(depth) + "END_CASE\n";
      }
      case 5:
        // A bounded WHILE: n counts down.
        return indent(depth) + "n := " + std::to_string(pick(5)) + ";\n" + indent(depth) + "WHILE n > 0 DO\n" +
               indent(depth + 1) + "n := n - 1;\n" + block(depth + 1) + indent(depth) + "END_WHILE\n";
      case 6: return indent(depth) + "s2 := " + expression(Kind::String, 0) + ";\n";
      default: return indent(depth) + variable_of(Kind::Bool) + " := timer.Q OR " + expression(Kind::Bool, 1) + ";\n";
    }
  }

  std::string simple() {
    const Variable& target = kVariables[pick(static_cast<uint32_t>(kVariables.size()))];
    return std::string(target.name) + " := " + expression(target.kind, 2) + ";\n";
  }

  std::string block(int depth) {
    std::string out;
    const uint32_t count = 1 + pick(2);
    for (uint32_t i = 0; i < count; ++i) out += statement(depth);
    return out;
  }

  // An index that is usually inside 0..9 and sometimes not (a run-time error is a valid outcome).
  std::string index() {
    // A variable in it keeps the checker from folding a constant index outside the bounds.
    if (pick(8) == 0) return "(i1 + " + expression(Kind::Int, 2) + ")";
    return "ABS(" + expression(Kind::Int, 2) + " MOD 10)";
  }

  std::string literal(Kind kind) {
    switch (kind) {
      case Kind::Int: return std::to_string(static_cast<int>(pick(200)) - 100);
      case Kind::Dint: return std::to_string(static_cast<int>(pick(100000)) - 50000);
      case Kind::Uint: return std::to_string(pick(70000) % 65536);
      case Kind::Bool: return pick(2) ? "TRUE" : "FALSE";
      case Kind::Real: return std::to_string(static_cast<int>(pick(100)) - 50) + ".5";
      case Kind::Lreal: return std::to_string(pick(1000)) + ".125";
      case Kind::Word: return "16#" + std::to_string(1000 + pick(8000));
      case Kind::String: return pick(2) ? "'xy'" : "'PLC line 7'";
      case Kind::Time: return "T#" + std::to_string(pick(5000)) + "MS";
    }
    return "0";
  }

  std::string expression(Kind kind, int depth) {
    if (depth >= 3 || pick(3) == 0) return pick(2) ? literal(kind) : variable_of(kind);
    const std::string a = expression(kind, depth + 1);
    switch (kind) {
      case Kind::Int:
        switch (pick(9)) {
          // Integer operators take a variable on the right: a constant expression that overflows
          // its type is a check error, not something to run.
          case 0: return "(" + a + " + " + variable_of(kind) + ")";
          case 1: return "(" + a + " - " + variable_of(kind) + ")";
          case 2: return "(" + a + " * " + variable_of(kind) + ")";
          // Divisors are variables: a constant zero divisor is a check error, not a run.
          case 3: return "(" + a + " / " + variable_of(kind) + ")";
          case 4: return "(" + a + " MOD " + variable_of(kind) + ")";
          case 5: return "LIMIT(-50, " + a + ", 50)";
          case 6: return "DINT_TO_INT(" + expression(Kind::Dint, depth + 1) + ")";
          case 7: return "REAL_TO_INT(" + expression(Kind::Real, depth + 1) + ")";
          default: return "arr[" + index() + "]";
        }
      case Kind::Dint:
        switch (pick(5)) {
          case 0: return "(" + a + " + " + variable_of(kind) + ")";
          case 1: return "(" + a + " * " + variable_of(kind) + ")";
          case 2: return "INT_TO_DINT(" + expression(Kind::Int, depth + 1) + ")";
          case 3: return "MAX(" + a + ", " + expression(kind, depth + 1) + ")";
          default: return "TIME_TO_DINT(" + expression(Kind::Time, depth + 1) + ")";
        }
      case Kind::Uint:
        switch (pick(3)) {
          case 0: return "(" + a + " + " + variable_of(kind) + ")";
          case 1: return "(" + a + " - " + variable_of(kind) + ")";
          default: return "WORD_TO_UINT(" + expression(Kind::Word, depth + 1) + ")";
        }
      case Kind::Bool:
        switch (pick(7)) {
          case 0: return "(" + a + " AND " + expression(kind, depth + 1) + ")";
          case 1: return "(" + a + " OR " + expression(kind, depth + 1) + ")";
          case 2: return "(" + a + " XOR " + expression(kind, depth + 1) + ")";
          case 3: return "NOT " + a;
          case 4: return "(" + expression(Kind::Int, depth + 1) + " < " + expression(Kind::Int, depth + 1) + ")";
          case 5: return "(" + expression(Kind::Real, depth + 1) + " >= " + expression(Kind::Real, depth + 1) + ")";
          default: return "(" + expression(Kind::String, depth + 1) + " = 'abc')";
        }
      case Kind::Real:
        switch (pick(5)) {
          case 0: return "(" + a + " + " + expression(kind, depth + 1) + ")";
          case 1: return "(" + a + " * " + expression(kind, depth + 1) + ")";
          case 2: return "INT_TO_REAL(" + expression(Kind::Int, depth + 1) + ")";
          case 3: return "SQRT(ABS(" + a + "))";
          default: return "LREAL_TO_REAL(" + expression(Kind::Lreal, depth + 1) + ")";
        }
      case Kind::Lreal:
        switch (pick(3)) {
          case 0: return "(" + a + " - " + expression(kind, depth + 1) + ")";
          case 1: return "REAL_TO_LREAL(" + expression(Kind::Real, depth + 1) + ")";
          default: return "(" + a + " / 3.0)";
        }
      case Kind::Word:
        switch (pick(4)) {
          case 0: return "(" + a + " AND " + expression(kind, depth + 1) + ")";
          case 1: return "SHL(" + a + ", " + std::to_string(pick(17)) + ")";
          case 2: return "ROR(" + a + ", " + std::to_string(pick(17)) + ")";
          default: return "INT_TO_WORD(" + expression(Kind::Int, depth + 1) + ")";
        }
      case Kind::String:
        switch (pick(4)) {
          case 0: return "CONCAT(" + a + ", " + expression(kind, depth + 1) + ")";
          case 1: return "LEFT(" + a + ", " + std::to_string(pick(6)) + ")";
          case 2: return "INT_TO_STRING(" + expression(Kind::Int, depth + 1) + ")";
          default: return "REPLACE(" + a + ", 'Q', 1, 2)";
        }
      case Kind::Time:
        switch (pick(3)) {
          case 0: return "(" + a + " + " + expression(kind, depth + 1) + ")";
          case 1: return "(" + a + " - T#10MS)";
          default: return "timer.ET";
        }
    }
    return a;
  }

  Choices& choices_;
};

}  // namespace

std::string random_program(Choices& choices, int statements) {
  return Generator(choices).program(statements);
}

}  // namespace rung::run::testing
