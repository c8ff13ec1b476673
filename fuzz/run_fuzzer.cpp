// The fuzzer's bytes choose a random well-typed program (tests/runner/random_program.hpp), which
// is checked, compiled and run for a few cycles. Nothing may crash or hang; a run may stop only
// with a run-time error a program can cause (division by zero, an index out of bounds, the
// watchdog), never with an internal one.
#include <cstddef>
#include <cstdint>

#include "checker/check.hpp"
#include "runner/compile/compile.hpp"
#include "runner/engine.hpp"
#include "tests/runner/random_program.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  rung::run::testing::Choices choices(data, size);
  const std::string source = rung::run::testing::random_program(choices, 16);
  rung::project::ProjectConfig config;
  auto workspace = rung::check::Workspace::from_texts({{"fuzz.st", source}}, config);
  for (const rung::check::FileDiagnostics& file : workspace->check_all(1)) {
    for (const rung::Diagnostic& diagnostic : file.diagnostics) {
      if (diagnostic.severity == rung::Severity::Error) __builtin_trap();  // the generator wrote bad code
    }
  }
  const rung::run::CompiledProject project = rung::run::compile_project(workspace->model(), {});
  if (!project.ok()) __builtin_trap();
  rung::run::Engine engine(project, 20'000'000);
  engine.machine().set_loop_budget(100000);
  for (int cycle = 0; cycle < 3 && engine.cycle(); ++cycle) {
  }
  if (const auto& error = engine.machine().error()) {
    using rung::run::TrapKind;
    if (error->kind != TrapKind::DivisionByZero && error->kind != TrapKind::IndexOutOfBounds &&
        error->kind != TrapKind::Watchdog) {
      __builtin_trap();
    }
  }
  return 0;
}
