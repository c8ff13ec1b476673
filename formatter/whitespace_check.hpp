// The formatter's quick safety check: proves, without parsing the result, that a formatted text
// parses to the same tree as its input. It holds when the output is the input's tokens, comments
// and pragmas, byte for byte (keywords and elementary type names up to letter case), with only
// whitespace between them, and that whitespace differs from the input's only in ways neither the
// generated lexer nor the external scanner (grammar/src/scanner.c) can notice:
//
// - Each gap between two tokens keeps its class: none, blanks only, or a line break. The scanner
//   tells only these classes apart (IL instructions end at line ends, header keywords count at the
//   start of a line, a '//' comment runs to its line end); no token holds whitespace across a
//   class change (time literals allow blanks after '#', strings no line break), and the lexer
//   skips any run of ' ', '\t', '\r', '\n' between tokens alike. Input gaps holding other
//   whitespace (form feed, no-break space) are left to the full check.
// - A gap may appear or disappear (x:=1 / x := 1, f (x) / f(x)) only where neither side could
//   read across it: never before the tokens the grammar reads only when joined ('<' of a generic
//   type, '#' of a typed literal, '...'), never between two word characters, after '#', between
//   ':' and '=', '(' and '*', '/' and '/' or '*', nor between S, R or REF and '=' (the ExST
//   assignments the scanner looks for). A gap may disappear only next to ')' ']' ',' ';', or before
//   '(' '[': no token of the grammar goes on across those characters.
// - The scanner looks ahead at most a fixed number of characters for a ';' (IL lines, and the
//   line after an IL line that might be a call); it counts blanks, so every stretch it could scan
//   must stay well under that budget in both texts.
//
// Then the lexer and the scanner return the same tokens at the same (shifted) places, so the
// parser takes the same steps and builds the same tree: the result's parse need not be run.
// When any condition does not hold, the answer is "cannot tell", never "unsafe": the caller then
// parses the result and runs check_tokens, which names the difference.
#pragma once

#include <string_view>
#include <vector>

#include "formatter/layout_walk.hpp"
#include "formatter/token_stream.hpp"

namespace rung::format {

// True when `output` provably parses to the same tree as `input` (whose tree parsed without
// errors, from the real bytes: not for text parsed with flattened comments). `leaves` are the
// layout walk's leaves of that tree, which the output was printed from: the check does not trust
// them to cover the input, it verifies that every byte between them is whitespace.
bool only_safe_whitespace_changes(CheckInput input, const std::vector<Leaf>& leaves, std::string_view output);

}  // namespace rung::format
