#include "checker/query/highlights.hpp"

#include <unordered_map>

#include "checker/lint/usage_analysis.hpp"
#include "checker/query/position.hpp"
#include "checker/query/references.hpp"
#include "checker/query/resolve.hpp"

namespace rung::check::query {
namespace {

// Whether a name of this kind stands for a value that can be written: a variable, or the result of
// a function, method or property inside it. A list or POU before a '.' (GVL.x := 1) is not written.
bool holds_a_value(const Symbol& symbol) {
  return symbol.kind == SymbolKind::Variable || symbol.kind == SymbolKind::Function ||
         symbol.kind == SymbolKind::Method || symbol.kind == SymbolKind::Property;
}

// What the code does with the name `name` (a reference of `symbol`), from how it is used and, for
// names in code, the usage analysis' flags at its offset.
Access access_of(const ProjectModel& model, SourceId source, SyntaxNode name, const Symbol& symbol,
                 const std::unordered_map<uint32_t, uint16_t>& flags_at) {
  const NameSite site = name_site(model, source, name);
  switch (site.use) {
    case NameUse::Declaration: return Access::Declaration;
    // fb(IN := x) and (x := 1) in an initial value set the parameter or member; fb(Q => x)
    // reads the output Q (x is the written one).
    case NameUse::Parameter: return name.parent().kind() == "output_argument" ? Access::Read : Access::Write;
    case NameUse::InitializedMember: return Access::Write;
    default: break;
  }
  const auto found = flags_at.find(name.begin());
  const bool written = found != flags_at.end() && (found->second & lint::kUseWrite) != 0;
  return written && holds_a_value(symbol) ? Access::Write : Access::Read;
}

}  // namespace

std::vector<Highlight> highlights_in(const Workspace& workspace, const Symbol* symbol, SourceId source) {
  std::vector<Highlight> highlights;
  const std::vector<Location> references = find_references_in(workspace, symbol, source, true);
  if (references.empty()) return highlights;
  const ProjectModel& model = workspace.model();
  const Symbol& target = *canonical_symbol(model, symbol);
  const Document& document = *model.source(source).document;
  const SyntaxNode root = document.tree()->root();  // find_references_in found names: there is a tree
  const lint::FileUsage usage = lint::collect_usage(model, source);
  std::unordered_map<uint32_t, uint16_t> flags_at;
  for (const lint::Use& use : usage.uses) flags_at[use.range.begin] |= use.flags;
  for (const Location& location : references) {
    Highlight highlight{.location = location};
    const std::optional<uint32_t> tree_offset = document.tree_offset_of(location.range.begin);
    if (const SyntaxNode name = tree_offset ? name_at(root, *tree_offset) : SyntaxNode()) {
      highlight.access = access_of(model, source, name, target, flags_at);
    }
    highlights.push_back(highlight);
  }
  return highlights;
}

}  // namespace rung::check::query
