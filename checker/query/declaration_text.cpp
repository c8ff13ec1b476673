#include "checker/query/declaration_text.hpp"

#include <fmt/format.h>

#include "checker/constant/const_value.hpp"
#include "checker/query/call_site.hpp"

namespace rung::check::query {
namespace {

constexpr size_t kMaxInitialValue = 60;  // characters of an initial value shown before "..."
constexpr size_t kMaxTypeLines = 30;

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v'; }

// The comments and pragmas inside `range`, in text order.
std::vector<TextRange> extras_in(SyntaxNode root, TextRange range) {
  std::vector<TextRange> extras;
  walk_preorder(root, [&](SyntaxNode node) {
    if (node.end() <= range.begin || node.begin() >= range.end) return false;
    if (node.kind() == "comment" || node.kind() == "pragma") {
      extras.push_back(node.range());
      return false;
    }
    return true;
  });
  return extras;
}

// The text of `range` with comments and pragmas blanked (newlines kept).
std::string without_extras(SyntaxNode root, TextRange range) {
  const std::string_view text = root.source();
  range.end = std::min<uint32_t>(range.end, static_cast<uint32_t>(text.size()));
  if (range.end <= range.begin) return {};
  std::string out(text.substr(range.begin, range.end - range.begin));
  for (const TextRange extra : extras_in(root, range)) {
    for (uint32_t at = std::max(extra.begin, range.begin); at < std::min(extra.end, range.end); ++at) {
      char& c = out[at - range.begin];
      if (c != '\n') c = ' ';
    }
  }
  return out;
}

// The lines of `range` without comments: blank lines dropped, common indentation removed.
std::vector<std::string> code_lines(SyntaxNode root, TextRange range) {
  const std::string text = without_extras(root, range);
  std::vector<std::string> lines;
  size_t indent = std::string::npos;
  for (size_t start = 0; start <= text.size();) {
    size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    std::string line = text.substr(start, end - start);
    while (!line.empty() && is_space(line.back())) line.pop_back();
    if (!line.empty()) {
      // The first line starts at the declaration, not at its line's start: it sets no indentation.
      if (!lines.empty()) indent = std::min(indent, line.find_first_not_of(" \t"));
      lines.push_back(std::move(line));
    }
    start = end + 1;
  }
  for (size_t i = 1; i < lines.size() && indent != std::string::npos; ++i) lines[i].erase(0, std::min(indent, lines[i].size()));
  for (std::string& line : lines) {
    for (char& c : line) {
      if (c == '\t') c = ' ';
    }
  }
  return lines;
}

std::string cut(std::string text, size_t limit) {
  if (text.size() <= limit) return text;
  text.resize(limit);
  return text + " ...";
}

bool ends_header(SyntaxNode child) {
  const std::string_view kind = child.kind();
  if (kind == "var_block" || kind == "statement_list" || kind == "il_body" || kind == "sfc_network" ||
      kind == "method_declaration" || kind == "property_declaration" || kind == "action_declaration" ||
      kind == "transition_declaration" || kind == "type_declaration" || kind == "property_accessor") {
    return true;
  }
  return !child.is_named() && child.text().size() > 4 && names_equal(child.text().substr(0, 4), "END_");
}

// The children of `node` in one pass (child(i) in a loop is quadratic in tree-sitter 0.20).
std::vector<SyntaxNode> children_of(SyntaxNode node) {
  std::vector<SyntaxNode> children;
  walk_preorder(node, [&](SyntaxNode child) {
    if (child == node) return true;
    children.push_back(child);
    return false;
  });
  return children;
}

std::string variable_text(const ProjectModel& model, const Symbol& symbol) {
  const SyntaxNode root = symbol.node.kind() == "var_declaration" ? symbol.node : SyntaxNode();
  std::string text(symbol.name);
  if (!root) return text + " : " + written_type(model, symbol) + ";";
  const ast::VarDeclaration::Parts parts = ast::VarDeclaration(symbol.node).parts();
  const SyntaxNode tree_root = model.source(symbol.source).document->tree()->root();
  if (parts.location) text += " AT " + code_text(tree_root, parts.location.range());
  text += " : " + written_type(model, symbol);
  if (parts.init_arguments) text += code_text(tree_root, parts.init_arguments.range());
  if (parts.initial_value) text += " := " + cut(code_text(tree_root, parts.initial_value.range()), kMaxInitialValue);
  return text + ";";
}

std::string enum_value_text(const ProjectModel& model, const Symbol& symbol) {
  std::string text(symbol.name);
  const SyntaxNode root = model.source(symbol.source).document->tree()->root();
  if (SyntaxNode written = symbol.node.child_by_field("value")) return text + " := " + code_text(root, written.range());
  if (const auto value = model.enum_value(&symbol)) text += " := " + int128_to_string(*value);
  return text;
}

std::string pou_text(const ProjectModel& model, const Symbol& symbol) {
  const SyntaxNode root = model.source(symbol.source).document->tree()->root();
  uint32_t header_end = symbol.node.end();
  const std::vector<SyntaxNode> children = children_of(symbol.node);
  for (SyntaxNode child : children) {
    if (ends_header(child)) {
      header_end = child.begin();
      break;
    }
  }
  std::string text = code_text(root, {symbol.node.begin(), header_end});
  for (SyntaxNode child : children) {
    if (child.kind() != "var_block") continue;
    const ast::VarBlock block(child);
    const ast::VarSection section = block.section();
    if (section != ast::VarSection::Input && section != ast::VarSection::Output && section != ast::VarSection::InOut) {
      continue;
    }
    text += "\n" + std::string(ast::var_section_name(section));
    for (const ast::VarDeclaration& declaration : block.declarations()) {
      text += "\n    " + code_text(root, declaration.node().range());
      for (SyntaxNode name : declaration.names()) {
        const Symbol* parameter = symbol.own_member(name.text());
        if (parameter && parameter->has(kExtensible)) {
          text += fmt::format(" // {}3, {}4 ... may follow", name.text().substr(0, name.text().size() - 1),
                              name.text().substr(0, name.text().size() - 1));
        }
      }
    }
    text += "\nEND_VAR";
  }
  return text;
}

std::string type_text(const ProjectModel& model, const Symbol& symbol) {
  const SyntaxNode root = model.source(symbol.source).document->tree()->root();
  SyntaxNode declaration = symbol.node;
  const SyntaxNode holder = symbol.node.parent();
  bool alone = false;
  if (holder && holder.kind() == "type_declaration") {
    size_t types = 0;
    for (SyntaxNode child : holder.named_children()) types += child.kind() != "comment" && child.kind() != "pragma";
    alone = types == 1;
  }
  if (alone) declaration = holder;
  std::vector<std::string> lines = code_lines(root, declaration.range());
  if (lines.size() > kMaxTypeLines) {
    lines.resize(kMaxTypeLines);
    lines.push_back("...");
  }
  std::string text = alone ? "" : "TYPE ";
  for (size_t i = 0; i < lines.size(); ++i) text += (i ? "\n" : "") + lines[i];
  if (!alone) text += "\nEND_TYPE";
  return text;
}

}  // namespace

std::string code_text(SyntaxNode root, TextRange range) {
  const std::string text = without_extras(root, range);
  std::string out;
  bool space = false;
  for (char c : text) {
    if (is_space(c)) {
      space = !out.empty();
      continue;
    }
    if (space) out += ' ';
    space = false;
    out += c;
  }
  return out;
}

std::string written_type(const ProjectModel& model, const Symbol& symbol) {
  if (symbol.type_node && symbol.source < model.source_count()) {
    return code_text(model.source(symbol.source).document->tree()->root(), symbol.type_node.range());
  }
  const Type* type = model.type_of(&symbol);
  return type && !type->is_unknown() ? type->name : "?";
}

std::string declaration_text(const ProjectModel& model, const Symbol& symbol) {
  if (symbol.source >= model.source_count() || !symbol.node) return std::string(symbol.name);
  const SyntaxTree* tree = model.source(symbol.source).document->tree();
  if (!tree || tree->aborted()) return std::string(symbol.name);
  switch (symbol.kind) {
    case SymbolKind::Variable: return variable_text(model, symbol);
    case SymbolKind::EnumValue: return enum_value_text(model, symbol);
    case SymbolKind::DataType: return type_text(model, symbol);
    case SymbolKind::GlobalList:
      return std::string(symbol.has(kQualifiedOnly) ? "{attribute 'qualified_only'}\n" : "") + "VAR_GLOBAL // " +
             std::string(symbol.name);
    default:
      if (is_pou_kind(symbol.kind)) return pou_text(model, symbol);
      return std::string(symbol.name);
  }
}

Signature signature_of(const ProjectModel& model, const Symbol& callee) {
  Signature signature;
  signature.label = std::string(callee.name);
  if (callee.node && callee.source < model.source_count()) {
    if (SyntaxNode generics = callee.node.child_by_field("type_parameters")) {
      signature.label += code_text(model.source(callee.source).document->tree()->root(), generics.range());
    }
  }
  signature.label += "(";
  bool first = true;
  for (const Symbol* parameter : call_parameters(&callee)) {
    if (names_equal(parameter->name, "EN") || names_equal(parameter->name, "ENO")) continue;
    if (!first) signature.label += ", ";
    first = false;
    const uint32_t begin = static_cast<uint32_t>(signature.label.size());
    signature.label += std::string(parameter->name) +
                       (parameter->section == ast::VarSection::Output ? " => " : " : ") + written_type(model, *parameter);
    signature.parameters.push_back(parameter);
    signature.ranges.emplace_back(begin, static_cast<uint32_t>(signature.label.size()));
    if (parameter->has(kExtensible)) signature.label += ", ...";
  }
  signature.label += ")";
  if (callee.type_node && callee.kind != SymbolKind::Property) {
    signature.label += " : " + code_text(model.source(callee.source).document->tree()->root(), callee.type_node.range());
  }
  return signature;
}

}  // namespace rung::check::query
