// The runner's speed: each workload runs once as PLC code in the VM (one cycle of a program) and
// once as the same algorithm in plain C++, so the ratio says what the interpreter costs. Also the
// empty cycle's overhead and the heap allocations per cycle (which must be 0: a PLC cycle never
// allocates). Results and the goals they are held against: docs/performance.md.
#include <benchmark/benchmark.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <new>
#include <string>
#include <vector>

#include "checker/check.hpp"
#include "runner/compile/compile.hpp"
#include "runner/engine.hpp"
#include "runner/inspect.hpp"

// Every allocation of the process is counted, so that a benchmark can report allocations per cycle.
namespace {
std::atomic<uint64_t> g_allocations{0};
}  // namespace

void* operator new(std::size_t size) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t size) {
  return operator new(size);
}
void operator delete(void* p) noexcept {
  std::free(p);
}
void operator delete[](void* p) noexcept {
  std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
  std::free(p);
}
void operator delete[](void* p, std::size_t) noexcept {
  std::free(p);
}

namespace {

using rung::run::CompiledProject;
using rung::run::Engine;

// A checked, compiled program ready to run; stops the benchmark binary when the source has errors
// (a benchmark of code that does not run would time nothing).
struct Loaded {
  std::unique_ptr<rung::check::Workspace> workspace;
  CompiledProject project;
  std::unique_ptr<Engine> engine;
};

std::unique_ptr<Loaded> load(const std::string& source) {
  auto loaded = std::make_unique<Loaded>();
  rung::project::ProjectConfig config;
  config.profile = rung::project::Profile::Codesys;
  loaded->workspace = rung::check::Workspace::from_texts({{"bench.st", source}}, config);
  for (const rung::check::FileDiagnostics& file : loaded->workspace->check_all(1)) {
    for (const rung::Diagnostic& diagnostic : file.diagnostics) {
      if (diagnostic.severity != rung::Severity::Error) continue;
      std::fprintf(stderr, "error: benchmark program does not check: [%s] %s\n", diagnostic.code.c_str(),
                   diagnostic.message.c_str());
      std::exit(2);
    }
  }
  loaded->project = rung::run::compile_project(loaded->workspace->model(), {});
  if (!loaded->project.ok()) {
    std::fprintf(stderr, "error: benchmark program does not compile: %s\n",
                 loaded->project.errors.front().message.c_str());
    std::exit(2);
  }
  loaded->engine = std::make_unique<Engine>(loaded->project, 0);
  return loaded;
}

// Runs cycles of `source`'s program; reports allocations per cycle.
void run_cycles(benchmark::State& state, const std::string& source) {
  auto loaded = load(source);
  Engine& engine = *loaded->engine;
  if (!engine.cycle()) {  // the first cycle outside the timing (it may initialise)
    state.SkipWithError("run-time error in the first cycle");
    return;
  }
  const uint64_t before = g_allocations.load();
  for (auto _ : state) {
    if (!engine.cycle()) {
      state.SkipWithError("run-time error");
      return;
    }
  }
  state.counters["allocs_per_cycle"] =
      benchmark::Counter(static_cast<double>(g_allocations.load() - before) / static_cast<double>(state.iterations()));
}

// --- integer arithmetic: 10,000 iterations of a DINT loop a cycle -----------------------------------

void BM_Vm_IntLoop(benchmark::State& state) {
  run_cycles(state, R"(
PROGRAM PLC_PRG
VAR
  i, acc : DINT;
END_VAR
acc := 0;
FOR i := 1 TO 10000 DO
  acc := acc + (i * 3) MOD 7 - i / 5;
END_FOR
END_PROGRAM
)");
}
BENCHMARK(BM_Vm_IntLoop);

void BM_Native_IntLoop(benchmark::State& state) {
  for (auto _ : state) {
    int32_t acc = 0;
    for (int32_t i = 1; i <= 10000; ++i) {
      benchmark::DoNotOptimize(i);
      acc = acc + (i * 3) % 7 - i / 5;
    }
    benchmark::DoNotOptimize(acc);
  }
}
BENCHMARK(BM_Native_IntLoop);

// --- REAL arithmetic -------------------------------------------------------------------------------

void BM_Vm_RealLoop(benchmark::State& state) {
  run_cycles(state, R"(
PROGRAM PLC_PRG
VAR
  i : DINT;
  x : REAL := 1.0;
END_VAR
FOR i := 1 TO 10000 DO
  x := x * 0.999 + 0.5;
END_FOR
END_PROGRAM
)");
}
BENCHMARK(BM_Vm_RealLoop);

void BM_Native_RealLoop(benchmark::State& state) {
  float x = 1.0F;
  for (auto _ : state) {
    for (int32_t i = 1; i <= 10000; ++i) {
      benchmark::DoNotOptimize(i);
      x = x * 0.999F + 0.5F;
    }
    benchmark::DoNotOptimize(x);
  }
}
BENCHMARK(BM_Native_RealLoop);

// --- sieve of Eratosthenes over 10^6 BOOLs ---------------------------------------------------------

void BM_Vm_Sieve(benchmark::State& state) {
  run_cycles(state, R"(
PROGRAM PLC_PRG
VAR
  composite : ARRAY[0..999999] OF BOOL;
  i, j, primes : DINT;
END_VAR
FOR i := 0 TO 999999 DO
  composite[i] := FALSE;
END_FOR
primes := 0;
FOR i := 2 TO 999999 DO
  IF NOT composite[i] THEN
    primes := primes + 1;
    j := i * i;
    WHILE j <= 999999 AND i < 1000 DO
      composite[j] := TRUE;
      j := j + i;
    END_WHILE
  END_IF
END_FOR
END_PROGRAM
)");
}
BENCHMARK(BM_Vm_Sieve)->Unit(benchmark::kMillisecond);

void BM_Native_Sieve(benchmark::State& state) {
  std::vector<uint8_t> composite(1000000);
  for (auto _ : state) {
    for (int32_t i = 0; i <= 999999; ++i) composite[static_cast<size_t>(i)] = 0;
    int32_t primes = 0;
    for (int32_t i = 2; i <= 999999; ++i) {
      if (composite[static_cast<size_t>(i)]) continue;
      ++primes;
      for (int32_t j = i * i; i < 1000 && j <= 999999; j += i) composite[static_cast<size_t>(j)] = 1;
    }
    benchmark::DoNotOptimize(primes);
    benchmark::DoNotOptimize(composite.data());
  }
}
BENCHMARK(BM_Native_Sieve)->Unit(benchmark::kMillisecond);

// --- 1,000 TON instances a cycle (the standard block's ST body, compiled like user code) -----------

void BM_Vm_Timers(benchmark::State& state) {
  run_cycles(state, R"(
PROGRAM PLC_PRG
VAR
  timers : ARRAY[1..1000] OF TON;
  i : DINT;
  done : DINT;
END_VAR
done := 0;
FOR i := 1 TO 1000 DO
  timers[i](IN := TRUE, PT := T#5S);
  IF timers[i].Q THEN
    done := done + 1;
  END_IF
END_FOR
END_PROGRAM
)");
}
BENCHMARK(BM_Vm_Timers);

struct NativeTon {
  bool in = false;
  int64_t pt = 0;
  bool q = false;
  int64_t et = 0;
  int64_t start = 0;
  bool running = false;
  void operator()(bool input, int64_t preset, int64_t now) {
    in = input;
    pt = preset;
    if (!in) {
      q = false;
      et = 0;
      running = false;
    } else if (!running) {
      running = true;
      start = now;
      et = 0;
    } else {
      et = now - start >= pt ? pt : now - start;
      q = et >= pt;
    }
  }
};

void BM_Native_Timers(benchmark::State& state) {
  std::vector<NativeTon> timers(1000);
  int64_t now = 0;
  for (auto _ : state) {
    int32_t done = 0;
    for (NativeTon& timer : timers) {
      timer(true, 5000, now);
      done += timer.q ? 1 : 0;
    }
    now += 10;
    benchmark::DoNotOptimize(done);
  }
}
BENCHMARK(BM_Native_Timers);

// --- strings: CONCAT, LEFT, FIND, LEN a hundred times a cycle --------------------------------------

void BM_Vm_Strings(benchmark::State& state) {
  run_cycles(state, R"(
PROGRAM PLC_PRG
VAR
  i : INT;
  s : STRING(80);
  found, length : INT;
END_VAR
FOR i := 1 TO 100 DO
  s := CONCAT('Station ', INT_TO_STRING(i));
  s := CONCAT(s, ': conveyor running');
  found := FIND(s, 'conveyor');
  s := LEFT(s, found - 1);
  length := LEN(s);
END_FOR
END_PROGRAM
)");
}
BENCHMARK(BM_Vm_Strings);

void BM_Native_Strings(benchmark::State& state) {
  char s[81];
  for (auto _ : state) {
    int found = 0;
    size_t length = 0;
    for (int i = 1; i <= 100; ++i) {
      std::snprintf(s, sizeof s, "Station %d", i);
      std::strncat(s, ": conveyor running", sizeof s - std::strlen(s) - 1);
      const char* at = std::strstr(s, "conveyor");
      found = at ? static_cast<int>(at - s) + 1 : 0;
      s[found > 0 ? found - 1 : 0] = '\0';
      length = std::strlen(s);
      benchmark::DoNotOptimize(s);
    }
    benchmark::DoNotOptimize(length);
  }
}
BENCHMARK(BM_Native_Strings);

// --- a CASE state machine stepped 1,000 times a cycle ----------------------------------------------

void BM_Vm_CaseMachine(benchmark::State& state) {
  run_cycles(state, R"(
TYPE E_State : (Idle, Filling, Heating, Mixing, Draining, Cleaning, Fault, Done); END_TYPE
PROGRAM PLC_PRG
VAR
  state : E_State;
  n, level, temp, faults : DINT;
END_VAR
FOR n := 1 TO 1000 DO
  CASE state OF
    E_State.Idle: state := E_State.Filling;
    E_State.Filling: level := level + 7; IF level > 90 THEN state := E_State.Heating; END_IF
    E_State.Heating: temp := temp + 3; IF temp > 60 THEN state := E_State.Mixing; END_IF
    E_State.Mixing: temp := temp - 1; IF temp < 50 THEN state := E_State.Draining; END_IF
    E_State.Draining: level := level - 9; IF level < 0 THEN level := 0; state := E_State.Cleaning; END_IF
    E_State.Cleaning: state := E_State.Done;
    E_State.Fault: faults := faults + 1; state := E_State.Idle;
    E_State.Done: state := E_State.Idle; temp := 0;
  END_CASE
END_FOR
END_PROGRAM
)");
}
BENCHMARK(BM_Vm_CaseMachine);

void BM_Native_CaseMachine(benchmark::State& state) {
  enum class S : int16_t { Idle, Filling, Heating, Mixing, Draining, Cleaning, Fault, Done };
  S s = S::Idle;
  int32_t level = 0, temp = 0, faults = 0;
  for (auto _ : state) {
    for (int32_t n = 1; n <= 1000; ++n) {
      benchmark::DoNotOptimize(s);
      switch (s) {
        case S::Idle: s = S::Filling; break;
        case S::Filling:
          level += 7;
          if (level > 90) s = S::Heating;
          break;
        case S::Heating:
          temp += 3;
          if (temp > 60) s = S::Mixing;
          break;
        case S::Mixing:
          temp -= 1;
          if (temp < 50) s = S::Draining;
          break;
        case S::Draining:
          level -= 9;
          if (level < 0) {
            level = 0;
            s = S::Cleaning;
          }
          break;
        case S::Cleaning: s = S::Done; break;
        case S::Fault:
          ++faults;
          s = S::Idle;
          break;
        case S::Done:
          s = S::Idle;
          temp = 0;
          break;
      }
    }
    benchmark::DoNotOptimize(level);
    benchmark::DoNotOptimize(temp);
    benchmark::DoNotOptimize(faults);
  }
}
BENCHMARK(BM_Native_CaseMachine);

// --- structure and array copies --------------------------------------------------------------------

void BM_Vm_Copies(benchmark::State& state) {
  run_cycles(state, R"(
TYPE ST_Recipe :
STRUCT
  name : STRING(15);
  setpoint : LREAL;
  steps : ARRAY[1..4] OF INT;
END_STRUCT
END_TYPE
PROGRAM PLC_PRG
VAR
  a, b : ARRAY[1..100] OF ST_Recipe;
  one : ST_Recipe;
  i : INT;
END_VAR
FOR i := 1 TO 100 DO
  b := a;
  one := b[i];
  a[i] := one;
END_FOR
END_PROGRAM
)");
}
BENCHMARK(BM_Vm_Copies);

void BM_Native_Copies(benchmark::State& state) {
  struct Recipe {
    char name[16];
    double setpoint;
    int16_t steps[4];
  };
  std::vector<Recipe> a(100), b(100);
  Recipe one{};
  for (auto _ : state) {
    for (size_t i = 0; i < 100; ++i) {
      b = a;
      one = b[i];
      a[i] = one;
      benchmark::DoNotOptimize(a.data());
    }
  }
}
BENCHMARK(BM_Native_Copies);

// --- interface calls (dynamic dispatch) ------------------------------------------------------------

void BM_Vm_InterfaceCalls(benchmark::State& state) {
  run_cycles(state, R"(
INTERFACE I_Shape
METHOD Area : LREAL
END_METHOD
END_INTERFACE

FUNCTION_BLOCK FB_Square IMPLEMENTS I_Shape
VAR
  side : LREAL := 2;
END_VAR
METHOD Area : LREAL
Area := side * side;
END_METHOD
END_FUNCTION_BLOCK

FUNCTION_BLOCK FB_Circle IMPLEMENTS I_Shape
VAR
  radius : LREAL := 1;
END_VAR
METHOD Area : LREAL
Area := 3.14159 * radius * radius;
END_METHOD
END_FUNCTION_BLOCK

PROGRAM PLC_PRG
VAR
  squares : ARRAY[0..499] OF FB_Square;
  circles : ARRAY[0..499] OF FB_Circle;
  shapes : ARRAY[0..999] OF I_Shape;
  i : INT;
  total : LREAL;
  ready : BOOL;
END_VAR
IF NOT ready THEN
  FOR i := 0 TO 499 DO
    shapes[2 * i] := squares[i];
    shapes[2 * i + 1] := circles[i];
  END_FOR
  ready := TRUE;
END_IF
total := 0;
FOR i := 0 TO 999 DO
  total := total + shapes[i].Area();
END_FOR
END_PROGRAM
)");
}
BENCHMARK(BM_Vm_InterfaceCalls);

struct Shape {
  virtual ~Shape() = default;
  virtual double area() const = 0;
};
struct Square : Shape {
  double side = 2;
  double area() const override { return side * side; }
};
struct Circle : Shape {
  double radius = 1;
  double area() const override { return 3.14159 * radius * radius; }
};

void BM_Native_InterfaceCalls(benchmark::State& state) {
  std::vector<Square> squares(500);
  std::vector<Circle> circles(500);
  std::vector<const Shape*> shapes;
  for (size_t i = 0; i < 500; ++i) {
    shapes.push_back(&squares[i]);
    shapes.push_back(&circles[i]);
  }
  for (auto _ : state) {
    double total = 0;
    for (const Shape* shape : shapes) {
      benchmark::DoNotOptimize(shape);
      total += shape->area();
    }
    benchmark::DoNotOptimize(total);
  }
}
BENCHMARK(BM_Native_InterfaceCalls);

// --- FB calls: 1,000 calls of a small function block a cycle ---------------------------------------

void BM_Vm_FbCalls(benchmark::State& state) {
  run_cycles(state, R"(
FUNCTION_BLOCK FB_Scale
VAR_INPUT
  raw : INT;
END_VAR
VAR_OUTPUT
  value : REAL;
END_VAR
value := INT_TO_REAL(raw) * 0.1 + 4.0;
END_FUNCTION_BLOCK

PROGRAM PLC_PRG
VAR
  scalers : ARRAY[1..1000] OF FB_Scale;
  i : INT;
  sum : REAL;
END_VAR
sum := 0;
FOR i := 1 TO 1000 DO
  scalers[i](raw := i);
  sum := sum + scalers[i].value;
END_FOR
END_PROGRAM
)");
}
BENCHMARK(BM_Vm_FbCalls);

struct NativeScale {
  int16_t raw = 0;
  float value = 0;
  void operator()(int16_t input) {
    raw = input;
    value = static_cast<float>(raw) * 0.1F + 4.0F;
  }
};

void BM_Native_FbCalls(benchmark::State& state) {
  std::vector<NativeScale> scalers(1000);
  for (auto _ : state) {
    float sum = 0;
    for (int16_t i = 1; i <= 1000; ++i) {
      NativeScale& scaler = scalers[static_cast<size_t>(i - 1)];
      benchmark::DoNotOptimize(&scaler);
      scaler(i);
      sum += scaler.value;
    }
    benchmark::DoNotOptimize(sum);
  }
}
BENCHMARK(BM_Native_FbCalls);

// --- the empty cycle: what the engine costs around a program that does nothing ---------------------

void BM_Vm_EmptyCycle(benchmark::State& state) {
  run_cycles(state, R"(
PROGRAM PLC_PRG
VAR
  x : INT;
END_VAR
;
END_PROGRAM
)");
}
BENCHMARK(BM_Vm_EmptyCycle);

// --- compiling: check + compile of the tank example's size of program ------------------------------

void BM_CompileTimers(benchmark::State& state) {
  const std::string source = R"(
PROGRAM PLC_PRG
VAR
  timers : ARRAY[1..1000] OF TON;
  i : DINT;
END_VAR
FOR i := 1 TO 1000 DO
  timers[i](IN := TRUE, PT := T#5S);
END_FOR
END_PROGRAM
)";
  for (auto _ : state) {
    auto loaded = load(source);
    benchmark::DoNotOptimize(loaded->project.program->code.size());
  }
}
BENCHMARK(BM_CompileTimers)->Unit(benchmark::kMillisecond);

}  // namespace
