#include "runner/engine.hpp"

#include <algorithm>

#include <fmt/format.h>


namespace rung::run {

Engine::Engine(const CompiledProject& project, uint64_t tick_ns) : project_(project) {
  machine_ = std::make_unique<Machine>(*project.program);
  for (const Program::InitCall& init : project.program->init_calls) {
    if (!machine_->call(init.callable, init.instance)) break;  // the error stays for the first cycle
  }
  if (tick_ns != 0) {
    tick_ns_ = tick_ns;
  } else {
    uint64_t shortest = 0;
    for (const TaskPlan& task : project.tasks) {
      if (task.interval_ns != 0 && (shortest == 0 || task.interval_ns < shortest)) shortest = task.interval_ns;
    }
    if (shortest != 0) tick_ns_ = shortest;
  }
}

bool Engine::cycle() {
  Machine& machine = *machine_;
  if (machine.error()) return false;
  machine.set_time_ns(now_ns_);
  for (const TaskPlan& task : project_.tasks) {
    const bool due = task.interval_ns == 0 || task.interval_ns <= tick_ns_ || now_ns_ % task.interval_ns == 0;
    if (!due) continue;
    for (size_t index : task.programs) {
      const ProgramInstance& program = project_.programs[index];
      if (!machine.call(program.callable, program.address)) return false;
    }
  }
  ++cycles_;
  now_ns_ += tick_ns_;
  return true;
}

bool Engine::finish() {
  if (finished_) return !machine_->error();
  finished_ = true;
  if (machine_->error()) return false;
  for (const Program::InitCall& exit : project_.program->exit_calls) {
    if (!machine_->call(exit.callable, exit.instance)) return false;
  }
  return true;
}

std::string describe_error(const CompiledProject& project, const RunError& error) {
  const check::ProjectModel& model = project.layouts->model();
  std::string text = fmt::format("run-time error: {}", error.message);
  bool first = true;
  for (const StackEntry& entry : error.stack) {
    if (entry.callable >= project.program->callables.size()) continue;
    const Callable& callable = project.program->callables[entry.callable];
    std::string where = "?";
    if (callable.source < model.source_count() && entry.pc < project.program->positions.size()) {
      const Document& document = *model.source(callable.source).document;
      const FilePosition position = document.position_of_tree_offset(project.program->positions[entry.pc]);
      where = fmt::format("{}:{}:{}", document.path(), position.line, position.column);
    }
    text += first ? fmt::format("\n  --> {} (in {})", where, callable.name)
                  : fmt::format("\n  called from {} (in {})", where, callable.name);
    first = false;
  }
  return text;
}

}  // namespace rung::run
