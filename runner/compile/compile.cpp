// The driver: which programs run (a CONFIGURATION's tasks, --program, or the project's one
// PROGRAM), globals in declaration order, then every reachable callable compiled from a queue.
#include "runner/compile/compile.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "checker/symbols/names.hpp"
#include "runner/compile/lowering.hpp"

namespace rung::run {
namespace {

std::vector<VariableView> instance_variables(Lowering& lowering, const Symbol* pou, uint64_t base) {
  std::vector<VariableView> views;
  const PouLayout& layout = lowering.layouts().pou(pou);
  for (const Symbol* variable : layout.instance_variables) {
    VariableView view{std::string(variable->name), variable->type, base + lowering.layouts().offset(variable),
                      Layouts::held_by_reference(variable)};
    if (variable->location_node) {
      // Located variables live in the process image, not in the instance.
      const Storage storage = lowering.storage_of(variable, pou);
      if (storage.kind == Storage::Kind::Global) {
        view.address = storage.offset;
        view.bit = storage.bit;
      }
    }
    views.push_back(std::move(view));
  }
  return views;
}

void add_program(Lowering& lowering, CompiledProject& out, std::string name, const Symbol* program) {
  ProgramInstance instance;
  instance.name = std::move(name);
  instance.program = program;
  instance.callable = lowering.callable_for(program);
  instance.address = lowering.program_instance(program);
  instance.variables = instance_variables(lowering, program, instance.address);
  out.programs.push_back(std::move(instance));
}

int64_t duration_ms(const check::ProjectModel& model, SyntaxNode value, const Symbol* scope) {
  if (auto constant = model.constant_value(value, scope)) {
    if (constant->kind == check::ConstValue::Kind::Duration) return static_cast<int64_t>(constant->integer / 1'000'000);
    if (constant->is_integer()) return static_cast<int64_t>(constant->integer);
  }
  return 0;
}

struct ConfiguredTask {
  std::string name;
  uint64_t interval_ns = 0;
  uint32_t priority = 0;
};

// PROGRAM instances and TASKs of a CONFIGURATION (directly or in its RESOURCEs).
void read_configuration(Lowering& lowering, CompiledProject& out, SyntaxNode configuration, const Symbol* scope) {
  const check::ProjectModel& model = lowering.model();
  std::vector<ConfiguredTask> tasks;
  std::vector<std::pair<SyntaxNode, SyntaxNode>> programs;  // program_configuration, its container
  std::vector<SyntaxNode> containers{configuration};
  for (SyntaxNode resource : configuration.children_of_kind("resource_declaration")) containers.push_back(resource);
  for (SyntaxNode container : containers) {
    for (SyntaxNode task : container.children_of_kind("task_configuration")) {
      ConfiguredTask plan;
      plan.name = std::string(task.child_by_field("name").text());
      for (const check::CallArgument& argument : check::call_arguments(task.child_by_field("arguments"))) {
        if (!argument.name) continue;
        if (check::names_equal(argument.name.text(), "INTERVAL")) {
          plan.interval_ns = static_cast<uint64_t>(duration_ms(model, argument.value, scope)) * 1'000'000;
        } else if (check::names_equal(argument.name.text(), "PRIORITY")) {
          if (auto constant = model.constant_value(argument.value, scope); constant && constant->is_integer()) {
            plan.priority = static_cast<uint32_t>(constant->integer);
          }
        }
      }
      tasks.push_back(plan);
    }
    for (SyntaxNode program : container.children_of_kind("program_configuration")) programs.emplace_back(program, container);
  }
  for (const ConfiguredTask& task : tasks) out.tasks.push_back(TaskPlan{task.name, task.interval_ns, task.priority, {}});
  for (const auto& [node, container] : programs) {
    SyntaxNode type_node = node.child_by_field("type");
    const Symbol* program = type_node ? model.find_global(type_node.text()) : nullptr;
    if (!program || program->kind != SymbolKind::Program) {
      lowering.error(scope, node, fmt::format("'{}' is not a PROGRAM of the project", type_node ? type_node.text() : ""));
      continue;
    }
    add_program(lowering, out, std::string(node.child_by_field("name").text()), program);
    SyntaxNode task_node = node.child_by_field("task");
    auto task = std::find_if(out.tasks.begin(), out.tasks.end(), [&](const TaskPlan& plan) {
      return task_node && check::names_equal(plan.name, task_node.text());
    });
    if (task == out.tasks.end()) {
      out.tasks.push_back(TaskPlan{task_node ? std::string(task_node.text()) : "(no task)", 0, 0, {}});
      task = out.tasks.end() - 1;
    }
    task->programs.push_back(out.programs.size() - 1);
  }
  // Higher priority (smaller number) first; stable for equal priorities.
  std::stable_sort(out.tasks.begin(), out.tasks.end(),
                   [](const TaskPlan& a, const TaskPlan& b) { return a.priority < b.priority; });
}

}  // namespace

CompiledProject compile_project(const check::ProjectModel& model, const CompileOptions& options) {
  CompiledProject out;
  out.program = std::make_unique<Program>();
  out.layouts = std::make_unique<Layouts>(model);
  Lowering lowering(model, *out.program, *out.layouts);

  // Globals of the project in declaration order (libraries' only when used).
  std::vector<const Symbol*> project_programs;
  std::vector<std::pair<SyntaxNode, const Symbol*>> configurations;
  for (check::SourceId id = 0; id < model.source_count(); ++id) {
    const check::Source& source = model.source(id);
    if (source.library) continue;
    for (const Symbol* symbol : model.top_level_symbols(id)) {
      if (symbol->kind == SymbolKind::GlobalList) {
        for (const Symbol* variable : symbol->ordered) {
          if (variable->kind == SymbolKind::Variable) lowering.global_address(variable);
        }
      } else if (symbol->kind == SymbolKind::Program) {
        project_programs.push_back(symbol);
      } else if (symbol->kind == SymbolKind::Configuration) {
        configurations.emplace_back(symbol->node, symbol);
      }
    }
  }

  if (!options.program.empty()) {
    const Symbol* program = model.find_global(options.program);
    if (!program || program->kind != SymbolKind::Program) {
      std::string known;
      for (const Symbol* candidate : project_programs) known += (known.empty() ? "" : ", ") + std::string(candidate->name);
      out.errors.push_back(CompileError{check::kNoSource, 0,
                                        fmt::format("there is no PROGRAM '{}' (programs: {})", options.program,
                                                    known.empty() ? "none" : known)});
      return out;
    }
    add_program(lowering, out, std::string(program->name), program);
  } else if (!options.all_programs && !configurations.empty()) {
    const Symbol* chosen = nullptr;
    for (const auto& [node, symbol] : configurations) {
      if (options.configuration.empty() || check::names_equal(symbol->name, options.configuration)) {
        chosen = symbol;
        break;
      }
    }
    if (!chosen) {
      out.errors.push_back(CompileError{check::kNoSource, 0, fmt::format("there is no CONFIGURATION '{}'", options.configuration)});
      return out;
    }
    read_configuration(lowering, out, chosen->node, chosen);
  } else if (options.all_programs) {
    for (const Symbol* program : project_programs) add_program(lowering, out, std::string(program->name), program);
  } else if (project_programs.size() == 1) {
    add_program(lowering, out, std::string(project_programs.front()->name), project_programs.front());
  } else if (project_programs.empty()) {
    out.errors.push_back(CompileError{check::kNoSource, 0, "the project has no PROGRAM to run"});
    return out;
  } else {
    // CODESYS's default task calls PLC_PRG; TwinCAT's calls MAIN.
    const Symbol* main = nullptr;
    for (const Symbol* program : project_programs) {
      if (check::names_equal(program->name, "PLC_PRG") || check::names_equal(program->name, "MAIN")) main = program;
    }
    if (!main) {
      std::string known;
      for (const Symbol* candidate : project_programs) known += (known.empty() ? "" : ", ") + std::string(candidate->name);
      out.errors.push_back(CompileError{
          check::kNoSource, 0,
          fmt::format("the project has several programs ({}) and no CONFIGURATION: choose one with --program", known)});
      return out;
    }
    add_program(lowering, out, std::string(main->name), main);
  }
  if (out.tasks.empty()) {
    TaskPlan task{"(default)", 0, 0, {}};
    for (size_t i = 0; i < out.programs.size(); ++i) task.programs.push_back(i);
    out.tasks.push_back(std::move(task));
  }

  // Computed initial values and FB instances built (FB_init): the global lists' first, then each
  // program's. FB_exit at the end in the reverse order: programs last to first, then the lists.
  std::vector<const Symbol*> global_lists;
  for (check::SourceId id = 0; id < model.source_count(); ++id) {
    if (model.source(id).library) continue;
    for (const Symbol* symbol : model.top_level_symbols(id)) {
      if (symbol->kind == SymbolKind::GlobalList) global_lists.push_back(symbol);
    }
  }
  for (const Symbol* list : global_lists) lowering.init_callable(list, 0);
  for (const ProgramInstance& program : out.programs) lowering.init_callable(program.program, program.address);
  for (auto program = out.programs.rbegin(); program != out.programs.rend(); ++program) {
    lowering.exit_callable(program->program, program->address);
  }
  for (auto list = global_lists.rbegin(); list != global_lists.rend(); ++list) lowering.exit_callable(*list, 0);

  lowering.compile_queue();
  lowering.build_vtables();
  lowering.compile_queue();
  lowering.build_vtables();
  out.globals = lowering.global_lists();
  out.errors.insert(out.errors.end(), lowering.errors().begin(), lowering.errors().end());
  return out;
}

}  // namespace rung::run
