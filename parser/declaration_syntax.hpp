// Syntax rules checked on the finished tree because the grammar cannot state them: a tree-sitter
// lexer turns a word into a keyword only where the grammar expects that keyword, so anywhere
// else a keyword reads as a name, and an unknown word at the start of a line reads as an IL
// instruction (IL bodies are legal in .st files, and functions are IL operators). This pass finds
//  - a reserved word that declares something (a variable "While", a POU "PROGRAM Program"),
//  - a declared name with two underscores in a row (A__BCD, __a), which IEC 61131-3 and the
//    CODESYS manuals forbid (names the system declares, __NEW or __SYSTEM, are only used),
//  - an IL "instruction" whose operator is a keyword that is never an IL operator (a stray
//    END_VAR) or a misspelled keyword (PROGRAMM, VAR_GLOBAS), and a misspelled keyword alone on
//    a line at top level,
//  - a TYPE name without ':' before STRUCT (the grammar reads the struct all the same).
// It only walks declarations and IL bodies, never into Structured Text statements.
#pragma once

#include <functional>
#include <string>
#include <string_view>

#include "parser/diagnostic.hpp"
#include "parser/syntax_tree.hpp"

namespace rung {

struct SyntaxFinding {
  std::string_view code;
  TextRange range;
  std::string message;
  std::string help;
  // A misspelled opener (VAR_GLOBAS) explains the stray closer of its block (END_VAR) later on.
  std::string_view explains_closer;
  // Set for a keyword where none belongs (an END_PROGRAM after the program): upper case.
  std::string stray_keyword;
};

// The report of a keyword that stands where nothing it could belong to is open.
SyntaxFinding stray_keyword(SyntaxNode keyword);

void check_declaration_syntax(const SyntaxTree& tree, const std::function<void(SyntaxFinding)>& report);

}  // namespace rung
