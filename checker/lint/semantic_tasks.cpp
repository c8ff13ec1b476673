// L012 global-written-by-several-tasks: a global variable written by code that runs in two or more
// tasks. Tasks interrupt each other (a faster or higher-priority task preempts a slower one), so a
// write of one task can land between another task's read and write of the same variable
// (gCount := gCount + 1 loses counts), and a structure can be seen half-updated.
//
// Which code runs in which task comes from the project's CONFIGURATION: `PROGRAM inst WITH task :
// PRG_Type` (a program without WITH runs in the resource's background, which is a task of its own
// here), then the call graph from that program (the one E209 uses: calls of functions, FB
// instances, methods and actions; the actions of an SFC body run with it). A project without a
// CONFIGURATION says nothing about tasks (CODESYS and TwinCAT keep the task configuration outside
// the code): then the rule says nothing. FB instances a configuration attaches to a task of their
// own (`PROGRAM p WITH t1 : P (fb WITH t2)`) are not followed, nor calls through pointers or
// interfaces.
//
// What counts as a write is what the usage rules record (assignments, S=/R=, `=> x`, IL ST/S/R).
// The finding goes on the first write of the global in each POU that runs in a task.
#include <fmt/format.h>

#include <algorithm>
#include <deque>
#include <map>
#include <mutex>
#include <set>
#include <unordered_map>

#include "checker/lint/semantic_rules.hpp"
#include "checker/lint/semantic_support.hpp"
#include "checker/lint/usage_project.hpp"
#include "checker/semantic/recursion_checker.hpp"

