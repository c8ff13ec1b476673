// Where the cursor stands, read from the words before it: at the top of a file, in a POU's header
// or declarations, in a VAR block, after ':' where a type is named, at the start of a statement,
// inside an expression, after '.', inside the arguments of a call. Completion and signature help
// ask this while the user types, so the text around the cursor is often unfinished (`fbTimer.`,
// `IF x THEN` without END_IF): the answer comes from the tokens before the cursor and the blocks
// they open and close, not from the shape error recovery gave the syntax tree.
#pragma once

#include <optional>
#include <string_view>
#include <vector>

#include "checker/project_model.hpp"

namespace rung::check::query {

// One token of the parsed text (comments and pragmas left out).
struct CodeToken {
  std::string_view text;
  TextRange range;  // tree coordinates
  bool word = false;            // an identifier or keyword
  bool newline_before = false;  // a line ends between the token before and this one
};

enum class CursorPlace : uint8_t {
  None,             // a comment, a string, a name being declared, a number: nothing to offer
  TopLevel,         // between declarations: a POU, TYPE or VAR_GLOBAL may begin
  PouHeader,        // after a POU's name on its first line: EXTENDS, IMPLEMENTS
  PouDeclarations,  // inside a POU after its header, before any statement: a VAR block, a member, or the body
  VarName,          // where a VAR block's next declaration (or END_VAR) begins
  TypeName,         // where a type is named: after ':' in a declaration, OF, POINTER TO, EXTENDS ...
  Statement,        // where a statement begins
  Expression,       // where a value begins
  Operator,         // after a complete value: AND, OR, THEN, DO ...
  Member,           // after `qualifier.`
  TypedLiteral,     // after `E_Color#`
};

// Which types fit a TypeName place.
enum class TypeFilter : uint8_t {
  Any,         // a variable's type
  Blocks,      // EXTENDS of a FUNCTION_BLOCK or CLASS
  Interfaces,  // IMPLEMENTS, EXTENDS of an INTERFACE
};

// The call whose argument list holds the cursor.
struct CallContext {
  TextRange callee;                     // the called expression (tree coordinates): F, fb, obj.M, GVL.fb
  TextRange open;                       // its '('
  size_t argument_index = 0;            // the argument the cursor is in, counted from 0
  bool argument_start = false;          // where a formal parameter name may be written
  std::string_view named;               // `name :=` / `name =>` before the cursor in this argument
  bool output = false;                  // `named` is bound with =>
  std::vector<std::string_view> given;  // formal names given in the other arguments
};

struct CursorContext {
  CursorPlace place = CursorPlace::None;
  TextRange word;  // the partial name at the cursor (tree coordinates; empty when none)
  std::string_view prefix;  // its part before the cursor
  const Symbol* scope = nullptr;  // the POU, method, action, GVL ... around the cursor
  std::string_view pou_keyword;  // the innermost open POU's keyword (upper case), "" at top level

  // TypeName
  TypeFilter types = TypeFilter::Any;
  bool type_constructors = false;  // ARRAY, POINTER TO, STRING ... may be written here
  bool structured_types = false;   // TYPE T : |  also STRUCT, UNION
  // Member, TypedLiteral: the expression before '.' or '#'
  TextRange qualifier;
  bool type_qualifier = false;  // Member: `Lib.|` where a type is named (x : Lib.T)
  // VarName: the keyword of the block (VAR_INPUT, STRUCT, TYPE ...), and whether its qualifiers
  // (CONSTANT, RETAIN ...) may still follow it
  std::string_view block_keyword;
  bool var_qualifiers = false;
  // Statement, Operator: the open IF/CASE/FOR/WHILE/REPEAT blocks, innermost first (upper case)
  std::vector<std::string_view> open_blocks;
  // Operator: the keyword that continues the statement (THEN, DO, OF, TO, BY), or ""
  std::vector<std::string_view> continuations;
  // Expression: `target := |` — the assigned expression (tree coordinates), empty otherwise
  TextRange assigned;
  // Inside the argument list of a call (in a body), whatever the place.
  std::optional<CallContext> call;
};

// The tokens of the parsed text in [begin, end) (tree coordinates), in text order. A token that
// only begins in the range is left out.
std::vector<CodeToken> code_tokens(SyntaxNode root, uint32_t begin, uint32_t end);

// The context at `tree_offset` of `source`. Never fails: a place it cannot tell is None.
CursorContext cursor_context(const ProjectModel& model, SourceId source, uint32_t tree_offset);

// The first token of the postfix expression (a.b[i]^.c, F(x).y, THIS^) that ends with
// tokens[last]; nullopt when tokens[last] ends no such expression.
std::optional<size_t> postfix_chain_begin(const std::vector<CodeToken>& tokens, size_t last);

}  // namespace rung::check::query
