// Edits that code actions propose, from the parsed (TREE) text to the file the editor shows, and
// the small facts about the surrounding text that make inserted code look as if the author wrote
// it: the line end the file uses, the indentation of a line, the project's indentation unit.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "checker/lint/lint_rule.hpp"
#include "checker/project/format_settings.hpp"
#include "parser/document.hpp"

namespace rung::check::query {

// `edits` (TREE coordinates of `document`) as edits of its FILE text, or nullopt when one of them
// cannot be written there: it touches text a container reader synthesized (an END_FUNCTION_BLOCK
// TwinCAT does not store), spans two pieces of the container, or inserts what the XML around it
// cannot hold ("]]>" in a CDATA section, '<' or '&' in plain XML text). Plain files: unchanged.
std::optional<std::vector<lint::TextEdit>> file_edits_of(const Document& document,
                                                         const std::vector<lint::TextEdit>& edits);
// The same test for an edit already in FILE coordinates (a lint fix, which lint_source maps).
bool writable_in_file(const Document& document, const lint::TextEdit& file_edit);

// "\r\n" when the line holding `offset` (or the nearest line end after it, else before it) ends
// with one, "\n" otherwise.
std::string_view line_end_at(std::string_view text, uint32_t offset);

// The start of the line holding `offset`, and the spaces and tabs that begin that line.
uint32_t line_start_at(std::string_view text, uint32_t offset);
std::string_view indentation_at(std::string_view text, uint32_t offset);
// The end of the line holding `offset`, before its line break.
uint32_t line_end_offset_at(std::string_view text, uint32_t offset);
// Whether only spaces and tabs stand between `from` and `to`.
bool is_blank(std::string_view text, uint32_t from, uint32_t to);

// One level of indentation as `rung fmt` writes it: a tab, or indent_width spaces.
std::string indent_unit(const project::FormatSettings& settings);
// A keyword in the case the project writes keywords (`like` decides for KeywordCase::Preserve:
// lower case when it is written in lower case).
std::string keyword_in_case(std::string_view keyword, const project::FormatSettings& settings,
                            std::string_view like = {});

}  // namespace rung::check::query
