#include "checker/query/position.hpp"

namespace rung::check::query {
namespace {

bool is_name_node(SyntaxNode node) {
  if (!node) return false;
  const std::string_view kind = node.kind();
  return kind == "identifier" || kind == "il_operator";
}

// Declarations that open a scope: the names of their variables and members are visible inside.
bool opens_scope(const Symbol& symbol) {
  return is_pou_kind(symbol.kind) || symbol.kind == SymbolKind::DataType || symbol.kind == SymbolKind::GlobalList ||
         symbol.kind == SymbolKind::Configuration;
}

bool node_contains(SyntaxNode node, uint32_t offset) {
  return node && node.begin() <= offset && offset < node.end();
}

bool contains(const Symbol& symbol, uint32_t offset) {
  if (node_contains(symbol.node, offset)) return true;
  // A list of globals keeps the first VAR_GLOBAL block as its node; later blocks of the same
  // list (same file, same name) are found through their variables.
  if (symbol.kind == SymbolKind::GlobalList) {
    for (const Symbol* variable : symbol.ordered) {
      if (node_contains(variable->node.parent(), offset)) return true;
    }
  }
  return false;
}

uint32_t extent(const Symbol& symbol) {
  return symbol.node ? symbol.node.end() - symbol.node.begin() : UINT32_MAX;
}

const Symbol* innermost_member(const Symbol& symbol, uint32_t offset) {
  for (const Symbol* member : symbol.ordered) {
    if (opens_scope(*member) && contains(*member, offset)) return innermost_member(*member, offset);
  }
  return &symbol;
}

}  // namespace

SyntaxNode name_at(SyntaxNode root, uint32_t tree_offset) {
  if (!root) return {};
  SyntaxNode at = root.descendant_for_range(tree_offset, tree_offset + 1);
  if (is_name_node(at) && at.begin() <= tree_offset) return at;
  if (tree_offset == 0) return {};
  SyntaxNode before = root.descendant_for_range(tree_offset - 1, tree_offset);
  return is_name_node(before) && before.end() == tree_offset ? before : SyntaxNode();
}

const Symbol* scope_at(const ProjectModel& model, SourceId source, uint32_t tree_offset) {
  const Symbol* best = nullptr;
  // Top-level declarations may nest (a PROGRAM's VAR_GLOBAL list lies inside the PROGRAM, a
  // snippet's unnamed PROGRAM spans the file): the smallest one that contains the offset wins.
  for (const Symbol* top : model.source(source).symbols.top_level) {
    if (!opens_scope(*top) || !contains(*top, tree_offset)) continue;
    if (!best || extent(*top) < extent(*best)) best = top;
  }
  return best ? innermost_member(*best, tree_offset) : nullptr;
}

std::optional<QueryPoint> query_point(const ProjectModel& model, SourceId source, uint32_t file_offset) {
  if (source >= model.source_count()) return std::nullopt;
  const Document& document = *model.source(source).document;
  const SyntaxTree* tree = document.tree();
  if (!tree || tree->aborted()) return std::nullopt;
  // The same mapping the diagnostics use, read backwards: file offset -> parsed text.
  const std::optional<uint32_t> tree_offset = document.tree_offset_of(file_offset);
  if (!tree_offset) return std::nullopt;
  QueryPoint point{.source = source, .tree_offset = *tree_offset};
  const SyntaxNode root = tree->root();
  point.name = name_at(root, *tree_offset);
  point.node = point.name ? point.name : root.descendant_for_range(*tree_offset, *tree_offset + 1);
  while (point.node && !point.node.is_named()) point.node = point.node.parent();
  point.scope = scope_at(model, source, *tree_offset);
  return point;
}

std::optional<QueryPoint> query_point(const Workspace& workspace, SourceId source, uint32_t file_offset) {
  return query_point(workspace.model(), source, file_offset);
}

}  // namespace rung::check::query
