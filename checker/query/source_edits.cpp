#include "checker/query/source_edits.hpp"

#include "parser/keywords.hpp"

namespace rung::check::query {
namespace {

using containers::ContainerKind;
using containers::Segment;

// The real segment holding the tree range [begin, end]: a range may end at its segment's end, and
// an insertion at a segment's end belongs to it (text typed after the last character of a body).
const Segment* real_segment_of(const containers::ContainerDocument& container, uint32_t begin, uint32_t end) {
  const auto holds = [&](const Segment* s) {
    return s && s->file_begin && s->virtual_begin <= begin && end <= s->virtual_begin + s->length;
  };
  const Segment* at = container.segment_at(begin);
  if (holds(at)) return at;
  if (begin > 0) {
    const Segment* before = container.segment_at(begin - 1);
    if (holds(before)) return before;
  }
  return nullptr;
}

// Whether the file byte at `file_offset` lies in a CDATA section (searching back for its start).
bool inside_cdata(std::string_view file_text, uint32_t file_offset) {
  const std::string_view before = file_text.substr(0, file_offset);
  const size_t open = before.rfind("<![CDATA[");
  if (open == std::string_view::npos) return false;
  const size_t close = before.rfind("]]>");
  return close == std::string_view::npos || close < open;
}

// Whether `replacement` may stand at `file_offset` of an XML container as it is.
bool fits_xml(std::string_view file_text, uint32_t file_offset, std::string_view replacement) {
  if (inside_cdata(file_text, file_offset)) return replacement.find("]]>") == std::string_view::npos;
  return replacement.find_first_of("<&") == std::string_view::npos && replacement.find("]]>") == std::string_view::npos;
}

bool is_xml(const containers::ContainerDocument* container) {
  return container && (container->kind == ContainerKind::TwinCat || container->kind == ContainerKind::PlcOpen);
}

}  // namespace

std::optional<std::vector<lint::TextEdit>> file_edits_of(const Document& document,
                                                         const std::vector<lint::TextEdit>& edits) {
  const containers::ContainerDocument* container = document.container();
  if (!container || container->kind == ContainerKind::None) return edits;
  std::vector<lint::TextEdit> mapped;
  mapped.reserve(edits.size());
  for (const lint::TextEdit& edit : edits) {
    if (edit.range.end < edit.range.begin) return std::nullopt;
    const Segment* segment = real_segment_of(*container, edit.range.begin, edit.range.end);
    if (!segment) return std::nullopt;
    const uint32_t begin = *segment->file_begin + (edit.range.begin - segment->virtual_begin);
    const uint32_t end = *segment->file_begin + (edit.range.end - segment->virtual_begin);
    if (is_xml(container) && !fits_xml(document.file_text(), begin, edit.replacement)) return std::nullopt;
    mapped.push_back(lint::TextEdit{{begin, end}, edit.replacement});
  }
  return mapped;
}

bool writable_in_file(const Document& document, const lint::TextEdit& file_edit) {
  const containers::ContainerDocument* container = document.container();
  if (!container || container->kind == ContainerKind::None) return true;
  const std::optional<uint32_t> begin = document.tree_offset_of(file_edit.range.begin);
  const std::optional<uint32_t> end = document.tree_offset_of(file_edit.range.end);
  if (!begin || !end || *end < *begin || !real_segment_of(*container, *begin, *end)) return false;
  return !is_xml(container) || fits_xml(document.file_text(), file_edit.range.begin, file_edit.replacement);
}

std::string_view line_end_at(std::string_view text, uint32_t offset) {
  offset = std::min<uint32_t>(offset, static_cast<uint32_t>(text.size()));
  size_t newline = text.find('\n', offset);
  if (newline == std::string_view::npos && offset > 0) newline = text.rfind('\n', offset - 1);
  if (newline == std::string_view::npos) return "\n";
  return newline > 0 && text[newline - 1] == '\r' ? "\r\n" : "\n";
}

uint32_t line_start_at(std::string_view text, uint32_t offset) {
  offset = std::min<uint32_t>(offset, static_cast<uint32_t>(text.size()));
  while (offset > 0 && text[offset - 1] != '\n' && text[offset - 1] != '\r') --offset;
  return offset;
}

uint32_t line_end_offset_at(std::string_view text, uint32_t offset) {
  offset = std::min<uint32_t>(offset, static_cast<uint32_t>(text.size()));
  while (offset < text.size() && text[offset] != '\n' && text[offset] != '\r') ++offset;
  return offset;
}

std::string_view indentation_at(std::string_view text, uint32_t offset) {
  const uint32_t start = line_start_at(text, offset);
  uint32_t end = start;
  while (end < text.size() && (text[end] == ' ' || text[end] == '\t')) ++end;
  return text.substr(start, end - start);
}

bool is_blank(std::string_view text, uint32_t from, uint32_t to) {
  for (uint32_t i = from; i < to && i < text.size(); ++i) {
    if (text[i] != ' ' && text[i] != '\t') return false;
  }
  return true;
}

std::string indent_unit(const project::FormatSettings& settings) {
  return settings.use_tabs ? std::string("\t") : std::string(settings.indent_width, ' ');
}

std::string keyword_in_case(std::string_view keyword, const project::FormatSettings& settings, std::string_view like) {
  bool lower = settings.keyword_case == project::KeywordCase::Lower;
  if (settings.keyword_case == project::KeywordCase::Preserve && !like.empty()) {
    lower = keywords::upper(like) != like;
  }
  std::string word = keywords::upper(keyword);
  if (lower) {
    for (char& c : word) c = static_cast<char>(c >= 'A' && c <= 'Z' ? c + 32 : c);
  }
  return word;
}

}  // namespace rung::check::query
