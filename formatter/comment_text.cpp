#include "formatter/comment_text.hpp"

namespace rung::format {
namespace {

bool is_blank(char c) {
  return c == ' ' || c == '\t';
}

// Calls `line(text)` for each line of the comment without its blanks at the end, and `end(eol)`
// after each but the last with the line end itself ("\n" or "\r\n").
template <typename Line, typename End>
void for_each_trimmed_line(std::string_view comment, Line&& line, End&& end) {
  size_t start = 0;
  while (true) {
    const size_t newline = comment.find('\n', start);
    const bool last = newline == std::string_view::npos;
    size_t stop = last ? comment.size() : newline;
    const bool crlf = !last && stop > start && comment[stop - 1] == '\r';
    if (crlf) --stop;
    size_t trimmed = stop;
    while (trimmed > start && is_blank(comment[trimmed - 1])) --trimmed;
    line(comment.substr(start, trimmed - start));
    if (last) return;
    end(crlf ? std::string_view("\r\n") : std::string_view("\n"));
    start = newline + 1;
  }
}

}  // namespace

bool is_comment(std::string_view trivia) {
  return trivia.size() >= 2 &&
         ((trivia[0] == '(' && trivia[1] == '*') || (trivia[0] == '/' && (trivia[1] == '/' || trivia[1] == '*')));
}

bool has_line_end_blanks(std::string_view comment) {
  size_t length = 0;
  for_each_trimmed_line(
      comment, [&](std::string_view line) { length += line.size(); },
      [&](std::string_view eol) { length += eol.size(); });
  return length != comment.size();
}

std::string printed_comment(std::string_view comment) {
  std::string out;
  out.reserve(comment.size());
  for_each_trimmed_line(
      comment, [&](std::string_view line) { out += line; }, [&](std::string_view eol) { out += eol; });
  return out;
}

}  // namespace rung::format
