#include "parser/source/line_index.hpp"

#include <algorithm>

#include "parser/source/utf8.hpp"

namespace rung::source {

LineIndex::LineIndex(std::string_view utf8) : text_(utf8) {
  starts_.push_back(0);
  const size_t n = utf8.size();
  for (size_t i = 0; i < n; ++i) {
    const char c = utf8[i];
    if (c == '\n') {
      starts_.push_back(static_cast<uint32_t>(i + 1));
    } else if (c == '\r') {
      if (i + 1 < n && utf8[i + 1] == '\n') ++i;
      starts_.push_back(static_cast<uint32_t>(i + 1));
    }
  }
}

uint32_t LineIndex::clamp_line(uint32_t line) const {
  return std::min(line, line_count() - 1);
}

uint32_t LineIndex::line_start(uint32_t line) const {
  return starts_[clamp_line(line)];
}

uint32_t LineIndex::line_end(uint32_t line) const {
  line = clamp_line(line);
  if (line + 1 == line_count()) return static_cast<uint32_t>(text_.size());
  uint32_t end = starts_[line + 1];
  // Strip the terminator: "\n", "\r" or "\r\n".
  if (end > starts_[line] && text_[end - 1] == '\n') --end;
  if (end > starts_[line] && text_[end - 1] == '\r') --end;
  return end;
}

std::string_view LineIndex::line_text(std::string_view text, uint32_t line) const {
  const uint32_t begin = std::min<size_t>(line_start(line), text.size());
  const uint32_t end = std::min<size_t>(line_end(line), text.size());
  return text.substr(begin, end - begin);
}

Position LineIndex::position_of(uint32_t byte_offset) const {
  uint32_t offset = std::min<size_t>(byte_offset, text_.size());
  const auto next = std::upper_bound(starts_.begin(), starts_.end(), offset);
  const auto line = static_cast<uint32_t>(next - starts_.begin() - 1);
  const uint32_t start = starts_[line];
  // Round down to the first byte of the character (at most 3 steps back in valid UTF-8).
  for (int k = 0; k < 3 && offset > start && offset < text_.size() &&
                  is_utf8_continuation(static_cast<unsigned char>(text_[offset]));
       ++k) {
    --offset;
  }

  Position pos;
  pos.line = line;
  pos.byte_column = offset - start;
  size_t i = start;
  while (i < offset) {
    const Utf8Step step = decode_utf8_at(text_, i);
    ++pos.char_column;
    pos.utf16_column += utf16_length(step.code_point);
    i += step.length;
  }
  return pos;
}

uint32_t LineIndex::offset_of_utf16(uint32_t line, uint32_t utf16_column) const {
  const uint32_t end = line_end(line);
  size_t i = line_start(line);
  uint32_t units = 0;
  while (i < end) {
    const Utf8Step step = decode_utf8_at(text_, i);
    const uint32_t width = utf16_length(step.code_point);
    if (units + width > utf16_column) break;  // the column is at or inside this character
    units += width;
    i += step.length;
  }
  return static_cast<uint32_t>(std::min<size_t>(i, end));
}

uint32_t LineIndex::offset_of_char(uint32_t line, uint32_t char_column) const {
  const uint32_t end = line_end(line);
  size_t i = line_start(line);
  for (uint32_t k = 0; k < char_column && i < end; ++k) i += decode_utf8_at(text_, i).length;
  return static_cast<uint32_t>(std::min<size_t>(i, end));
}

}  // namespace rung::source
