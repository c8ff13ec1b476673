#include "checker/lint/usage_project.hpp"

#include "checker/lint/lint_rule.hpp"

namespace rung::lint {
namespace {

bool is_word_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
         static_cast<unsigned char>(c) >= 0x80;  // identifiers may hold letters beyond ASCII
}

bool is_word_start(char c) {
  return is_word_char(c) && !(c >= '0' && c <= '9');
}

}  // namespace

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
      for (const check::Symbol& symbol : source.symbols.storage) {
        if (symbol.kind == check::SymbolKind::Program) facts_.has_program = true;
        if (symbol.kind == check::SymbolKind::Configuration) facts_.has_configuration = true;
        if (symbol.kind != check::SymbolKind::FunctionBlock && symbol.kind != check::SymbolKind::Class) continue;
        int depth = 0;  // EXTENDS cycles are E-diagnostics of their own
        for (const check::Symbol* base = symbol.base; base && depth < 32; base = base->base, ++depth) {
          facts_.derived[base].push_back(&symbol);
        }
      }
      const SyntaxTree* tree = source.document->tree();
      if (!tree) continue;
      const std::string_view text = tree->text();
      for (size_t at = 0; at < text.size();) {
        if (!is_word_char(text[at])) {
          ++at;
          continue;
        }
        size_t end = at;
        while (end < text.size() && is_word_char(text[end])) ++end;
        if (is_word_start(text[at])) {
          std::vector<check::SourceId>& files = facts_.words[text.substr(at, end - at)];
          if (files.empty() || files.back() != id) files.push_back(id);
        }
        at = end;
      }
    }
  });
  return facts_;
}

std::span<const check::SourceId> ProjectUsage::files_mentioning(const check::ProjectModel& model,
                                                                std::string_view name) {
  const ProjectFacts& known = facts(model);
  auto found = known.words.find(name);
  if (found == known.words.end()) return {};
  return found->second;
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
  for (const check::SourceId id : files_mentioning(model, name)) {
    const FileUsage& usage = file(model, id);
    if (usage.unresolved_names.contains(name) || usage.inactive_names.contains(name)) return true;
  }
  return false;
}

}  // namespace rung::lint
