// The usage analysis of every project file, built lazily and shared by all files of one lint run
// (AnalysisCache), and the project-wide facts the usage rules ask: which files name something,
// which blocks extend a block, whether the project has programs and a configuration.
//
// Project-wide questions ("is FB_Motor used anywhere?") look only at the files whose text holds
// the name as a word (a prefilter built once), and there at names the analysis resolved, so
// linting one file of a large project analyses the few files that matter, and linting all files
// analyses each file once.
#pragma once

#include <memory>
#include <mutex>
#include <span>
#include <unordered_map>
#include <vector>

#include "checker/lint/usage_analysis.hpp"

namespace rung::lint {

class AnalysisCache;

class ProjectUsage {
 public:
  // The analysis of each file walks the file's node list, shared through `cache`.
  explicit ProjectUsage(AnalysisCache& cache) : cache_(cache) {}

  // All calls are thread-safe: files are linted in parallel.
  const FileUsage& file(const check::ProjectModel& model, check::SourceId id);
  // Project files (not stub libraries) whose text holds `name` as a whole word (case-insensitive),
  // in id order. Comments count too: a prefilter, the analysis decides.
  std::span<const check::SourceId> files_mentioning(const check::ProjectModel& model, std::string_view name);
  // Blocks of project files that EXTEND `base`, directly or through others, in file order.
  std::span<const check::Symbol* const> derived_of(const check::ProjectModel& model, const check::Symbol* base);
  // Whether a project file declares a PROGRAM (a project without one is a library: its POUs and
  // types are there for other projects) and a CONFIGURATION (which says what tasks run).
  bool has_program(const check::ProjectModel& model);
  bool has_configuration(const check::ProjectModel& model);

  // Whether `symbol` is used anywhere in the project by a use that `accept(use, file)` takes
  // (only files that hold its name are looked at).
  template <typename Accept>
  bool any_use(const check::ProjectModel& model, const check::Symbol* symbol, Accept&& accept) {
    for (const check::SourceId id : files_mentioning(model, symbol->name)) {
      const FileUsage& usage = file(model, id);
      for (const uint32_t index : usage.uses_of(symbol)) {
        if (accept(usage.uses[index], id)) return true;
      }
    }
    return false;
  }
  // Whether some project file could not resolve a name `name`, or leaves it out by conditional
  // compilation (see FileUsage).
  bool maybe_named_unresolved(const check::ProjectModel& model, std::string_view name);

 private:
  struct Slot {
    std::once_flag once;
    std::unique_ptr<FileUsage> usage;
  };
  struct ProjectFacts {
    std::unordered_map<const check::Symbol*, std::vector<const check::Symbol*>> derived;
    bool has_program = false;
    bool has_configuration = false;
  };
  void prepare(const check::ProjectModel& model);
  const ProjectFacts& facts(const check::ProjectModel& model);

  AnalysisCache& cache_;
  std::once_flag slots_once_;
  std::vector<std::unique_ptr<Slot>> slots_;
  std::once_flag facts_once_;
  ProjectFacts facts_;
};

// The shared analysis of `context`'s run (one per lint_all / lint_source call).
class LintContext;
ProjectUsage& project_usage(LintContext& context);

}  // namespace rung::lint
