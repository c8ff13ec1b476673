#include "formatter/unified_diff.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <unordered_map>
#include <utility>

namespace rung::format {
namespace {

// Myers' greedy algorithm on line ids, in its linear-space form: find the "middle snake" of the
// shortest edit script by running it from both ends at once, then solve both halves the same way.
// Memory stays O(N+M) and time O((N+M)D) even when a whole file is rewritten (D large).
class MyersDiff {
 public:
  MyersDiff(const std::vector<uint32_t>& a, const std::vector<uint32_t>& b) : a_(a), b_(b) {
    const size_t size = a.size() + b.size() + 2;
    forward_.resize(2 * size + 1);
    backward_.resize(2 * size + 1);
  }

  // Pairs (i, j) with a[i] == b[j] on the shortest edit script, in order.
  std::vector<std::pair<size_t, size_t>> common() {
    solve(0, a_.size(), 0, b_.size());
    return std::move(common_);
  }

 private:
  struct Snake {
    size_t x_begin, y_begin, x_end, y_end;  // relative to the sub-problem's origin
  };

  void solve(size_t a0, size_t a1, size_t b0, size_t b1) {
    // Equal lines at both ends belong to every shortest script: take them without searching.
    while (a0 < a1 && b0 < b1 && a_[a0] == b_[b0]) common_.emplace_back(a0++, b0++);
    size_t suffix = 0;
    while (a0 < a1 - suffix && b0 < b1 - suffix && a_[a1 - 1 - suffix] == b_[b1 - 1 - suffix]) ++suffix;
    if (a0 < a1 - suffix && b0 < b1 - suffix) {
      // Both sides still have lines: split at the middle snake. After the trimming above the
      // script has at least two edits, one on each side of the snake, so both halves shrink.
      const Snake s = middle_snake(a0, a1 - suffix, b0, b1 - suffix);
      solve(a0, a0 + s.x_begin, b0, b0 + s.y_begin);
      for (size_t k = 0; k < s.x_end - s.x_begin; ++k) common_.emplace_back(a0 + s.x_begin + k, b0 + s.y_begin + k);
      solve(a0 + s.x_end, a1 - suffix, b0 + s.y_end, b1 - suffix);
    }
    for (size_t k = suffix; k > 0; --k) common_.emplace_back(a1 - k, b1 - k);
  }

  // forward_[k] is the furthest x reached on diagonal k = x - y from the start; backward_[c] the
  // furthest distance from the end reached on reverse diagonal c (forward diagonal delta - c).
  Snake middle_snake(size_t a0, size_t a1, size_t b0, size_t b1) {
    const auto n = static_cast<int64_t>(a1 - a0);
    const auto m = static_cast<int64_t>(b1 - b0);
    const int64_t delta = n - m;
    const bool odd = (delta & 1) != 0;
    const int64_t max_d = (n + m + 1) / 2;
    const int64_t offset = max_d + 1;
    auto f = [&](int64_t k) -> int64_t& { return forward_[static_cast<size_t>(k + offset)]; };
    auto r = [&](int64_t c) -> int64_t& { return backward_[static_cast<size_t>(c + offset)]; };
    f(1) = 0;
    r(1) = 0;
    for (int64_t d = 0; d <= max_d; ++d) {
      for (int64_t k = -d; k <= d; k += 2) {
        int64_t x = (k == -d || (k != d && f(k - 1) < f(k + 1))) ? f(k + 1) : f(k - 1) + 1;
        int64_t y = x - k;
        const int64_t x0 = x, y0 = y;
        while (x < n && y < m && a_[a0 + static_cast<size_t>(x)] == b_[b0 + static_cast<size_t>(y)]) ++x, ++y;
        f(k) = x;
        const int64_t c = delta - k;
        if (odd && c >= -(d - 1) && c <= d - 1 && x + r(c) >= n) return snake(x0, y0, x, y);
      }
      for (int64_t c = -d; c <= d; c += 2) {
        int64_t x = (c == -d || (c != d && r(c - 1) < r(c + 1))) ? r(c + 1) : r(c - 1) + 1;
        int64_t y = x - c;
        const int64_t x0 = x, y0 = y;
        while (x < n && y < m && a_[a1 - 1 - static_cast<size_t>(x)] == b_[b1 - 1 - static_cast<size_t>(y)]) {
          ++x, ++y;
        }
        r(c) = x;
        const int64_t k = delta - c;
        if (!odd && k >= -d && k <= d && f(k) + x >= n) return snake(n - x, m - y, n - x0, m - y0);
      }
    }
    return snake(0, 0, 0, 0);  // not reached: the two searches meet by d = max_d
  }

  static Snake snake(int64_t x0, int64_t y0, int64_t x1, int64_t y1) {
    return {static_cast<size_t>(x0), static_cast<size_t>(y0), static_cast<size_t>(x1), static_cast<size_t>(y1)};
  }

