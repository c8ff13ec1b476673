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

const std::vector<const check::Symbol*>& LintContext::pous() const {
  if (!pous_) pous_ = check::pous_of(source().symbols);
  return *pous_;
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
