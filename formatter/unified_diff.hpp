// Line diffs: which lines changed between two texts (Myers' O((N+M)D) algorithm in linear space)
// and the unified diff text `rung fmt --diff` prints, as `diff -u` and `git diff` print it.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace rung::format {

// The lines of `text`, each with its "\n" (a "\r\n" line keeps its '\r'); the last line has no
// terminator when the text does not end with one. An empty text has no lines.
std::vector<std::string_view> split_lines(std::string_view text);

// Lines [before_begin, before_begin + before_count) of the old text are replaced by lines
// [after_begin, after_begin + after_count) of the new one (0-based; a count may be 0).
struct LineChange {
  size_t before_begin = 0;
  size_t before_count = 0;
  size_t after_begin = 0;
  size_t after_count = 0;
  bool operator==(const LineChange&) const = default;
};

// The changes that turn `before` into `after`, in order, with as few removed plus inserted lines
// as possible. Lines compare byte for byte, line ends included.
std::vector<LineChange> diff_lines(const std::vector<std::string_view>& before,
                                   const std::vector<std::string_view>& after);

// The unified diff of two texts: "--- <before_name>", "+++ <after_name>", then "@@ -l,n +l,n @@"
// hunks with `context` unchanged lines around each change; a line without a line end is followed
// by "\ No newline at end of file". Empty when the texts are equal.
std::string unified_diff(std::string_view before, std::string_view after, std::string_view before_name,
                         std::string_view after_name, size_t context = 3);

}  // namespace rung::format
