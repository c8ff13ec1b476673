// One lint rule: its registry facts (code, name, default severity) and the function that looks
// for it in one file. Rules are grouped in files by concern (rules_*.cpp); each group adds its
// rules to the registry (rule_registry.cpp). A rule reads the linked ProjectModel and the syntax
// tree, never files: the same rules serve `rung lint`, the language server and the tests.
#pragma once

#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <typeindex>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "checker/lint/node_list.hpp"
#include "checker/lint/project_index.hpp"
#include "checker/project/lint_settings.hpp"
#include "checker/project_model.hpp"
#include "parser/diagnostic.hpp"

namespace rung::lint {

// Replace `range` of the TREE text by `replacement`.
struct TextEdit {
  TextRange range;
  std::string replacement;
};

// An automatic fix: only offered where it is safe (it cannot change what the program does, or it
// does exactly what the message says, e.g. removing `x := x;`). Edits never overlap.
struct Fix {
  std::string description;  // "remove the empty statement"
  std::vector<TextEdit> edits;
};

// A finding with its fix. Ranges in tree coordinates inside rules; lint_file() maps them to the
// file (container files: the container's own offsets).
struct Finding {
  Diagnostic diagnostic;
  std::optional<Fix> fix;
};

// Analyses several rules share (where each variable is read and written, ...), built by the first
// rule that asks. One cache serves one lint_all() (its threads lint files in parallel, so a T must
// make its own lazy parts thread-safe) or one lint_source() call; it lives no longer than that, so
// it never sees an edited model.
class AnalysisCache {
 public:
  // `kept`: a project index the caller keeps across runs (see project_index.hpp); without one the
  // run builds its own.
  explicit AnalysisCache(ProjectIndex* kept = nullptr) : kept_index_(kept) {}

  // The project index, brought up to date with `model` by the first caller of the run.
  ProjectIndex& index(const check::ProjectModel& model);

  // The analysis of type T; T is default-constructed, or constructed with this cache if it can be
  // (to ask for node lists). Its constructor must not call get().
  template <typename T>
  T& get() {
    std::lock_guard lock(mutex_);
    std::shared_ptr<void>& slot = entries_[std::type_index(typeid(T))];
    if (!slot) {
      if constexpr (std::is_constructible_v<T, AnalysisCache&>) {
        slot = std::make_shared<T>(*this);
      } else {
        slot = std::make_shared<T>();
      }
    }
    return *static_cast<T*>(slot.get());
  }

  // The node list of a file, built once for the file's own rules and the project-wide analyses
  // that read the file (whichever asks first), until release_nodes().
  std::shared_ptr<const NodeList> nodes(const check::ProjectModel& model, check::SourceId source);
  // Forgets the file's list (its lint is done): a later question builds a list of its own.
  void release_nodes(check::SourceId source);

 private:
  struct NodesSlot {
    std::once_flag once;
    std::shared_ptr<const NodeList> list;
  };

  ProjectIndex* kept_index_ = nullptr;
  std::unique_ptr<ProjectIndex> own_index_;
  std::once_flag index_once_;
  std::mutex mutex_;
  std::unordered_map<std::type_index, std::shared_ptr<void>> entries_;
  std::unordered_map<check::SourceId, std::shared_ptr<NodesSlot>> nodes_;
  std::unordered_set<check::SourceId> released_;
};

// What the rules of one file share, built by the first rule that asks: lint_source() keeps one
// per file for all its rules.
struct FileShared {
  std::shared_ptr<const NodeList> nodes;
  std::optional<std::vector<const check::Symbol*>> pous;
};

class LintContext;
using RuleCheck = void (*)(LintContext& context);

struct Rule {
  std::string_view code;  // "L030": also a row of the diagnostic registry (parser/diagnostic_codes)
  std::string_view name;  // "case-without-else": the same as the registry's title
  bool enabled_by_default = true;
  bool has_fix = false;  // the rule offers a Fix (tests check that fixed.st exists)
  RuleCheck check = nullptr;
};

// Everything a rule may look at while it checks one file, and where it reports.
class LintContext {
 public:
  LintContext(const check::ProjectModel& model, check::SourceId source, const project::LintSettings& settings,
              std::vector<Finding>& out, AnalysisCache* cache = nullptr, FileShared* file = nullptr)
      : model_(model), source_(source), settings_(settings), out_(out), cache_(cache), file_(file) {}

  const check::ProjectModel& model() const { return model_; }
  check::SourceId source_id() const { return source_; }
  const check::Source& source() const { return model_.source(source_); }
  // The file's syntax tree root and text (tree coordinates); the root is null when the file
  // was not parsed.
  SyntaxNode root() const;
  std::string_view text() const;
  // The file's tree as a flat preorder list (empty when the file was not parsed): node 0 is the
  // root. Walking it is what rules that look at every node should do (node_list.hpp).
  const NodeList& nodes() const;
  // The file's POUs (members after their owner), as the body checks see them.
  const std::vector<const check::Symbol*>& pous() const;

  // [lint.thresholds] value, or `fallback` when rung.toml does not set it.
  int64_t threshold(std::string_view key, int64_t fallback) const;
  // [lint.naming] pattern, or `fallback`.
  std::string_view naming(std::string_view key, std::string_view fallback) const;
  const project::LintSettings& settings() const { return settings_; }
  // Analyses shared with the other rules of this run (a cache of its own when none was given).
  AnalysisCache& cache() const;

  // Reports a finding of `code` (its registry severity; rung.toml overrides come later).
  void report(std::string_view code, std::string message, TextRange range, std::string help = {},
              std::optional<Fix> fix = std::nullopt);
  // The same, with labels that point at related code ("first tested here").
  void report(std::string_view code, std::string message, TextRange range, std::string help,
              std::vector<DiagnosticLabel> labels, std::optional<Fix> fix = std::nullopt);

 private:
  const check::ProjectModel& model_;
  check::SourceId source_;
  const project::LintSettings& settings_;
  std::vector<Finding>& out_;
  AnalysisCache* cache_ = nullptr;
  mutable std::unique_ptr<AnalysisCache> own_cache_;
  FileShared* file_ = nullptr;
  mutable std::unique_ptr<FileShared> own_file_;
  FileShared& file() const;
};

// Every rule, ordered by code.
std::span<const Rule> all_rules();
// By code ("L030") or name ("case-without-else"), case-insensitively.
const Rule* find_rule(std::string_view code_or_name);

}  // namespace rung::lint
