// L024 multiple-statements-per-line: a statement that starts on the line where the statement
// before it in the same statement list ends (`a := 1; b := 2;`, `END_IF x := 0;`). A one-line
// `IF c THEN x := 1; END_IF` or CASE branch `1: x := 1;` holds one statement per list and is fine.
#include <fmt/format.h>

#include "checker/lint/structure_pou.hpp"
#include "checker/lint/structure_rules.hpp"

namespace rung::lint::structure {
namespace {

bool on_one_line(std::string_view text, uint32_t begin, uint32_t end) {
  return text.substr(begin, end - begin).find('\n') == std::string_view::npos;
}

uint32_t line_start(std::string_view text, uint32_t offset) {
  while (offset > 0 && text[offset - 1] != '\n') --offset;
  return offset;
}

// Blanks that put the next line's text under column of `anchor`: the line's tabs kept, every other
// character before the anchor a space.
std::string indent_under(std::string_view text, uint32_t anchor) {
  std::string indent;
  for (uint32_t at = line_start(text, anchor); at < anchor; ++at) indent += text[at] == '\t' ? '\t' : ' ';
  return indent;
}

// Moves `statement` to a line of its own, aligned under `anchor` (the line's first statement):
// the blanks before it become a line break and the indentation.
Fix new_line_fix(std::string_view text, SyntaxNode statement, uint32_t anchor) {
  uint32_t begin = statement.begin();
  while (begin > 0 && (text[begin - 1] == ' ' || text[begin - 1] == '\t')) --begin;
  return Fix{"put the statement on a line of its own",
             {TextEdit{{begin, statement.begin()}, "\n" + indent_under(text, anchor)}}};
}

}  // namespace

void check_statements_per_line(LintContext& context) {
  const std::string_view text = context.text();
  const NodeList& nodes = context.nodes();
  nodes.walk(0, [&](uint32_t i) {
    if (nodes.is_extra(i)) return false;
    if (nodes.kind(i) != "statement_list") return nodes.has_children(i);
    uint32_t previous = NodeList::kNone;
    uint32_t line_first = 0;  // the first statement of the current line in this list
    nodes.for_each_child(i, [&](uint32_t child) {
      if (!nodes.is_named(child) || nodes.is_extra(child)) return;
      const std::string_view kind = nodes.kind(child);
      if (kind == "empty_statement" || kind == "label") return;  // ast::StatementKind Empty and Label
      const SyntaxNode statement = nodes.node(child);
      if (previous != NodeList::kNone && on_one_line(text, nodes.end(previous), statement.begin())) {
        uint32_t end = statement.end();
        if (const size_t eol = text.find('\n', statement.begin()); eol < end) end = static_cast<uint32_t>(eol);
        context.report("L024",
                       fmt::format("'{}' is on the line of the statement before it",
                                   message_excerpt(text.substr(statement.begin(), end - statement.begin()), 40)),
                       {statement.begin(), end},
                       "one statement per line shows each step, and breakpoints and diffs line up with it; "
                       "`rung lint --fix` moves it to a line of its own",
                       new_line_fix(text, statement, line_first));
      } else {
        line_first = statement.begin();
      }
      previous = child;
    });
    return true;
  });
}

}  // namespace rung::lint::structure
