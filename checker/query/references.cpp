#include "checker/query/references.hpp"

#include <algorithm>

#include "checker/query/position.hpp"
#include "checker/query/resolve.hpp"
#include "checker/symbols/names.hpp"

namespace rung::check::query {
namespace {

// Offsets of whole-word, case-insensitive occurrences of `name` in `text`: the cheap prefilter
// that keeps the search fast on large projects (resolution runs on these only).
std::vector<uint32_t> word_occurrences(std::string_view text, std::string_view name) {
  std::vector<uint32_t> found;
  const char first = ascii_upper(name.front());
  for (size_t at = 0; at + name.size() <= text.size(); ++at) {
    if (ascii_upper(text[at]) != first || !names_equal(text.substr(at, name.size()), name)) continue;
    if (at > 0 && is_identifier_char(text[at - 1])) continue;
    if (at + name.size() < text.size() && is_identifier_char(text[at + name.size()])) continue;
    found.push_back(static_cast<uint32_t>(at));
  }
  return found;
}

void collect_in_source(const ProjectModel& model, SourceId id, const Symbol* target, bool include_declaration,
                       std::vector<Location>& out) {
  const SyntaxTree* tree = model.source(id).document->tree();
  if (!tree || tree->aborted()) return;
  const std::string_view name = target->name;
  const SyntaxNode root = tree->root();
  for (const uint32_t at : word_occurrences(tree->text(), name)) {
    // Only a name token of exactly this extent counts (not a comment, string or pragma).
    const SyntaxNode node = name_at(root, at);
    if (!node || node.begin() != at || node.end() != at + name.size()) continue;
    if (!include_declaration && id == target->source && node.begin() == target->name_range.begin) continue;
    if (resolve_name(model, id, node, scope_at(model, id, at)) != target) continue;
    out.push_back(location_in_file(model, id, node.range()));
  }
}

}  // namespace

std::vector<Location> find_references(const Workspace& workspace, const Symbol* symbol, bool include_declaration) {
  const ProjectModel& model = workspace.model();
  const Symbol* target = canonical_symbol(model, symbol);
  std::vector<Location> references;
  if (!target || target->name.empty()) return references;
  const bool in_library = model.source(target->source).library;
  for (SourceId id = 0; id < model.source_count(); ++id) {
    if (model.source(id).library && !in_library) continue;
    collect_in_source(model, id, target, include_declaration, references);
  }
  // The project's own files first, then the library's: a user looks for their own uses, and the
  // order must not depend on where the project and the library sit on disk.
  std::sort(references.begin(), references.end(), [&model](const Location& a, const Location& b) {
    const bool a_library = model.source(a.source).library;
    const bool b_library = model.source(b.source).library;
    if (a_library != b_library) return b_library;
    return a.path != b.path ? a.path < b.path : a.range.begin < b.range.begin;
  });
  return references;
}

std::vector<Location> find_references_in(const Workspace& workspace, const Symbol* symbol, SourceId source,
                                         bool include_declaration) {
  const ProjectModel& model = workspace.model();
  const Symbol* target = canonical_symbol(model, symbol);
  std::vector<Location> references;
  if (!target || target->name.empty() || source >= model.source_count()) return references;
  collect_in_source(model, source, target, include_declaration, references);
  return references;
}

}  // namespace rung::check::query
