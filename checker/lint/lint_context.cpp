#include "checker/lint/lint_rule.hpp"
#include "parser/diagnostic_codes.hpp"

namespace rung::lint {

SyntaxNode LintContext::root() const {
  const SyntaxTree* tree = source().document->tree();
  return tree ? tree->root() : SyntaxNode();
}

std::string_view LintContext::text() const {
  const SyntaxTree* tree = source().document->tree();
  return tree ? std::string_view(tree->text()) : std::string_view();
}

FileShared& LintContext::file() const {
  if (file_) return *file_;
  if (!own_file_) own_file_ = std::make_unique<FileShared>();
  return *own_file_;
}

const NodeList& LintContext::nodes() const {
  std::shared_ptr<const NodeList>& nodes = file().nodes;
  if (!nodes) nodes = cache().nodes(model_, source_);
  return *nodes;
}

const std::vector<const check::Symbol*>& LintContext::pous() const {
  std::optional<std::vector<const check::Symbol*>>& pous = file().pous;
  if (!pous) pous = check::pous_of(source().symbols);
  return *pous;
}

std::shared_ptr<const NodeList> AnalysisCache::nodes(const check::ProjectModel& model, check::SourceId source) {
  std::shared_ptr<NodesSlot> slot;
  {
    std::lock_guard lock(mutex_);
    if (released_.contains(source)) {
      // The file's own lint is over: build the list for this one question and do not keep it.
      slot = std::make_shared<NodesSlot>();
    } else {
      std::shared_ptr<NodesSlot>& entry = nodes_[source];
      if (!entry) entry = std::make_shared<NodesSlot>();
      slot = entry;
    }
  }
  // Built outside the lock: other threads go on with other files meanwhile.
  std::call_once(slot->once, [&] {
    const SyntaxTree* tree = model.source(source).document->tree();
    slot->list = std::make_shared<const NodeList>(tree ? tree->root() : SyntaxNode());
  });
  return slot->list;
}

ProjectIndex& AnalysisCache::index(const check::ProjectModel& model) {
  std::call_once(index_once_, [&] {
    if (!kept_index_) {
      own_index_ = std::make_unique<ProjectIndex>();
      kept_index_ = own_index_.get();
    }
    kept_index_->refresh(model);
  });
  return *kept_index_;
}

void AnalysisCache::release_nodes(check::SourceId source) {
  std::lock_guard lock(mutex_);
  nodes_.erase(source);
  released_.insert(source);
}

AnalysisCache& LintContext::cache() const {
  if (cache_) return *cache_;
  if (!own_cache_) own_cache_ = std::make_unique<AnalysisCache>();
  return *own_cache_;
}

int64_t LintContext::threshold(std::string_view key, int64_t fallback) const {
  auto found = settings_.thresholds.find(std::string(key));
  return found == settings_.thresholds.end() ? fallback : found->second;
}

std::string_view LintContext::naming(std::string_view key, std::string_view fallback) const {
  auto found = settings_.naming.find(std::string(key));
  return found == settings_.naming.end() ? fallback : std::string_view(found->second);
}

void LintContext::report(std::string_view code, std::string message, TextRange range, std::string help,
                         std::optional<Fix> fix) {
  out_.push_back(Finding{make_diagnostic(code, std::move(message), range, std::move(help)), std::move(fix)});
}

void LintContext::report(std::string_view code, std::string message, TextRange range, std::string help,
                         std::vector<DiagnosticLabel> labels, std::optional<Fix> fix) {
  out_.push_back(
      Finding{make_diagnostic(code, std::move(message), range, std::move(help), std::move(labels)), std::move(fix)});
}

}  // namespace rung::lint
