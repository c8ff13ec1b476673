#include "formatter/printer.hpp"

#include <algorithm>

#include "formatter/comment_text.hpp"
#include "formatter/spacing.hpp"

namespace rung::format {

uint32_t display_width(std::string_view token) {
  uint32_t width = 0;
  uint32_t blanks = 0;  // at the end so far: a comment is printed without them (comment_text.hpp)
  for (char c : token) {
    if (c == '\n' || c == '\r') break;
    // Count code points: every byte but UTF-8 continuation bytes.
    if ((static_cast<unsigned char>(c) & 0xC0) != 0x80) ++width;
    blanks = c == ' ' || c == '\t' ? blanks + 1 : 0;
  }
  return width - blanks;
}

namespace {

std::string_view token_text(std::string_view text, const Leaf& leaf) {
  return text.substr(leaf.begin, leaf.end - leaf.begin);
}

uint32_t tab_width(const project::FormatSettings& settings) {
  return settings.indent_width ? settings.indent_width : 4;
}

// The file's line end: the first one it uses (CRLF stays CRLF).
std::string_view line_end_of(std::string_view text) {
  const size_t lf = text.find('\n');
  if (lf != std::string_view::npos) return lf > 0 && text[lf - 1] == '\r' ? "\r\n" : "\n";
  return text.find('\r') != std::string_view::npos ? "\r" : "\n";
}

void append_indent(std::string& out, int32_t level, const project::FormatSettings& settings) {
  if (level <= 0) return;
  if (settings.use_tabs) {
    out.append(static_cast<size_t>(level), '\t');
  } else {
    out.append(static_cast<size_t>(level) * settings.indent_width, ' ');
  }
}

}  // namespace

uint32_t span_width(const WalkResult& walk, const Layout& layout, std::string_view text, uint32_t a, uint32_t b) {
  uint32_t width = display_width(token_text(text, walk.leaves[a]));
  for (uint32_t m = a + 1; m <= b; ++m) width += layout.spaces[m] + display_width(token_text(text, walk.leaves[m]));
  return width;
}

Layout lay_out(const WalkResult& walk, std::string_view text, const project::FormatSettings& settings) {
  const std::vector<Leaf>& leaves = walk.leaves;
  const uint32_t count = static_cast<uint32_t>(leaves.size());
  Layout layout;
  layout.spaces.assign(count, 0);
  layout.line_of.assign(count, 0);
  for (uint32_t i = 0; i < count; ++i) {
    if (i == 0 || leaves[i].newlines > 0) {
      if (i > 0) layout.lines.back().last = i - 1;
      Line line;
      line.first = i;
      layout.lines.push_back(line);
    } else {
      layout.spaces[i] = spaces_between(leaves[i - 1], leaves[i], text, settings);
    }
    layout.line_of[i] = static_cast<uint32_t>(layout.lines.size() - 1);
  }
  if (!layout.lines.empty()) layout.lines.back().last = count - 1;

  // A line's level is its first token's; a line of comments only takes the level of the code
  // that follows (the body's level before a closing keyword).
  int32_t next_comment_level = 0;
  std::vector<int32_t> following(count, 0);
  for (uint32_t i = count; i-- > 0;) {
    if (!leaves[i].trivia()) next_comment_level = leaves[i].comment_level;
    following[i] = next_comment_level;
  }
  for (Line& line : layout.lines) {
    line.level = following[line.first];
    for (uint32_t i = line.first; i <= line.last; ++i) {
      if (!leaves[i].trivia()) {
        line.level = leaves[i].level;
        break;
      }
    }
  }

  align_rows(walk, text, settings, layout);

  const uint32_t indent = settings.use_tabs ? tab_width(settings) : settings.indent_width;
  for (Line& line : layout.lines) {
    uint32_t width = static_cast<uint32_t>(std::max(line.level, 0)) * indent;
    uint32_t code_width = 0;
    for (uint32_t i = line.first; i <= line.last; ++i) {
      if (i > line.first) width += layout.spaces[i];
      width += display_width(token_text(text, leaves[i]));
      if (leaves[i].multiline) break;
      if (!leaves[i].trivia()) code_width = width;
    }
    line.width = width;
    line.code_width = code_width;
  }
  return layout;
}

std::string print(const WalkResult& walk, const Layout& layout, std::string_view text,
                  const project::FormatSettings& settings) {
  std::string out;
  out.reserve(text.size() + text.size() / 8 + 16);
  if (text.substr(0, 3) == "\xEF\xBB\xBF") out += "\xEF\xBB\xBF";
  const std::vector<Leaf>& leaves = walk.leaves;
  if (leaves.empty()) return out;
  const std::string_view eol = line_end_of(text);
  const uint32_t most_breaks = settings.max_blank_lines + 1;
  bool after_opener = false;  // the previous line ends with the token that opens a block
  for (uint32_t i = 0; i < leaves.size(); ++i) {
    const Leaf& leaf = leaves[i];
    const Line& line = layout.lines[layout.line_of[i]];
    if (line.first == i) {
      if (i > 0) {
        uint32_t breaks = std::min(leaf.newlines, most_breaks);
        if (after_opener) breaks = 1;  // no blank line at the start of a block
        for (uint32_t b = 0; b < breaks; ++b) out += eol;
      }
      after_opener = false;
      append_indent(out, line.level, settings);
    } else {
      out.append(layout.spaces[i], ' ');
    }
    if (!leaf.trivia()) after_opener = leaf.opens_block;
    const std::string_view token = token_text(text, leaf);
    if (leaf.trivia() && is_comment(token)) {
      append_printed_comment(out, token);
    } else {
      append_in_case(out, token, leaf.case_class, settings);
    }
  }
  out += eol;
  return out;
}

}  // namespace rung::format
