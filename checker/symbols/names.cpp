#include "checker/symbols/names.hpp"

#include <algorithm>
#include <vector>

namespace rung::check {

bool names_equal(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i) {
    if (ascii_upper(a[i]) != ascii_upper(b[i])) return false;
  }
  return true;
}

std::string upper_name(std::string_view name) {
  std::string upper(name);
  for (char& c : upper) c = ascii_upper(c);
  return upper;
}

size_t NameHash::operator()(std::string_view name) const {
  // FNV-1a over the upper-cased bytes.
  size_t hash = 1469598103934665603ull;
  for (char c : name) {
    hash ^= static_cast<unsigned char>(ascii_upper(c));
    hash *= 1099511628211ull;
  }
  return hash;
}

size_t name_distance(std::string_view a, std::string_view b, size_t limit) {
  const size_t n = a.size(), m = b.size();
  if ((n > m ? n - m : m - n) > limit) return limit + 1;
  // Three rows of the optimal-string-alignment table.
  std::vector<size_t> before(m + 1), previous(m + 1), current(m + 1);
  for (size_t j = 0; j <= m; ++j) previous[j] = j;
  for (size_t i = 1; i <= n; ++i) {
    current[0] = i;
    size_t row_min = current[0];
    for (size_t j = 1; j <= m; ++j) {
      const bool same = ascii_upper(a[i - 1]) == ascii_upper(b[j - 1]);
      size_t cost = std::min({previous[j] + 1, current[j - 1] + 1, previous[j - 1] + (same ? 0 : 1)});
      if (i > 1 && j > 1 && ascii_upper(a[i - 1]) == ascii_upper(b[j - 2]) &&
          ascii_upper(a[i - 2]) == ascii_upper(b[j - 1])) {
        cost = std::min(cost, before[j - 2] + 1);
      }
      current[j] = cost;
      row_min = std::min(row_min, cost);
    }
    if (row_min > limit) return limit + 1;
    std::swap(before, previous);
    std::swap(previous, current);
  }
  return std::min(previous[m], limit + 1);
}

std::string_view closest_name(std::string_view name, std::span<const std::string_view> candidates) {
  // Short names tolerate one edit, longer ones a third of their length, at most three.
  const size_t limit = std::min<size_t>(3, std::max<size_t>(1, name.size() / 3));
  std::string_view best;
  size_t best_distance = limit + 1;
  for (std::string_view candidate : candidates) {
    if (candidate.empty() || names_equal(candidate, name)) continue;
    const size_t distance = name_distance(name, candidate, limit);
    if (distance < best_distance ||
        (distance == best_distance && distance <= limit && upper_name(candidate) < upper_name(best))) {
      best = candidate;
      best_distance = distance;
    }
  }
  return best_distance <= limit ? best : std::string_view{};
}

}  // namespace rung::check