namespace rung::lint::semantic {
namespace {

using check::SourceId;
using check::Symbol;

// A task of the configuration, with the programs it runs.
struct Task {
  std::string key;    // RESOURCE/TASK, upper case; "(no task)" for programs without WITH
  std::string shown;  // as the message names it
  std::vector<const Symbol*> programs;
};

std::string upper(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

std::vector<Task> read_tasks(const check::ProjectModel& model) {
  std::map<std::string, Task> tasks;
  auto add_programs = [&](SyntaxNode holder, std::string_view resource) {
    for (SyntaxNode instance : holder.children_of_kind("program_configuration")) {
      const SyntaxNode type = instance.child_by_field("type");
      const Symbol* program = type ? model.find_global(type.text()) : nullptr;
      if (!program || program->kind != check::SymbolKind::Program) continue;
      const SyntaxNode task = instance.child_by_field("task");
      const std::string name = task ? std::string(task.text()) : std::string("(no task)");
      Task& entry = tasks[upper(resource) + "/" + upper(name)];
      if (entry.key.empty()) {
        entry.key = upper(resource) + "/" + upper(name);
        entry.shown = resource.empty() || task ? name : fmt::format("(no task, resource {})", resource);
      }
      if (std::find(entry.programs.begin(), entry.programs.end(), program) == entry.programs.end()) {
        entry.programs.push_back(program);
      }
    }
  };
  for (SourceId id = 0; id < model.source_count(); ++id) {
    if (model.source(id).library) continue;
    for (const Symbol* symbol : model.source(id).symbols.top_level) {
      if (symbol->kind != check::SymbolKind::Configuration || !symbol->node) continue;
      add_programs(symbol->node, {});
      for (SyntaxNode resource : symbol->node.children_of_kind("resource_declaration")) {
        const SyntaxNode name = resource.child_by_field("name");
        add_programs(resource, name ? name.text() : std::string_view());
      }
    }
  }
  std::vector<Task> result;
  result.reserve(tasks.size());
  for (auto& [key, task] : tasks) result.push_back(std::move(task));
  // Tasks of one name in two resources: say which resource.
  for (Task& task : result) {
    const size_t same =
        std::count_if(result.begin(), result.end(), [&](const Task& other) { return other.shown == task.shown; });
    if (same > 1) task.shown = fmt::format("{} (resource {})", task.shown, task.key.substr(0, task.key.find('/')));
  }
  return result;
}

bool runs_sfc(const Symbol& pou) {
  for (SyntaxNode body : bodies_of(pou)) {
    if (body.kind() == "sfc_network") return true;
  }
  return false;
}

// Which tasks reach each POU, and through which of their programs.
class TaskMap {
 public:
  struct Reach {
    size_t task = 0;
    const Symbol* program = nullptr;
  };

  void build(const check::ProjectModel& model) {
    tasks_ = read_tasks(model);
    if (tasks_.empty()) return;
    std::unordered_map<const Symbol*, std::vector<const Symbol*>> calls;
    const check::RecursionIndex& graph = model.recursion_index();
    for (SourceId id = 0; id < model.source_count(); ++id) {
      for (const check::CallEdge& edge : graph.edges(id)) {
        if (!edge.instance) calls[edge.from].push_back(edge.to);
      }
    }
    for (size_t t = 0; t < tasks_.size(); ++t) {
      for (const Symbol* program : tasks_[t].programs) {
        std::set<const Symbol*> seen{program};
        std::deque<const Symbol*> queue{program};
        while (!queue.empty()) {
          const Symbol* pou = queue.front();
          queue.pop_front();
          reached_[pou].push_back({t, program});
          std::vector<const Symbol*> next;
          if (auto found = calls.find(pou); found != calls.end()) next = found->second;
          if (runs_sfc(*pou)) {  // its actions and transitions run with the chart
            for (const Symbol* member : pou->ordered) {
              if (member->kind == check::SymbolKind::Action || member->kind == check::SymbolKind::Transition) {
                next.push_back(member);
              }
            }
          }
          for (const Symbol* callee : next) {
            if (seen.insert(callee).second) queue.push_back(callee);
          }
        }
      }
    }
  }

  const std::vector<Task>& tasks() const { return tasks_; }
  const std::vector<Reach>* reach(const Symbol* pou) const {
    auto found = reached_.find(pou);
    return found == reached_.end() ? nullptr : &found->second;
  }
  // The POUs some task runs, in project order (deterministic).
  std::vector<const Symbol*> reached_pous() const {
    std::vector<const Symbol*> pous;
    for (const auto& [pou, reach] : reached_) pous.push_back(pou);
    std::sort(pous.begin(), pous.end(), [](const Symbol* a, const Symbol* b) {
      return std::make_pair(a->source, a->name_range.begin) < std::make_pair(b->source, b->name_range.begin);
    });
    return pous;
  }

 private:
  std::vector<Task> tasks_;
  std::unordered_map<const Symbol*, std::vector<Reach>> reached_;
};

bool is_global(const Symbol* symbol) {
  return symbol && symbol->kind == check::SymbolKind::Variable && symbol->section == ast::VarSection::Global &&
         !symbol->has(check::kConstant);
}

// The globals written by more than one task, with the text that says by which.
class TaskWrites {
 public:
  void build(const check::ProjectModel& model, ProjectUsage& usage) {
    std::call_once(once_, [&] { compute(model, usage); });
  }
  const TaskMap& tasks() const { return tasks_; }
  // "Fast (PRG_Fast), Slow (PRG_Slow)" for a global written by several tasks, else nullptr.
  const std::string* conflict(const Symbol* global) const {
    auto found = conflicts_.find(global);
    return found == conflicts_.end() ? nullptr : &found->second;
  }

 private:
  void compute(const check::ProjectModel& model, ProjectUsage& usage) {
    tasks_.build(model);
    if (tasks_.tasks().empty()) return;
    // For each global: task -> the programs through which that task writes it.
    std::map<const Symbol*, std::map<size_t, std::set<std::string_view>>> writers;
    std::set<SourceId> files;
    for (const Symbol* pou : tasks_.reached_pous()) files.insert(pou->source);
    for (SourceId id : files) {
      if (model.source(id).library) continue;
      for (const Use& use : usage.file(model, id).uses) {
        if (!(use.flags & kUseWrite) || !is_global(use.symbol)) continue;
        const auto* reach = tasks_.reach(use.scope);
        if (!reach) continue;
        for (const TaskMap::Reach& r : *reach) writers[use.symbol][r.task].insert(r.program->name);
      }
    }
    for (const auto& [global, by_task] : writers) {
      if (by_task.size() < 2) continue;
      std::vector<std::string> parts;
      for (const auto& [task, programs] : by_task) {
        std::string names;
        for (std::string_view program : programs) names += (names.empty() ? "" : ", ") + std::string(program);
        parts.push_back(fmt::format("{} ({})", tasks_.tasks()[task].shown, names));
      }
      std::sort(parts.begin(), parts.end());
      std::string text;
      for (const std::string& part : parts) text += (text.empty() ? "" : ", ") + part;
      conflicts_.emplace(global, fmt::format("{} tasks: {}", by_task.size(), text));
    }
  }

  std::once_flag once_;
  TaskMap tasks_;
  std::map<const Symbol*, std::string> conflicts_;
};

}  // namespace

void check_task_writes(LintContext& context) {
  const check::ProjectModel& model = context.model();
  ProjectUsage& usage = project_usage(context);
  if (!usage.has_configuration(model)) return;
  TaskWrites& index = context.cache().get<TaskWrites>();
  index.build(model, usage);
  std::set<std::pair<const Symbol*, const Symbol*>> reported;  // (POU, global): its first write only
  for (const Use& use : usage.file(model, context.source_id()).uses) {
    if (!(use.flags & kUseWrite) || !is_global(use.symbol) || !index.tasks().reach(use.scope)) continue;
    const std::string* tasks = index.conflict(use.symbol);
    if (!tasks || !reported.insert({use.scope, use.symbol}).second) continue;
    context.report("L012", fmt::format("'{}' is written by programs of {}", use.symbol->name, *tasks), use.range,
                   "a task can interrupt another between its read and its write of the variable: write it from one "
                   "task only, and hand values to other tasks through variables that only one task writes");
  }
}

}  // namespace rung::lint::semantic
