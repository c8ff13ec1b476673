// Lowers a checked project to a Program: the front door of runner/compile.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "checker/project_model.hpp"
#include "runner/compile/layout.hpp"
#include "runner/vm/program.hpp"

namespace rung::run {

// A variable the reports show, at its absolute address.
struct VariableView {
  std::string name;
  const check::Type* type = nullptr;
  uint64_t address = 0;
  bool by_reference = false;  // the address holds a pointer to the value (VAR_IN_OUT)
  int bit = -1;               // a BOOL at a bit address of the process image (AT %IX0.3)
};

struct ProgramInstance {
  std::string name;  // the instance name (the program's name, or CONFIGURATION's PROGRAM x)
  const check::Symbol* program = nullptr;
  uint32_t callable = kNoCallable;
  uint64_t address = 0;
  std::vector<VariableView> variables;
};

struct GlobalList {
  std::string name;  // the GVL's name (its file or object name)
  std::vector<VariableView> variables;
};

struct TaskPlan {
  std::string name;
  uint64_t interval_ns = 0;  // 0: every base tick (freewheeling / no interval)
  uint32_t priority = 0;
  std::vector<size_t> programs;  // indexes into CompiledProject::programs, in call order
};

struct CompileError {
  check::SourceId source = check::kNoSource;
  uint32_t offset = 0;  // in the source's tree text
  std::string message;
};

struct CompileOptions {
  std::string program;        // --program NAME
  std::string configuration;  // --config NAME
  bool all_programs = false;  // compile every PROGRAM (rung test)
};

struct CompiledProject {
  std::unique_ptr<Program> program;
  std::unique_ptr<Layouts> layouts;
  std::vector<ProgramInstance> programs;
  std::vector<GlobalList> globals;
  std::vector<TaskPlan> tasks;
  std::vector<CompileError> errors;  // empty when the project can run
  bool ok() const { return errors.empty(); }
};

CompiledProject compile_project(const check::ProjectModel& model, const CompileOptions& options);

}  // namespace rung::run
