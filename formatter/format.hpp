// `rung fmt`'s engine: lays out IEC 61131-3 source text (ST, IL, textual SFC, declarations,
// CONFIGURATION blocks) from its lossless syntax tree, keeping every comment and pragma.
//
// Safety: after formatting, the tokens of the result (whitespace and comments set aside, keyword
// case ignored) are compared with the input's; a difference means a formatter bug, and the input
// is returned unchanged with Status::Unsafe — a file is never written with a changed meaning.
// Most results only change whitespace in ways the grammar cannot notice, which whitespace_check
// proves without parsing them; the others are parsed and compared token by token (token_check).
#pragma once

#include <string>
#include <string_view>

#include "checker/project/format_settings.hpp"
#include "parser/diagnostic.hpp"
#include "parser/syntax_tree.hpp"

namespace rung::format {

enum class Status {
  Formatted,     // `text` is the formatted input (it may equal the input)
  SyntaxErrors,  // the input does not parse cleanly: left unchanged (`message` says where)
  Unsafe,        // the safety check failed: left unchanged (`message` names the first difference)
};

struct FormatResult {
  Status status = Status::Formatted;
  std::string text;      // the result; the input itself unless Status::Formatted
  bool changed = false;  // text differs from the input
  std::string message;   // for SyntaxErrors and Unsafe: "line 12: ..." (1-based, in the input)
};

struct FormatRequest {
  // Comments do not nest (OpenPCS, CODESYS V2.3 exports without nested comments).
  bool flat_comments = false;
};

// Formats a whole text (a plain source file, or one ST/IL part of a vendor container).
FormatResult format_text(std::string_view text, const project::FormatSettings& settings,
                         const FormatRequest& request = {});

// The same for a text whose syntax tree the caller already has (the language server keeps one
// per open document): `tree` was parsed from `text`, or from `text` with its comments read flat
// when `request.flat_comments` is set. Saves the first of format_text's parses.
FormatResult format_parsed(const SyntaxTree& tree, std::string_view text, const project::FormatSettings& settings,
                           const FormatRequest& request = {});

// Formats only the lines that intersect `range` (byte offsets in `text`), for the language
// server's range formatting; every other byte stays as it is.
FormatResult format_range(std::string_view text, TextRange range, const project::FormatSettings& settings,
                          const FormatRequest& request = {});

}  // namespace rung::format
