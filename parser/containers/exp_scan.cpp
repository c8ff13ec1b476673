#include "parser/containers/exp_scan.hpp"

#include <cctype>

namespace rung::containers::exp {
namespace {

bool is_word_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}
bool is_blank(char c) {
  return c == ' ' || c == '\t';
}

}  // namespace

Line line_at(std::string_view text, uint32_t begin) {
  const auto size = static_cast<uint32_t>(text.size());
  uint32_t end = begin;
  while (end < size && text[end] != '\n' && text[end] != '\r') ++end;
  uint32_t next = end;
  if (next < size && text[next] == '\r') ++next;
  if (next < size && text[next] == '\n' && (next == end || text[end] == '\r')) ++next;
  return {begin, end, next};
}

std::string first_word(std::string_view line) {
  size_t i = 0;
  while (i < line.size() && is_blank(line[i])) ++i;
  std::string word;
  while (i < line.size() && is_word_char(line[i])) {
    word.push_back(static_cast<char>(std::toupper(static_cast<unsigned char>(line[i]))));
    ++i;
  }
  return word;
}

std::string name_after(std::string_view text, uint32_t from) {
  size_t i = from;
  while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
  const size_t begin = i;
  while (i < text.size() && is_word_char(text[i])) ++i;
  return std::string(text.substr(begin, i - begin));
}

std::optional<Marker> parse_marker(std::string_view line) {
  size_t i = 0;
  while (i < line.size() && is_blank(line[i])) ++i;
  if (line.substr(i, 2) != "(*") return std::nullopt;
  i += 2;
  while (i < line.size() && is_blank(line[i])) ++i;
  if (i >= line.size() || line[i] != '@') return std::nullopt;
  ++i;
  Marker marker;
  while (i < line.size() && is_word_char(line[i])) {
    marker.key.push_back(static_cast<char>(std::toupper(static_cast<unsigned char>(line[i]))));
    ++i;
  }
  if (marker.key.empty()) return std::nullopt;
  const size_t open = line.find('\'', i);
  if (open == std::string_view::npos) return marker;  // e.g. "(* @CONNECTIONS := Name" spanning lines
  const size_t close = line.find('\'', open + 1);
  if (close == std::string_view::npos) return marker;
  marker.value = std::string(line.substr(open + 1, close - open - 1));
  return marker;
}

std::string unescape_path(std::string_view value) {
  std::string out;
  out.reserve(value.size());
  for (size_t i = 0; i < value.size(); ++i) {
    if (value[i] == '\\' && i + 1 < value.size() && value[i + 1] == '/') continue;
    out.push_back(value[i]);
  }
  return out;
}

void CommentTracker::feed(std::string_view line) {
  size_t i = 0;
  const size_t n = line.size();
  while (i < n) {
    const char c = line[i];
    const char next = i + 1 < n ? line[i + 1] : '\0';
    if (depth_ > 0) {
      if (c == '*' && next == ')') {
        --depth_;
        i += 2;
      } else if (nested_ && c == '(' && next == '*') {
        ++depth_;
        i += 2;
      } else {
        ++i;
      }
      continue;
    }
    if (c == '(' && next == '*') {
      depth_ = 1;
      i += 2;
    } else if (c == '/' && next == '/') {
      return;  // the rest of the line is a comment
    } else if (c == '\'' || c == '"') {
      // IEC strings escape with '$' ("$'" is a quote); a string never spans lines.
      ++i;
      while (i < n && line[i] != c) i += line[i] == '$' ? 2 : 1;
      ++i;
    } else {
      ++i;
    }
  }
}

}  // namespace rung::containers::exp
