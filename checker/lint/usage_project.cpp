#include "checker/lint/usage_project.hpp"

#include "checker/lint/lint_rule.hpp"

namespace rung::lint {
ProjectUsage& project_usage(LintContext& context) {
  return context.cache().get<ProjectUsage>();
}

void ProjectUsage::prepare(const check::ProjectModel& model) {
  std::call_once(slots_once_, [&] {
    slots_.resize(model.source_count());
    for (auto& slot : slots_) slot = std::make_unique<Slot>();
  });
}

const FileUsage& ProjectUsage::file(const check::ProjectModel& model, check::SourceId id) {
  prepare(model);
  Slot& slot = *slots_[id];
  std::call_once(slot.once, [&] {
    const std::shared_ptr<const NodeList> nodes = cache_.nodes(model, id);
    slot.usage = std::make_unique<FileUsage>(collect_usage(model, id, *nodes));
  });
  return *slot.usage;
}

const ProjectUsage::ProjectFacts& ProjectUsage::facts(const check::ProjectModel& model) {
  std::call_once(facts_once_, [&] {
    for (check::SourceId id = 0; id < model.source_count(); ++id) {
      const check::Source& source = model.source(id);
      if (source.library) continue;
      // Programs, configurations and blocks are top-level declarations: the variables, many
      // times more, need not be looked at (this runs for every file the language server lints).
      for (const check::Symbol* symbol : source.symbols.top_level) {
        if (symbol->kind == check::SymbolKind::Program) facts_.has_program = true;
        if (symbol->kind == check::SymbolKind::Configuration) facts_.has_configuration = true;
        if (symbol->kind != check::SymbolKind::FunctionBlock && symbol->kind != check::SymbolKind::Class) continue;
        int depth = 0;  // EXTENDS cycles are E-diagnostics of their own
        for (const check::Symbol* base = symbol->base; base && depth < 32; base = base->base, ++depth) {
          facts_.derived[base].push_back(symbol);
        }
      }
    }
  });
  return facts_;
}

std::span<const check::SourceId> ProjectUsage::files_mentioning(const check::ProjectModel& model,
                                                                std::string_view name) {
  return cache_.index(model).files_mentioning(name);
}

std::span<const check::Symbol* const> ProjectUsage::derived_of(const check::ProjectModel& model,
                                                               const check::Symbol* base) {
  const ProjectFacts& known = facts(model);
  auto found = known.derived.find(base);
  if (found == known.derived.end()) return {};
  return found->second;
}

bool ProjectUsage::has_program(const check::ProjectModel& model) {
  return facts(model).has_program;
}

bool ProjectUsage::has_configuration(const check::ProjectModel& model) {
  return facts(model).has_configuration;
}

bool ProjectUsage::maybe_named_unresolved(const check::ProjectModel& model, std::string_view name) {
  ProjectIndex& index = cache_.index(model);
  for (const check::SourceId id : files_mentioning(model, name)) {
    // The language server asks this for every variable of an edited file, and common names are in
    // thousands of files: their names are kept in the index, across lint runs.
    const bool unresolved = index.leaves_unresolved(model, id, name, [&] {
      const FileUsage& usage = file(model, id);
      ProjectIndex::NameSet names;
      for (const std::string_view unresolved : usage.unresolved_names) names.emplace(unresolved);
      for (const std::string_view inactive : usage.inactive_names) names.emplace(inactive);
      return names;
    });
    if (unresolved) return true;
  }
  return false;
}

}  // namespace rung::lint
