#include "formatter/spacing.hpp"

#include "formatter/keyword_case.hpp"

namespace rung::format {
namespace {

enum class Space { None, One, Keep };

bool is_word_char(unsigned char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c >= 0x80 ||
         c == '#' || c == '%' || c == '\'' || c == '"' || c == '$';
}

bool is_digit(char c) {
  return c >= '0' && c <= '9';
}

// Whether two tokens that the input separated may touch without being read differently: two
// words would merge (a b -> ab), some character pairs form another token or open a comment
// (: = -> :=, ( * -> a comment, 1 .5 -> 1.5), and S, R and REF before '=' would become the
// set/reset assignments S=, R=, REF=.
bool may_touch(std::string_view left, std::string_view right) {
  if (left.empty() || right.empty()) return true;
  const char l = left.back();
  const char r = right.front();
  if (is_word_char(static_cast<unsigned char>(l)) && is_word_char(static_cast<unsigned char>(r))) return false;
  static constexpr std::string_view kPairs[] = {":=", "=>", "<=", ">=", "<>", "**", "..", "(*",
                                                "*)", "//", "/*", "*/", "?=", "=<", "=="};
  const char pair[2] = {l, r};
  for (std::string_view p : kPairs)
    if (p == std::string_view(pair, 2)) return false;
  if ((is_digit(l) && r == '.') || (l == '.' && is_digit(r))) return false;
  if (r == '=') {
    for (std::string_view word : {"S", "R", "REF"}) {
      if (left.size() >= word.size() && equal_ignoring_case(left.substr(left.size() - word.size()), word) &&
          (left.size() == word.size() ||
           !is_word_char(static_cast<unsigned char>(left[left.size() - word.size() - 1]))))
        return false;
    }
  }
  return true;
}

bool is_wordlike(Role role) {
  return role == Role::Word || role == Role::Keyword || role == Role::BinaryWordOp || role == Role::UnaryWordOp;
}

bool is_open(Role role) {
  return role == Role::OpenCall || role == Role::OpenGroup || role == Role::OpenIndex || role == Role::OpenInit;
}

Space rule(const Leaf& p, const Leaf& n, const project::FormatSettings& settings) {
  const Space ops = settings.spaces_around_operators ? Space::One : Space::None;
  if (n.trivia()) return p.trivia() ? Space::Keep : Space::One;  // a comment after code: one space
  if (p.trivia()) return Space::Keep;
  if (p.glue != 0 && p.glue == n.glue) return Space::Keep;  // INT#5, FB<10>: as typed
  if (n.role == Role::Comma || n.role == Role::Semicolon || n.role == Role::Close) return Space::None;
  if (is_open(p.role)) return Space::None;
  if (p.role == Role::OpenIl) return Space::Keep;
  if (p.role == Role::Comma) return settings.space_after_comma ? Space::One : Space::None;
  if (p.role == Role::Semicolon) return Space::One;
  if (p.role == Role::At) return Space::None;
  if (p.role == Role::Dot || n.role == Role::Dot || p.role == Role::GlobalDot) return Space::None;
  if (n.role == Role::Caret) return Space::None;
  if (n.role == Role::OpenCall || n.role == Role::OpenIndex) return Space::None;
  if (p.role == Role::UnaryOp) return Space::None;
  if (p.role == Role::UnaryWordOp) return n.role == Role::OpenGroup ? Space::Keep : Space::One;  // NOT x, NOT(x)
  if (p.role == Role::BinaryWordOp || n.role == Role::BinaryWordOp) return Space::One;
  if (p.role == Role::BinaryOp || n.role == Role::BinaryOp) return ops;
  if (p.role == Role::Assign || n.role == Role::Assign) return ops;
  if (n.role == Role::LabelColon) return Space::None;
  if (p.role == Role::LabelColon) return Space::One;
  if (p.role == Role::DeclColon || n.role == Role::DeclColon) return Space::One;
  if (p.role == Role::Range || n.role == Role::Range) return Space::Keep;
  if (is_wordlike(p.role) && is_wordlike(n.role)) return Space::One;
  if (p.role == Role::Keyword || n.role == Role::Keyword) return Space::One;
  return Space::Keep;
}

}  // namespace

uint32_t spaces_between(const Leaf& before, const Leaf& after, std::string_view text,
                        const project::FormatSettings& settings) {
  switch (rule(before, after, settings)) {
    case Space::One: return 1;
    case Space::Keep: return after.space_before ? 1 : 0;
    case Space::None: break;
  }
  if (!after.space_before) return 0;
  const std::string_view left = text.substr(before.begin, before.end - before.begin);
  const std::string_view right = text.substr(after.begin, after.end - after.begin);
  return may_touch(left, right) ? 0 : 1;
}

}  // namespace rung::format
