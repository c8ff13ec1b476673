// The tokens of a syntax tree as the full safety check (token_check) compares them: the
// significant tokens in text order (with whether their letter case may change), the comments and
// pragmas (each pragma one piece, braces included), and optionally the tree's shape. Read straight
// from the tree, independently of the layout walk, so that a bug in the walk cannot hide itself.
#pragma once

#include <tree_sitter/api.h>

#include <cstdint>
#include <string_view>
#include <utility>
#include <vector>

#include "parser/syntax_tree.hpp"

namespace rung::format {

struct CheckInput {
  const SyntaxTree* tree = nullptr;
  std::string_view text;  // the real bytes (the tree may have been parsed from flattened comments)
};

struct Token {
  std::string_view text;
  uint32_t offset = 0;       // in its own text (for the input: where a message points)
  bool ignore_case = false;  // keyword or elementary type name
};

struct TokenStream {
  std::vector<Token> tokens;
  std::vector<Token> trivia;                         // comments and pragmas
  std::vector<std::pair<TSSymbol, uint32_t>> shape;  // named nodes in preorder, with their offsets
  bool has_error = false;
};

// One cursor walk over the tree; `with_shape` also records the named nodes.
TokenStream token_stream_of(CheckInput in, bool with_shape);

}  // namespace rung::format
