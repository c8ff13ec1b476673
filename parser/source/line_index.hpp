// Byte offsets <-> line/column, at the edges of the toolchain (diagnostics, LSP).
//
// Lines end at "\n", "\r\n" or a lone "\r" (old Mac files and some CODESYS
// exports mix them). Columns are counted three ways because each consumer
// wants another: bytes (internal), code points (terminal output), UTF-16 code
// units (the Language Server Protocol default).
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

namespace rung::source {

struct Position {
  uint32_t line = 0;  // 0-based
  uint32_t byte_column = 0;
  uint32_t char_column = 0;   // code points
  uint32_t utf16_column = 0;  // UTF-16 code units (astral characters count 2)

  friend bool operator==(const Position&, const Position&) = default;
};

class LineIndex {
 public:
  // Keeps a view of `utf8`: the text must outlive the index and stay unchanged.
  explicit LineIndex(std::string_view utf8);

  // Offsets past the end clamp to the end; an offset inside a multi-byte
  // character rounds down to its first byte. O(log lines + line length).
  Position position_of(uint32_t byte_offset) const;

  // The byte offset of a column on a line. Lines past the last clamp to the
  // last line, columns past the line's end clamp to line_end (never into the
  // terminator); a UTF-16 column in the middle of a surrogate pair rounds down.
  uint32_t offset_of_utf16(uint32_t line, uint32_t utf16_column) const;
  uint32_t offset_of_char(uint32_t line, uint32_t char_column) const;

  // Always >= 1: the empty text has one empty line, and a text ending in a
  // line terminator has an empty last line after it.
  uint32_t line_count() const { return static_cast<uint32_t>(starts_.size()); }
  uint32_t line_start(uint32_t line) const;
  uint32_t line_end(uint32_t line) const;  // excludes the terminator

  // The text of `line` without its terminator; `text` is the indexed text.
  std::string_view line_text(std::string_view text, uint32_t line) const;

 private:
  uint32_t clamp_line(uint32_t line) const;

  std::string_view text_;
  std::vector<uint32_t> starts_;
};

}  // namespace rung::source
