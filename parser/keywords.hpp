// The words of IEC 61131-3 and its dialects that the syntax checks must know by heart: reserved
// words that cannot name anything, the standard IL operators, and which keyword a misspelled word
// most likely stands for. All comparisons ignore case.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace rung::keywords {

// ASCII upper case: keywords and identifiers compare without case.
std::string upper(std::string_view word);

// A word that is reserved in every dialect rung reads (CODESYS, TwinCAT, IEC 61131-3, OpenPCS):
// the keywords of declarations and statements, the operators written as words and the
// elementary type names. Contextual words that real code uses as names (METHOD, TYPE, STEP, AT,
// GET, ...) and the SFC qualifier letters are not in the list.
bool is_reserved(std::string_view word);

// An elementary type name (INT, TIME, STRING, ...): reserved, but also the name of a conversion
// or of a built-in function (CODESYS TIME()), so it may stand where a function is called.
bool is_type_name(std::string_view word);

// An operator written as a word (AND, OR, XOR, NOT, MOD): reserved, but also the name of a
// standard function that the IEC library declares.
bool is_operator_word(std::string_view word);

// An operator of Instruction List (LD, ST, S, R, AND, ADD, JMPC, CAL, RET, ...). Functions are
// called as IL operators too; those are not in this list.
bool is_il_operator(std::string_view word);

// The keyword `word` is a misspelling of ("" when none): ELSEIF for ELSIF, ENDIF or END_IFF for
// END_IF, VAR_GLOBAS for VAR_GLOBAL, PROGRAMM for PROGRAM. `word` must not be a keyword itself.
// With `any_keyword` false only closing words (END_...) and ELSIF are considered, the words that
// matter inside a statement; with it true the openers of blocks are considered too (PROGRAM,
// VAR_GLOBAL, STRUCT, ...), for a word that stands where a declaration may begin. A name that
// only adds digits to a keyword (Program1, Struct2) is never a misspelling.
std::string_view misspelled(std::string_view word, bool any_keyword);

// The keyword that closes a block opened by `opener` (VAR_GLOBAL -> END_VAR, PROGRAM ->
// END_PROGRAM), or "" when it has none.
std::string_view closer_of(std::string_view opener);

// Levenshtein distance of two upper-case words.
size_t edit_distance(std::string_view a, std::string_view b);

}  // namespace rung::keywords
