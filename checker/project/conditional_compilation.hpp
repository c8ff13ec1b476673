// Conditional compilation (CODESYS ExST): `{IF cond} ... {ELSIF cond} ... {ELSE} ... {END_IF}`,
// `{define NAME [value]}` and `{undefine NAME}`. The first branch of a group whose condition holds
// is compiled, the others are not; a group without a true branch and without {ELSE} compiles
// nothing. rung models "not compiled" by blanking the inactive text (line ends kept, so every
// position stays where it was) before the text is read for checking: code in an inactive branch
// then gives no diagnostics and declares nothing.
//
// Conditions: NOT, AND, OR, parentheses, TRUE/FALSE and integer constants (non-zero holds), and
//   defined(NAME)                   NAME is a define ({define} above, or rung.toml [defines])
//   hasvalue(NAME, 'value')         NAME is defined with exactly that value
//   defined(variable: v)            v is a variable visible at the {IF} (locals, then globals)
//   defined(type: T)                a data type (or function block, or elementary type) T
//   defined(pou: P)                 a POU or an action P
//   defined(task: T), defined(resource: R)
//   hasattribute(pou: P, 'attr'), hasattribute(variable: v, 'attr')
//   hastype(variable: v, TYPE)      TYPE an elementary type, ANY_* category or user type
// The questions about declarations are answered by a callback, so this file knows nothing of the
// project model (checker/conditional_sources.cpp answers them from the ProjectModel).
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "parser/diagnostic.hpp"
#include "parser/syntax_tree.hpp"

namespace rung::project {

// One conditional pragma of a text: `range` spans "{...}", `content` the text inside the braces.
struct ConditionalPragma {
  TextRange range;
  TextRange content;
};

// The conditional pragmas of a parsed text, in text order (pragmas are extras anywhere in the tree).
std::vector<ConditionalPragma> find_conditional_pragmas(const SyntaxTree& tree);

// What a condition asks about the project's declarations.
struct DeclarationQuestion {
  enum class Ask { Defined, HasAttribute, HasType };
  enum class Kind { Variable, Type, Pou, Task, Resource };
  Ask ask = Ask::Defined;
  Kind kind = Kind::Variable;
  std::string_view name;      // as written; may be dotted (GVL.x, PLC_PRG.ActionA)
  std::string_view argument;  // HasAttribute: the attribute name (unquoted); HasType: the type name
  uint32_t at = 0;            // offset of the {IF}/{ELSIF} in the text: the scope of variables
};
using DeclarationOracle = std::function<bool(const DeclarationQuestion&)>;

// rung.toml [defines]: name -> value ("" for a define without value). Names are case-insensitive.
using Defines = std::map<std::string, std::string>;

struct ConditionalResult {
  std::string text;                     // the input with the inactive regions blanked
  std::vector<TextRange> inactive;      // the blanked regions, in text order
  std::vector<Diagnostic> diagnostics;  // E606: unbalanced pragmas, conditions that do not read
};

// Evaluates the conditional pragmas of `text` (as found by find_conditional_pragmas) in text order.
// Inactive regions are blanked except the conditional pragmas inside them, which stay so that the
// structure of the groups can still be checked on the blanked text. Conditions of inactive groups
// are read (syntax errors are reported) but not evaluated, and {define}s there do not count.
ConditionalResult evaluate_conditionals(std::string_view text, std::span<const ConditionalPragma> pragmas,
                                        const Defines& defines, const DeclarationOracle& oracle);

// The same for a text that has not been parsed yet (parses it to find its pragmas).
ConditionalResult apply_conditional_compilation(std::string_view text, const Defines& defines,
                                                const DeclarationOracle& oracle);

// Only the E606 findings (structure and condition syntax), for the checker: they do not depend on
// what the conditions evaluate to.
std::vector<Diagnostic> check_conditional_pragmas(std::string_view text, std::span<const ConditionalPragma> pragmas);

// Whether `text` may hold a conditional pragma ("{IF", "{define", ... in any case): a cheap test
// before parsing.
bool may_have_conditional_pragmas(std::string_view text);

}  // namespace rung::project
