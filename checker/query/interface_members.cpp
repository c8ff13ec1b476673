#include "checker/query/interface_members.hpp"

#include <algorithm>

#include "checker/query/doc_comment.hpp"
#include "checker/query/source_edits.hpp"
#include "parser/keywords.hpp"

namespace rung::check::query {
namespace {

SyntaxNode end_keyword(SyntaxNode node, std::string_view keyword) {
  for (uint32_t i = node.child_count(); i-- > 0;) {
    if (!node.child(i).is_named() && keywords::upper(node.child(i).text()) == keyword) return node.child(i);
  }
  return {};
}

std::string_view trim_right(std::string_view text) {
  while (!text.empty() && (text.back() == ' ' || text.back() == '\t' || text.back() == '\n' || text.back() == '\r')) {
    text.remove_suffix(1);
  }
  return text;
}

// `member`'s declaration with `indentation` in place of its own, lines ending in `newline`, closed
// with END_METHOD / END_PROPERTY if the interface's file leaves that out.
std::string skeleton(const Symbol& member, std::string_view indentation, std::string_view newline,
                     const project::FormatSettings& settings) {
  const std::string_view source = member.node.source();
  const std::string_view own = indentation_at(source, member.node.begin());
  const std::string_view text = trim_right(member.node.text());
  std::string out(indentation);
  size_t at = 0;
  while (at <= text.size()) {
    size_t end = text.find('\n', at);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(at, end - at);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (at > 0) {
      out += newline;
      if (line.starts_with(own)) line.remove_prefix(own.size());
      if (!trim_right(line).empty()) out += std::string(indentation) + std::string(line);
    } else {
      out += line;
    }
    at = end + 1;
  }
  const std::string_view closer = member.kind == SymbolKind::Method ? "END_METHOD" : "END_PROPERTY";
  if (!keywords::upper(text).ends_with(closer)) {
    out += std::string(newline) + std::string(indentation) + keyword_in_case(closer, settings, member.node.child(0).text());
  }
  return out;
}

// The interface member's doc comment as a (* ... *) comment above the implementation, so that
// hover on the implementation says what the interface promised; "" when it has none.
std::string doc_lines(const ProjectModel& model, const Symbol& member, std::string_view indentation,
                      std::string_view newline) {
  const std::string doc = doc_comment(model, member);
  if (doc.empty() || doc.find("*)") != std::string::npos) return {};
  std::string out = std::string(indentation) + "(* ";
  for (const char c : doc) {
    if (c == '\n') {
      out += std::string(newline) + std::string(indentation) + "   ";
    } else {
      out += c;
    }
  }
  return out + " *)" + std::string(newline);
}

}  // namespace

std::vector<MissingMembers> missing_interface_members(const ProjectModel& model, const Symbol& block) {
  std::vector<MissingMembers> result;
  if (block.has(kAbstract)) return result;  // an abstract block leaves them to its subclasses
  for (const Symbol* interface : block.interfaces) {
    if (!interface || interface->kind != SymbolKind::Interface) continue;
    MissingMembers missing{interface, {}};
    std::vector<const Symbol*> pending{interface};
    for (size_t k = 0; k < pending.size() && k < 64; ++k) {  // bounded: EXTENDS may cycle
      for (const Symbol* base : pending[k]->bases) {
        if (std::find(pending.begin(), pending.end(), base) == pending.end()) pending.push_back(base);
      }
      for (const Symbol* member : pending[k]->ordered) {
        if (member->kind != SymbolKind::Method && member->kind != SymbolKind::Property) continue;
        if (model.find_member(&block, member->name)) continue;
        const bool listed = std::any_of(missing.members.begin(), missing.members.end(),
                                        [&](const Symbol* m) { return names_equal(m->name, member->name); });
        if (!listed) missing.members.push_back(member);
      }
    }
    if (!missing.members.empty()) result.push_back(std::move(missing));
  }
  return result;
}

std::optional<lint::TextEdit> implement_members(const Workspace& workspace, const Symbol& block,
                                                const std::vector<const Symbol*>& members,
                                                const project::FormatSettings& settings) {
  const Document& document = *workspace.model().source(block.source).document;
  if (!document.tree() || !block.node || members.empty()) return std::nullopt;
  // TwinCAT and PLCopen XML keep each method in an XML element of its own, with an id the vendor
  // tool assigns: code inserted into the block's text would land in its body.
  if (const containers::ContainerDocument* container = document.container();
      container && (container->kind == containers::ContainerKind::TwinCat ||
                    container->kind == containers::ContainerKind::PlcOpen)) {
    return std::nullopt;
  }
  const std::string_view text = document.tree()->text();
  const std::string newline(line_end_at(text, block.node.begin()));
  // Members stand where the block's other members stand, else at the block's own indentation.
  std::string_view indentation = indentation_at(text, block.node.begin());
  uint32_t last_member_end = block.node.end();
  for (const Symbol* member : block.ordered) {
    if ((member->kind == SymbolKind::Method || member->kind == SymbolKind::Property) && member->node) {
      indentation = indentation_at(text, member->node.begin());
      last_member_end = std::max(last_member_end, member->node.end());
    }
  }
  std::string code;
  for (const Symbol* member : members) {
    if (!member->node) return std::nullopt;
    code += doc_lines(workspace.model(), *member, indentation, newline) + skeleton(*member, indentation, newline, settings) + newline;
  }
  lint::TextEdit edit;
  const SyntaxNode end_block = end_keyword(block.node, block.kind == SymbolKind::Class ? "END_CLASS" : "END_FUNCTION_BLOCK");
  if (end_block && is_blank(text, line_start_at(text, end_block.begin()), end_block.begin())) {
    const uint32_t at = line_start_at(text, end_block.begin());
    edit = {{at, at}, code};
  } else if (end_block) {
    return std::nullopt;  // END_FUNCTION_BLOCK on a line with other code: no good place for whole declarations
  } else {
    const uint32_t at = line_end_offset_at(text, last_member_end == 0 ? 0 : last_member_end - 1);
    code.resize(code.size() - newline.size());
    edit = {{at, at}, newline + code};
  }
  const std::optional<std::vector<lint::TextEdit>> mapped = file_edits_of(document, {edit});
  if (!mapped) return std::nullopt;
  return mapped->front();
}

}  // namespace rung::check::query
