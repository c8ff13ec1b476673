// The line-picking half of range formatting (format_range in format.hpp), on its own so that it
// can be tested without the engine.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace rung::format {

struct TakenLines {
  std::string text;                  // `before` with the picked changes of `after` applied
  std::optional<size_t> first_line;  // 0-based line of `before` where the first picked change starts
};

// Takes from `after` only the changed lines (a line diff against `before`) that touch lines
// [first_line, last_line] of `before` (0-based, inclusive); every other line stays as in `before`.
// An insertion touches the range when it stands before one of its lines. A change that replaces
// as many lines as it removes is taken line by line; any other change touching the range is taken
// whole, even where it reaches outside the range (lines joined or split belong together).
TakenLines take_changed_lines(std::string_view before, std::string_view after, size_t first_line, size_t last_line);

}  // namespace rung::format
