#include "checker/query/case_else.hpp"

#include "checker/query/source_edits.hpp"
#include "parser/keywords.hpp"

namespace rung::check::query {
namespace {

// Whether `node` is the first thing on its line.
bool starts_line(std::string_view text, SyntaxNode node) {
  return is_blank(text, line_start_at(text, node.begin()), node.begin());
}

SyntaxNode end_case_keyword(SyntaxNode statement) {
  for (uint32_t i = statement.child_count(); i-- > 0;) {
    const SyntaxNode child = statement.child(i);
    if (!child.is_named() && keywords::upper(child.text()) == "END_CASE") return child;
  }
  return {};
}

}  // namespace

SyntaxNode case_statement_at(const Document& document, uint32_t tree_offset) {
  const SyntaxTree* tree = document.tree();
  if (!tree || tree->aborted()) return {};
  for (SyntaxNode node = tree->root().descendant_for_range(tree_offset, tree_offset); node; node = node.parent()) {
    if (node.kind() == "case_statement") return node.has_error() ? SyntaxNode() : node;
  }
  return {};
}

std::optional<lint::TextEdit> add_case_else(const Document& document, SyntaxNode case_statement,
                                            const project::FormatSettings& settings) {
  if (!case_statement || case_statement.has_error() || case_statement.first_child_of_kind("else_clause")) {
    return std::nullopt;
  }
  const SyntaxNode end_case = end_case_keyword(case_statement);
  if (!end_case) return std::nullopt;
  const std::string_view text = document.tree()->text();
  const std::string unit = indent_unit(settings);
  // ELSE stands where the labels stand; its comment where the first label's statements stand.
  std::string label_indent = std::string(indentation_at(text, case_statement.begin())) + unit;
  std::string body_indent = label_indent + unit;
  if (const SyntaxNode first = case_statement.first_child_of_kind("case_element")) {
    if (starts_line(text, first)) label_indent = indentation_at(text, first.begin());
    body_indent = label_indent + unit;
    const SyntaxNode body = first.child_by_field("body");
    const SyntaxNode statement = body ? body.named_child(0) : SyntaxNode();
    if (statement && starts_line(text, statement)) body_indent = indentation_at(text, statement.begin());
  }
  const std::string else_word = keyword_in_case("ELSE", settings, end_case.text());
  const std::string comment = "(* other values *)";
  lint::TextEdit edit;
  if (starts_line(text, end_case)) {
    const std::string newline(line_end_at(text, end_case.begin()));
    const uint32_t at = line_start_at(text, end_case.begin());
    edit = {{at, at}, label_indent + else_word + newline + body_indent + comment + newline};
  } else {
    edit = {{end_case.begin(), end_case.begin()}, else_word + " " + comment + " "};
  }
  const std::optional<std::vector<lint::TextEdit>> mapped = file_edits_of(document, {edit});
  if (!mapped) return std::nullopt;
  return mapped->front();
}

}  // namespace rung::check::query
