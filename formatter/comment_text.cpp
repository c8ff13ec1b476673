#include "formatter/comment_text.hpp"

namespace rung::format {

bool is_comment(std::string_view trivia) {
  return trivia.size() >= 2 &&
         ((trivia[0] == '(' && trivia[1] == '*') || (trivia[0] == '/' && (trivia[1] == '/' || trivia[1] == '*')));
}

void append_printed_comment(std::string& out, std::string_view comment) {
  size_t start = 0;
  while (true) {
    const size_t newline = comment.find('\n', start);
    const bool last = newline == std::string_view::npos;
    // The line's text ends before its line end, "\n" or "\r\n" (a lone '\r' ends no line).
    size_t stop = last ? comment.size() : newline;
    if (!last && stop > start && comment[stop - 1] == '\r') --stop;
    size_t trimmed = stop;
    while (trimmed > start && (comment[trimmed - 1] == ' ' || comment[trimmed - 1] == '\t')) --trimmed;
    out.append(comment.substr(start, trimmed - start));
    if (last) return;
    out.append(comment.substr(stop, newline + 1 - stop));
    start = newline + 1;
  }
}

std::string printed_comment(std::string_view comment) {
  std::string out;
  out.reserve(comment.size());
  append_printed_comment(out, comment);
  return out;
}

}  // namespace rung::format
