// The first pass of the formatter: walks the syntax tree's leaves in text order and records, for
// each token, comment and pragma, what the layout needs — how many line breaks stood before it,
// the indentation level it gets when it starts a line (from the tree's nesting), its spacing role
// and whether its letter case may change. It also collects the declarations and IL instructions
// (for column alignment) and the conditions and argument lists (for line breaking).
//
// Levels. Every node gets a level L (for its own keywords and for a line it starts) and a
// continuation level C = L + 1 (for a line that starts inside it). A block's body is one level in
// (IF/CASE/FOR/WHILE/REPEAT, VAR blocks, STRUCT, CONFIGURATION...); a POU's body, members and VAR
// blocks stay at the POU's level, as the CODESYS and TwinCAT editors show them. A node that starts
// in the middle of a line is anchored to that line's level, so a continuation line is one level
// deeper than the line where its expression (or open parenthesis) began, and a closing ')' or ']'
// at the start of a line goes back to that line's level.
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

#include "formatter/keyword_case.hpp"
#include "parser/syntax_tree.hpp"

namespace rung::format {

// How a token takes part in spacing (see spacing.cpp).
enum class Role : uint8_t {
  Word,     // identifier, literal, IL operator, address
  Keyword,  // IF, END_VAR, ARRAY, TO ...
  Comma,
  Semicolon,
  OpenCall,      // '(' right after a name: f(x), STRING(10), INT(1..5), 3(0)
  OpenGroup,     // '(' of a parenthesized expression, an initializer or an enumeration
  OpenIl,        // '(' of IL's deferred operator: spacing as typed
  OpenIndex,     // '[' of an index, ARRAY[, STRING[
  OpenInit,      // '[' of an array initializer
  Close,         // ')' and ']'
  Dot,           // a.b
  GlobalDot,     // .x (CODESYS global scope)
  Caret,         // p^
  At,            // @ of an OpenPCS step macro
  BinaryOp,      // + - * / ** = <> < > <= >= &
  BinaryWordOp,  // AND OR XOR MOD AND_THEN OR_ELSE
  UnaryOp,       // - + &
  UnaryWordOp,   // NOT
  Assign,        // := => ?= S= R= REF=
  DeclColon,     // x : INT, METHOD M : BOOL
  LabelColon,    // case labels, jump labels, STEP S1:, ACTION A:
  Range,         // ..
  Other,
  Trivia,  // comment or pragma
};

struct Leaf {
  uint32_t begin = 0;
  uint32_t end = 0;
  uint32_t newlines = 0;  // line breaks before it (in the input, or 1 where a break was added)
  int32_t level = 0;      // indentation when it starts a line
  // Indentation of a comment line right before it: its level, or the body's level for a block's
  // closing keyword (a comment before END_IF belongs to the IF's statements).
  int32_t comment_level = 0;
  uint32_t glue = 0;  // nonzero: the node (typed literal, generic type) whose tokens stay as typed
  Role role = Role::Other;
  CaseClass case_class = CaseClass::None;
  bool space_before = false;  // the input had whitespace right before it
  bool multiline = false;     // a comment or pragma that spans lines
  bool line_comment = false;  // a // comment (runs to the end of the line)
  bool opens_block = false;   // the last token before a block's body (THEN, DO, VAR, OF, ...)
  bool trivia() const { return role == Role::Trivia; }
};

inline constexpr uint32_t kNoLeaf = UINT32_MAX;

// A line that may be column-aligned with its neighbours: a variable declaration (or STRUCT
// field), or an IL instruction.
struct AlignedRow {
  uint32_t first = kNoLeaf;  // its first leaf
  uint32_t last = kNoLeaf;   // its last leaf (the ';' of a declaration)
  // The token that starts the first aligned column: the ':' before a declaration's type, the
  // operand of an IL instruction.
  uint32_t column = kNoLeaf;
  uint32_t assign = kNoLeaf;  // the ':=' of a declaration's initial value
  uint32_t group = 0;         // the VAR block, STRUCT or IL body it belongs to (its start offset)
  bool il = false;
};

struct WalkResult {
  std::vector<Leaf> leaves;
  std::vector<AlignedRow> rows;
  // Candidates for line breaking (only collected when `collect_breaks`).
  std::vector<SyntaxNode> conditions;      // IF/ELSIF/WHILE/UNTIL conditions
  std::vector<SyntaxNode> argument_lists;  // argument lists of ST calls (never IL: it is line-based)
};

struct WalkOptions {
  bool collect_breaks = false;
  // Leaf indices before which a line break is added (from line breaking), sorted.
  const std::vector<uint32_t>* added_breaks = nullptr;
};

// `text` holds the real bytes (comments as written); the tree may have been parsed from a copy
// with flattened comments, of the same length.
WalkResult walk_leaves(const SyntaxTree& tree, std::string_view text, const WalkOptions& options);

// Line breaks in a gap of whitespace (\r\n, \n and a lone \r count one each).
uint32_t count_line_breaks(std::string_view gap);

}  // namespace rung::format