  const std::vector<uint32_t>& a_;
  const std::vector<uint32_t>& b_;
  std::vector<int64_t> forward_;
  std::vector<int64_t> backward_;
  std::vector<std::pair<size_t, size_t>> common_;
};

// "@@ -l,n" numbers: a range of one line omits ",1"; an empty range names the line before it.
std::string hunk_range(size_t begin, size_t count) {
  if (count == 1) return fmt::format("{}", begin + 1);
  return fmt::format("{},{}", count == 0 ? begin : begin + 1, count);
}

void append_line(std::string& out, char mark, std::string_view line) {
  out += mark;
  out += line;
  if (line.empty() || line.back() != '\n') out += "\n\\ No newline at end of file\n";
}

}  // namespace

std::vector<std::string_view> split_lines(std::string_view text) {
  std::vector<std::string_view> lines;
  size_t begin = 0;
  while (begin < text.size()) {
    const size_t end = text.find('\n', begin);
    const size_t next = end == std::string_view::npos ? text.size() : end + 1;
    lines.push_back(text.substr(begin, next - begin));
    begin = next;
  }
  return lines;
}

std::vector<LineChange> diff_lines(const std::vector<std::string_view>& before,
                                   const std::vector<std::string_view>& after) {
  // Compare small integers instead of strings: equal lines get the same id.
  std::unordered_map<std::string_view, uint32_t> ids;
  auto ids_of = [&](const std::vector<std::string_view>& lines) {
    std::vector<uint32_t> out;
    out.reserve(lines.size());
    for (std::string_view line : lines)
      out.push_back(ids.emplace(line, static_cast<uint32_t>(ids.size())).first->second);
    return out;
  };
  const std::vector<uint32_t> a = ids_of(before);
  const std::vector<uint32_t> b = ids_of(after);

  // A line that the other text does not have at all is removed or inserted in every script: leave
  // it out of the search. When a formatter rewrites most lines this leaves little to search, and
  // the time no longer grows with the square of the file.
  std::vector<char> in_a(ids.size(), 0), in_b(ids.size(), 0);
  for (uint32_t id : a) in_a[id] = 1;
  for (uint32_t id : b) in_b[id] = 1;
  std::vector<size_t> a_index, b_index;  // positions of the lines kept for the search
  std::vector<uint32_t> a_kept, b_kept;
  for (size_t k = 0; k < a.size(); ++k) {
    if (in_b[a[k]]) a_index.push_back(k), a_kept.push_back(a[k]);
  }
  for (size_t k = 0; k < b.size(); ++k) {
    if (in_a[b[k]]) b_index.push_back(k), b_kept.push_back(b[k]);
  }

  std::vector<LineChange> changes;
  size_t i = 0, j = 0;
  for (const auto& [ci, cj] : MyersDiff(a_kept, b_kept).common()) {
    const size_t next_i = a_index[ci], next_j = b_index[cj];
    if (next_i > i || next_j > j) changes.push_back({i, next_i - i, j, next_j - j});
    i = next_i + 1;
    j = next_j + 1;
  }
  if (i < a.size() || j < b.size()) changes.push_back({i, a.size() - i, j, b.size() - j});
  return changes;
}

std::string unified_diff(std::string_view before, std::string_view after, std::string_view before_name,
                         std::string_view after_name, size_t context) {
  const std::vector<std::string_view> old_lines = split_lines(before);
  const std::vector<std::string_view> new_lines = split_lines(after);
  const std::vector<LineChange> changes = diff_lines(old_lines, new_lines);
  if (changes.empty()) return {};

  std::string out = fmt::format("--- {}\n+++ {}\n", before_name, after_name);
  for (size_t first = 0; first < changes.size();) {
    // A hunk takes every following change whose context would touch or overlap its own.
    size_t last = first;
    while (last + 1 < changes.size() &&
           changes[last + 1].before_begin - (changes[last].before_begin + changes[last].before_count) <= 2 * context) {
      ++last;
    }
    const LineChange& head = changes[first];
    const LineChange& tail = changes[last];
    const size_t lead = std::min(context, head.before_begin);
    const size_t old_begin = head.before_begin - lead;
    const size_t new_begin = head.after_begin - lead;
    const size_t old_end = std::min(old_lines.size(), tail.before_begin + tail.before_count + context);
    const size_t trail = old_end - (tail.before_begin + tail.before_count);  // the same lines in both texts
    const size_t new_end = tail.after_begin + tail.after_count + trail;
    out += fmt::format("@@ -{} +{} @@\n", hunk_range(old_begin, old_end - old_begin),
                       hunk_range(new_begin, new_end - new_begin));
    size_t line = old_begin;
    for (size_t c = first; c <= last; ++c) {
      for (; line < changes[c].before_begin; ++line) append_line(out, ' ', old_lines[line]);
      for (size_t k = 0; k < changes[c].before_count; ++k) append_line(out, '-', old_lines[line + k]);
      for (size_t k = 0; k < changes[c].after_count; ++k) append_line(out, '+', new_lines[changes[c].after_begin + k]);
      line += changes[c].before_count;
    }
    for (; line < old_end; ++line) append_line(out, ' ', old_lines[line]);
    first = last + 1;
  }
  return out;
}

}  // namespace rung::format
