// Runs grammar/queries/highlights.scm over tests/grammar/highlights_golden.st with the committed
// parser and compares every capture with tests/grammar/highlights_golden.expected (produced by
// scripts/grammar/update-highlight-golden.sh with the tree-sitter CLI). So a grammar change that
// silently changes what editors highlight fails CI.
#include <gtest/gtest.h>
#include <tree_sitter/api.h>

#include <sstream>
#include <string>
#include <vector>

#include "parser/syntax_tree.hpp"
#include "tests/support/test_paths.hpp"

namespace rung {
namespace {

// The subset of regular expressions the queries use: literals, '.', [classes] with ranges and
// negation, '*', and the anchors '^' and '$'. (Unanchored patterns search, like #match? does.)
class MiniRegex {
 public:
  explicit MiniRegex(std::string pattern) : p_(std::move(pattern)) {}
  bool search(std::string_view text) const {
    if (!p_.empty() && p_[0] == '^') return match_here(1, text, 0);
    for (size_t i = 0; i <= text.size(); ++i)
      if (match_here(0, text, i)) return true;
    return false;
  }

 private:
  // Length of the atom at pattern position pi, and whether it matches character c.
  size_t atom(size_t pi, char c, bool* ok) const {
    if (p_[pi] == '[') {
      size_t j = pi + 1;
      bool negate = j < p_.size() && p_[j] == '^';
      if (negate) ++j;
      bool hit = false;
      bool first = true;
      while (j < p_.size() && (p_[j] != ']' || first)) {
        first = false;
        if (j + 2 < p_.size() && p_[j + 1] == '-' && p_[j + 2] != ']') {
          if (c >= p_[j] && c <= p_[j + 2]) hit = true;
          j += 3;
        } else {
          if (c == p_[j]) hit = true;
          ++j;
        }
      }
      *ok = hit != negate;
      return j + 1 - pi;
    }
    if (p_[pi] == '\\' && pi + 1 < p_.size()) {
      *ok = c == p_[pi + 1];
      return 2;
    }
    *ok = p_[pi] == '.' || p_[pi] == c;
    return 1;
  }

  bool match_here(size_t pi, std::string_view t, size_t ti) const {
    if (pi == p_.size()) return true;
    if (p_[pi] == '$' && pi + 1 == p_.size()) return ti == t.size();
    bool ok = false;
    size_t len = atom(pi, ti < t.size() ? t[ti] : '\0', &ok);
    if (pi + len < p_.size() && p_[pi + len] == '*') {
      // Greedy star with backtracking.
      size_t k = ti;
      while (true) {
        if (match_here(pi + len + 1, t, k)) return true;
        if (k >= t.size()) return false;
        bool step = false;
        atom(pi, t[k], &step);
        if (!step) return false;
        ++k;
      }
    }
    if (ti >= t.size() || !ok) return false;
    return match_here(pi + len, t, ti + 1);
  }

  std::string p_;
};

std::string escape(std::string_view s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '\\': out += "\\\\"; break;
      case '"': out += "\\\""; break;
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\t': out += "\\t"; break;
      default: out += c;
    }
  }
  return out;
}

// Evaluates the text predicates (#match?, #any-of?, #eq? and their not- forms) of a match.
bool predicates_hold(const TSQuery* q, const TSQueryMatch& m, std::string_view source) {
  uint32_t steps_count = 0;
  const TSQueryPredicateStep* steps = ts_query_predicates_for_pattern(q, m.pattern_index, &steps_count);
  auto capture_text = [&](uint32_t capture_id) -> std::string_view {
    for (uint16_t i = 0; i < m.capture_count; ++i) {
      if (m.captures[i].index == capture_id) {
        TSNode n = m.captures[i].node;
        return source.substr(ts_node_start_byte(n), ts_node_end_byte(n) - ts_node_start_byte(n));
      }
    }
    return {};
  };
  auto string_value = [&](uint32_t id) {
    uint32_t len = 0;
    const char* s = ts_query_string_value_for_id(q, id, &len);
    return std::string(s, len);
  };
  uint32_t i = 0;
  while (i < steps_count) {
    uint32_t end = i;
    while (end < steps_count && steps[end].type != TSQueryPredicateStepTypeDone) ++end;
    std::string name = string_value(steps[i].value_id);
    if (name == "match?" || name == "not-match?" || name == "any-of?" || name == "not-any-of?" || name == "eq?" ||
        name == "not-eq?") {
      std::string_view subject = capture_text(steps[i + 1].value_id);
      bool result = false;
      if (name == "match?" || name == "not-match?") {
        result = MiniRegex(string_value(steps[i + 2].value_id)).search(subject);
      } else if (name == "any-of?" || name == "not-any-of?") {
        for (uint32_t k = i + 2; k < end; ++k)
          if (subject == string_value(steps[k].value_id)) result = true;
      } else {
        std::string other = steps[i + 2].type == TSQueryPredicateStepTypeCapture
                                ? std::string(capture_text(steps[i + 2].value_id))
                                : string_value(steps[i + 2].value_id);
        result = subject == other;
      }
      if (name.rfind("not-", 0) == 0) result = !result;
      if (!result) return false;
    }
    i = end + 1;
  }
  return true;
}

TEST(GrammarHighlights, GoldenCaptures) {
  std::string source = test::read_file(test::source_dir() / "tests/grammar/highlights_golden.st");
  std::string query_text = test::read_file(test::source_dir() / "grammar/queries/highlights.scm");
  ASSERT_FALSE(source.empty());
  SyntaxTree::Options options;
  options.keep_parse_tree = true;  // the query runs on tree-sitter's own tree, as in an editor
  SyntaxTree tree = SyntaxTree::parse(source, options);
  ASSERT_FALSE(tree.root().has_error()) << "the golden sample must parse cleanly";

  uint32_t error_offset = 0;
  TSQueryError error = TSQueryErrorNone;
  TSQuery* q = ts_query_new(tree_sitter_iec61131(), query_text.data(), static_cast<uint32_t>(query_text.size()),
                            &error_offset, &error);
  ASSERT_NE(q, nullptr) << "highlights.scm does not compile at byte " << error_offset;
  TSQueryCursor* cursor = ts_query_cursor_new();
  ts_query_cursor_exec(cursor, q, ts_tree_root_node(tree.raw()));

  std::ostringstream out;
  TSQueryMatch match;
  uint32_t capture_index = 0;
  while (ts_query_cursor_next_capture(cursor, &match, &capture_index)) {
    if (!predicates_hold(q, match, tree.text())) {
      ts_query_cursor_remove_match(cursor, match.id);
      continue;
    }
    const TSQueryCapture& c = match.captures[capture_index];
    uint32_t name_len = 0;
    const char* name = ts_query_capture_name_for_id(q, c.index, &name_len);
    TSPoint s = ts_node_start_point(c.node), e = ts_node_end_point(c.node);
    uint32_t b = ts_node_start_byte(c.node), en = ts_node_end_byte(c.node);
    out << s.row << ':' << s.column << '-' << e.row << ':' << e.column << ' ' << std::string(name, name_len) << " \""
        << escape(std::string_view(tree.text()).substr(b, en - b)) << "\"\n";
  }
  ts_query_cursor_delete(cursor);
  ts_query_delete(q);

  std::string expected = test::read_file(test::source_dir() / "tests/grammar/highlights_golden.expected");
  EXPECT_EQ(out.str(), expected);
}

}  // namespace
}  // namespace rung
