// Range formatting: the whole text is formatted (layout depends on context: a VAR block's
// alignment, an IF's indentation), then only the changed lines that touch the range are taken.
#include "formatter/range_format.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <optional>

#include "formatter/format.hpp"
#include "formatter/unified_diff.hpp"

namespace rung::format {
namespace {

// The 0-based line holding byte `offset` of `text`.
size_t line_of(std::string_view text, uint32_t offset) {
  offset = std::min<uint32_t>(offset, static_cast<uint32_t>(text.size()));
  return static_cast<size_t>(std::count(text.begin(), text.begin() + offset, '\n'));
}

bool touches(const LineChange& change, size_t first, size_t last) {
  if (change.before_count == 0) return change.before_begin >= first && change.before_begin <= last;  // an insertion
  return change.before_begin <= last && change.before_begin + change.before_count > first;
}

}  // namespace

TakenLines take_changed_lines(std::string_view before_text, std::string_view after_text, size_t first_line,
                              size_t last_line) {
  const std::vector<std::string_view> before = split_lines(before_text);
  const std::vector<std::string_view> after = split_lines(after_text);
  TakenLines out;
  size_t kept = 0;  // lines of `before` up to here are in out.text
  for (const LineChange& change : diff_lines(before, after)) {
    if (!touches(change, first_line, last_line)) continue;
    for (; kept < change.before_begin; ++kept) out.text += before[kept];
    if (change.before_count == change.after_count) {
      // Lines rewritten one for one (re-indented, keywords re-cased): each is its own change.
      for (size_t k = 0; k < change.before_count; ++k, ++kept) {
        const bool in_range = kept >= first_line && kept <= last_line;
        if (in_range && !out.first_line) out.first_line = kept;
        out.text += in_range ? after[change.after_begin + k] : before[kept];
      }
      continue;
    }
    if (!out.first_line) out.first_line = change.before_begin;
    for (size_t k = 0; k < change.after_count; ++k) out.text += after[change.after_begin + k];
    kept += change.before_count;
  }
  for (; kept < before.size(); ++kept) out.text += before[kept];
  return out;
}

FormatResult format_range(std::string_view text, TextRange range, const project::FormatSettings& settings,
                          const FormatRequest& request) {
  FormatResult whole = format_text(text, settings, request);
  if (whole.status != Status::Formatted || !whole.changed) return whole;

  // A range that ends at the start of a line (a selection of whole lines) does not take that line.
  const size_t first = line_of(text, range.begin);
  const size_t last = line_of(text, range.end > range.begin ? range.end - 1 : range.begin);

  TakenLines taken = take_changed_lines(text, whole.text, first, last);
  FormatResult out;
  out.text = std::move(taken.text);
  out.changed = out.text != text;

  // Taking some changed lines and not others is only right when the formatter's changes are line
  // by line; if it moved a token or comment between two separate changes, taking one of them
  // would lose or double it. Then the partial result no longer formats to the same text as the
  // whole input did, which this check catches.
  if (out.changed && format_text(out.text, settings, request).text != whole.text) {
    out.status = Status::Unsafe;
    out.text = std::string(text);
    out.changed = false;
    out.message = fmt::format(
        "line {}: the formatting of the range depends on lines outside it; format the whole "
        "text instead",
        *taken.first_line + 1);
  }
  return out;
}

}  // namespace rung::format
