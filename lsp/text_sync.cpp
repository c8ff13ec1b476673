#include "lsp/text_sync.hpp"

#include "parser/source/line_index.hpp"

namespace rung::lsp {
namespace {

std::optional<uint32_t> offset_of(const source::LineIndex& lines, const Json& position) {
  if (!position.is_object()) return std::nullopt;
  const auto line = position.find("line");
  const auto character = position.find("character");
  if (line == position.end() || character == position.end() || !line->is_number_integer() ||
      !character->is_number_integer() || line->get<int64_t>() < 0 || character->get<int64_t>() < 0) {
    return std::nullopt;
  }
  const uint64_t l = line->get<uint64_t>();
  const uint64_t c = character->get<uint64_t>();
  // A line past the last one means the end of the text (an edit appended at the end).
  if (l >= lines.line_count()) return lines.line_end(lines.line_count() - 1);
  return lines.offset_of_utf16(static_cast<uint32_t>(l), static_cast<uint32_t>(std::min<uint64_t>(c, UINT32_MAX)));
}

}  // namespace

std::optional<std::string> apply_content_change(std::string& text, const Json& change) {
  if (!change.is_object()) return "content change is not an object";
  const auto new_text = change.find("text");
  if (new_text == change.end() || !new_text->is_string()) return "content change without text";
  const auto range = change.find("range");
  if (range == change.end() || range->is_null()) {
    text = new_text->get<std::string>();
    return std::nullopt;
  }
  if (text.size() > UINT32_MAX) return "document too large for incremental changes";
  const source::LineIndex lines(text);
  const auto begin = offset_of(lines, range->value("start", Json()));
  const auto end = offset_of(lines, range->value("end", Json()));
  if (!begin || !end) return "content change with a malformed range";
  if (*end < *begin) return "content change whose range ends before it starts";
  text.replace(*begin, *end - *begin, new_text->get_ref<const std::string&>());
  return std::nullopt;
}

}  // namespace rung::lsp
