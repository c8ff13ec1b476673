// Line-level pieces of reading a CODESYS V2.3 .EXP export: lines, the first
// word of a line, the "(* @KEY := 'value' *)" object markers, and just enough
// comment and string tracking to know whether a line starts inside a comment.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace rung::containers::exp {

struct Line {
  uint32_t begin = 0;  // first byte
  uint32_t end = 0;    // end of the content, before the terminator
  uint32_t next = 0;   // start of the following line
};

// The line starting at `begin` ("\n", "\r\n" and lone "\r" end a line).
Line line_at(std::string_view text, uint32_t begin);

// The first word of the line after leading blanks, upper-cased: letters, digits
// and '_' ("END_PROGRAM", "_FBD_BODY"); empty when the line starts otherwise.
std::string first_word(std::string_view line);

// The identifier following `word` on the line, or the first identifier of the
// text after it (for "TYPE\n  Name : ..."), original case. Empty if none.
std::string name_after(std::string_view text, uint32_t from);

struct Marker {
  std::string key;    // "PATH", upper-case
  std::string value;  // between the quotes, verbatim
};

// "(* @KEY := 'value' *)" at the start of a line (after blanks), or nullopt.
std::optional<Marker> parse_marker(std::string_view line);

// "\/Folder\/Sub" -> "/Folder/Sub".
std::string unescape_path(std::string_view value);

// Tracks (* *) comments across lines, skipping '...' and "..." strings and
// "//" line comments. With nested comments off (OSCAT's "@NESTEDCOMMENTS := 'No'")
// a "(*" inside a comment does not open another level.
class CommentTracker {
 public:
  bool in_comment() const { return depth_ > 0; }
  void set_nested(bool nested) { nested_ = nested; }
  void reset() { depth_ = 0; }
  void feed(std::string_view line);

 private:
  uint32_t depth_ = 0;
  bool nested_ = true;
};

}  // namespace rung::containers::exp
