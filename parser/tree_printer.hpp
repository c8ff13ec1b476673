// Text renderings of a syntax tree: an indented outline for `rung parse --tree` and an
// S-expression in tree-sitter's corpus format for golden tests.
#pragma once

#include <functional>
#include <string>

#include "parser/syntax_tree.hpp"

namespace rung {

struct TreePrintOptions {
  // Renders an offset as "line:col"; the outline shows node spans with it.
  std::function<std::string(uint32_t offset)> describe_position;
  // Renders the END of a range (defaults to describe_position): for container files an end must
  // map to the end of the node's own text, not to the start of the next real text.
  std::function<std::string(uint32_t offset)> describe_end_position;
  bool include_anonymous = false;  // keywords and punctuation too
  bool include_text = true;        // leaf text after named leaves
};

// One node per line, indented by depth: `field: kind [l:c-l:c] "text"`. Iterative, so 10,000
// levels of nesting print without exhausting the stack.
std::string print_outline(SyntaxNode root, const TreePrintOptions& options);

// `(source_file (program_declaration name: (identifier) ...))`, named nodes only, as in
// tree-sitter's test corpus files.
std::string print_sexp(SyntaxNode root);

}  // namespace rung
