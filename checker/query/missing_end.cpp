#include "checker/query/missing_end.hpp"

#include <algorithm>
#include <cctype>
#include <utility>

#include "checker/query/source_edits.hpp"
#include "parser/diagnostic_codes.hpp"
#include "parser/keywords.hpp"

namespace rung::check::query {
namespace {

bool is_statement_closer(std::string_view closer) {
  return closer == "END_IF" || closer == "END_CASE" || closer == "END_FOR" || closer == "END_WHILE" ||
         closer == "END_REPEAT";
}

// Blocks whose extent the indentation shows; a POU or TYPE usually starts in column 1 with its
// contents in column 1 too, so only the parser's recovery point tells where it ends.
bool follows_layout(std::string_view closer) {
  return is_statement_closer(closer) || closer == "END_VAR" || closer == "END_STRUCT" || closer == "END_UNION";
}

// The word that closes a block: keywords::closer_of knows the declaration blocks.
std::string_view closer_of(std::string_view opener) {
  static constexpr std::pair<std::string_view, std::string_view> kMore[] = {
      {"IF", "END_IF"},     {"CASE", "END_CASE"},     {"FOR", "END_FOR"},   {"WHILE", "END_WHILE"},
      {"REPEAT", "END_REPEAT"}, {"TYPE", "END_TYPE"}, {"UNION", "END_UNION"}, {"CLASS", "END_CLASS"},
      {"ACTION", "END_ACTION"}, {"TRANSITION", "END_TRANSITION"}, {"STEP", "END_STEP"},
  };
  for (const auto& [open, close] : kMore) {
    if (open == opener) return close;
  }
  return keywords::closer_of(opener);
}

// A line starting with one of these words still belongs to the block `opener` opened.
bool continues(std::string_view opener, std::string_view word) {
  if (opener == "IF") return word == "ELSIF" || word == "ELSE";
  if (opener == "CASE") return word == "ELSE";
  if (opener == "REPEAT") return word == "UNTIL";
  return false;
}

// Indentation width in columns (tabs to the next multiple of four, as PLC editors show them).
uint32_t width_of(std::string_view indentation) {
  uint32_t width = 0;
  for (const char c : indentation) width = c == '\t' ? (width / 4 + 1) * 4 : width + 1;
  return width;
}

std::string first_word(std::string_view text, uint32_t from) {
  while (from < text.size() && (text[from] == ' ' || text[from] == '\t')) ++from;
  uint32_t end = from;
  while (end < text.size() && (std::isalnum(static_cast<unsigned char>(text[end])) || text[end] == '_')) ++end;
  return keywords::upper(text.substr(from, end - from));
}

uint32_t next_line_start(std::string_view text, uint32_t line_end) {
  if (line_end < text.size() && text[line_end] == '\r') ++line_end;
  if (line_end < text.size() && text[line_end] == '\n') ++line_end;
  return line_end;
}

// The end of the line's text without trailing spaces.
uint32_t content_end(std::string_view text, uint32_t line_start) {
  uint32_t end = line_end_offset_at(text, line_start);
  while (end > line_start && (text[end - 1] == ' ' || text[end - 1] == '\t')) --end;
  return end;
}

// Where the block opened at `opener` (tree offset) ends: the end of its last line, at most `limit`.
uint32_t block_end(std::string_view text, uint32_t opener, std::string_view opener_word, uint32_t limit) {
  const uint32_t opener_width = width_of(indentation_at(text, opener));
  uint32_t last = std::min(content_end(text, line_start_at(text, opener)), limit);
  for (uint32_t line = next_line_start(text, line_end_offset_at(text, opener)); line < limit && line < text.size();
       line = next_line_start(text, line_end_offset_at(text, line))) {
    const uint32_t end = content_end(text, line);
    if (is_blank(text, line, end)) continue;
    if (width_of(indentation_at(text, line)) <= opener_width && !continues(opener_word, first_word(text, line))) break;
    last = std::min(end, limit);
  }
  return last;
}

// The text that closes the block at `at`, laid out for where `at` stands on its line.
lint::TextEdit closing_edit(std::string_view text, uint32_t at, std::string_view indentation, const std::string& closer) {
  const std::string_view newline = line_end_at(text, at);
  const uint32_t start = line_start_at(text, at);
  if (is_blank(text, start, at)) {
    return lint::TextEdit{{start, start}, std::string(indentation) + closer + std::string(newline)};
  }
  if (is_blank(text, at, line_end_offset_at(text, at))) {
    return lint::TextEdit{{at, at}, std::string(newline) + std::string(indentation) + closer};
  }
  return lint::TextEdit{{at, at}, closer + " "};
}

}  // namespace

std::vector<ClosingInsertion> missing_end_insertions(const Document& document,
                                                     const project::FormatSettings& settings) {
  std::vector<ClosingInsertion> result;
  const SyntaxTree* tree = document.tree();
  if (!tree) return result;
  const std::string_view text = tree->text();
  for (const Diagnostic& diagnostic : document.diagnostics()) {
    if (diagnostic.code != codes::kUnclosedBlock || diagnostic.labels.empty()) continue;
    const std::optional<uint32_t> opener_begin = document.tree_offset_of(diagnostic.labels.front().range.begin);
    const std::optional<uint32_t> opener_end = document.tree_offset_of(diagnostic.labels.front().range.end);
    if (!opener_begin || !opener_end || *opener_end <= *opener_begin || *opener_end > text.size()) continue;
    const std::string_view opener_text = text.substr(*opener_begin, *opener_end - *opener_begin);
    const std::string opener = keywords::upper(opener_text);
    const std::string_view closer_word = closer_of(opener);
    if (closer_word.empty()) continue;
    const uint32_t limit = std::max(*opener_end, document.tree_offset_of(diagnostic.range.begin)
                                                     .value_or(static_cast<uint32_t>(text.size())));
    const uint32_t at = follows_layout(closer_word) ? block_end(text, *opener_begin, opener, limit) : limit;
    const std::string keyword = keyword_in_case(closer_word, settings, opener_text);
    std::string closer = keyword;
    if (is_statement_closer(closer_word) && settings.end_semicolon == project::EndSemicolon::Always) closer += ';';
    const std::optional<std::vector<lint::TextEdit>> edits =
        file_edits_of(document, {closing_edit(text, at, indentation_at(text, *opener_begin), closer)});
    if (!edits) continue;
    result.push_back(ClosingInsertion{diagnostic, keyword, edits->front()});
  }
  return result;
}

}  // namespace rung::check::query
