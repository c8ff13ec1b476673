#include "formatter/token_check.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "formatter/comment_text.hpp"
#include "formatter/keyword_case.hpp"
#include "formatter/syntax_kinds.hpp"
#include "formatter/token_stream.hpp"

namespace rung::format {
namespace {

uint32_t line_of(std::string_view text, uint32_t offset) {
  offset = std::min<uint32_t>(offset, static_cast<uint32_t>(text.size()));
  return 1 + static_cast<uint32_t>(std::count(text.begin(), text.begin() + offset, '\n'));
}

std::string excerpt(std::string_view text) {
  const size_t cut = text.find_first_of("\r\n");
  if (cut != std::string_view::npos) text = text.substr(0, cut);
  if (text.size() > 40) return std::string(text.substr(0, 37)) + "...";
  return std::string(text);
}

size_t index_at(const std::vector<Token>& tokens, uint32_t offset) {
  auto it =
      std::lower_bound(tokens.begin(), tokens.end(), offset, [](const Token& t, uint32_t at) { return t.offset < at; });
  return it != tokens.end() && it->offset == offset ? static_cast<size_t>(it - tokens.begin()) : tokens.size();
}

// Applies the rewrites to the input's tokens, each validated on the input's tree; a rewrite
// that does not hold there is an error.
std::optional<std::string> apply_to_tokens(CheckInput input, const std::vector<Rewrite>& rewrites,
                                           std::vector<Token>& tokens) {
  static constexpr std::string_view kSemicolon = ";";
  static constexpr std::string_view kElsif = "ELSIF";
  struct Change {
    size_t index;
    enum { Insert, Remove, Replace } what;
    std::string_view text;
  };
  std::vector<Change> changes;
  for (const Rewrite& r : rewrites) {
    const size_t i = index_at(tokens, r.at);
    if (i == tokens.size()) return fmt::format("line {}: rewrite at no token", line_of(input.text, r.at));
    SyntaxNode leaf = input.tree->root().descendant_for_range(r.at, r.at + 1);
    switch (r.kind) {
      case Rewrite::Kind::AddSemicolon:
        if (!is_statement_end_keyword(leaf) || (i + 1 < tokens.size() && tokens[i + 1].text == ";"))
          return fmt::format("line {}: ';' added where it does not end a statement", line_of(input.text, r.at));
        changes.push_back({i + 1, Change::Insert, kSemicolon});
        break;
      case Rewrite::Kind::RemoveSemicolon: {
        // Empty statements right after END_IF (END_IF;;) may all go.
        size_t before = i;
        while (before > 0 && tokens[before - 1].text == ";") --before;
        const bool after_end = before > 0 && is_statement_end_keyword(input.tree->root().descendant_for_range(
                                                 tokens[before - 1].offset, tokens[before - 1].offset + 1));
        if (tokens[i].text != ";" || !after_end)
          return fmt::format("line {}: ';' removed that does not follow an END_ keyword", line_of(input.text, r.at));
      }
        changes.push_back({i, Change::Remove, {}});
        break;
      case Rewrite::Kind::MergeElseIf: {
        const ElseIfMerge merge = else_if_merge_at(*input.tree, input.text, r.at);
        if (!merge.valid())
          return fmt::format("line {}: ELSE IF merged where it is not safe", line_of(input.text, r.at));
        changes.push_back({i, Change::Remove, {}});
        changes.push_back({index_at(tokens, merge.if_keyword.begin()), Change::Replace, kElsif});
        changes.push_back({index_at(tokens, merge.end_if.begin()), Change::Remove, {}});
        if (merge.end_semicolon) changes.push_back({index_at(tokens, merge.end_semicolon.begin()), Change::Remove, {}});
        break;
      }
    }
  }
  std::stable_sort(changes.begin(), changes.end(), [](const Change& a, const Change& b) { return a.index < b.index; });
  std::vector<Token> out;
  out.reserve(tokens.size() + changes.size());
  size_t next = 0;
  for (size_t i = 0; i <= tokens.size(); ++i) {
    bool keep = i < tokens.size();
    Token token = keep ? tokens[i] : Token{};
    for (; next < changes.size() && changes[next].index == i; ++next) {
      const Change& c = changes[next];
      if (c.what == Change::Insert) out.push_back({c.text, i < tokens.size() ? tokens[i].offset : 0, false});
      if (c.what == Change::Remove) keep = false;
      if (c.what == Change::Replace) token = {c.text, token.offset, true};
    }
    if (keep) out.push_back(token);
  }
  tokens = std::move(out);
  return std::nullopt;
}

}  // namespace

std::optional<std::string> check_tokens(CheckInput input, CheckInput output, const std::vector<Rewrite>& rewrites) {
  TokenStream in = token_stream_of(input, rewrites.empty());
  TokenStream out = token_stream_of(output, rewrites.empty());
  if (out.has_error) return std::string("line 1: the formatted text does not parse (a formatter bug)");
  if (auto problem = apply_to_tokens(input, rewrites, in.tokens)) return problem;

  const size_t common = std::min(in.tokens.size(), out.tokens.size());
  for (size_t i = 0; i < common; ++i) {
    const Token& a = in.tokens[i];
    const Token& b = out.tokens[i];
    if (a.text == b.text) continue;
    if (a.ignore_case && b.ignore_case && equal_ignoring_case(a.text, b.text)) continue;
    return fmt::format("line {}: the formatter changed '{}' into '{}'", line_of(input.text, a.offset), excerpt(a.text),
                       excerpt(b.text));
  }
  if (in.tokens.size() != out.tokens.size()) {
    const uint32_t at = common < in.tokens.size() ? in.tokens[common].offset : static_cast<uint32_t>(input.text.size());
    return fmt::format("line {}: the formatter {} tokens", line_of(input.text, at),
                       in.tokens.size() > out.tokens.size() ? "lost" : "added");
  }
  const size_t trivia = std::min(in.trivia.size(), out.trivia.size());
  for (size_t i = 0; i < trivia; ++i) {
    const std::string_view before = in.trivia[i].text;
    const std::string_view after = out.trivia[i].text;
    // Blanks at a comment's line ends are the one change a comment may see (comment_text.hpp).
    const bool same = before == after || (is_comment(before) && printed_comment(before) == after);
    if (!same)
      return fmt::format("line {}: the formatter changed the comment '{}'", line_of(input.text, in.trivia[i].offset),
                         excerpt(in.trivia[i].text));
  }
  if (in.trivia.size() != out.trivia.size()) {
    const uint32_t at = trivia < in.trivia.size() ? in.trivia[trivia].offset : static_cast<uint32_t>(input.text.size());
    return fmt::format("line {}: the formatter {} a comment", line_of(input.text, at),
                       in.trivia.size() > out.trivia.size() ? "lost" : "added");
  }
  auto same_shape = [&] {
    return in.shape.size() == out.shape.size() &&
           std::equal(in.shape.begin(), in.shape.end(), out.shape.begin(),
                      [](const auto& a, const auto& b) { return a.first == b.first; });
  };
  if (rewrites.empty() && !same_shape()) {
    size_t i = 0;
    while (i < in.shape.size() && i < out.shape.size() && in.shape[i].first == out.shape[i].first) ++i;
    const uint32_t at = i < in.shape.size() ? in.shape[i].second : static_cast<uint32_t>(input.text.size());
    return fmt::format("line {}: the formatted text parses to another tree", line_of(input.text, at));
  }
  return std::nullopt;
}

}  // namespace rung::format
