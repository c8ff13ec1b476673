#include "parser/source/flat_comments.hpp"

#include <algorithm>

namespace rung::source {

size_t read_comments_flat(std::string& text, size_t begin, size_t end) {
  enum class State { Code, Quote, DoubleQuote, Block, Slash, Line } state = State::Code;
  end = std::min(end, text.size());
  size_t blanked = 0;
  for (size_t k = begin; k < end; ++k) {
    const char c = text[k];
    const char next = k + 1 < end ? text[k + 1] : '\0';
    switch (state) {
      case State::Code:
        if (c == '\'') {
          state = State::Quote;
        } else if (c == '"') {
          state = State::DoubleQuote;
        } else if (c == '(' && next == '*') {
          state = State::Block;
          ++k;
        } else if (c == '/' && next == '*') {
          state = State::Slash;
          ++k;
        } else if (c == '/' && next == '/') {
          state = State::Line;
          ++k;
        }
        break;
      case State::Quote:
      case State::DoubleQuote:
        if (c == '$') {
          ++k;
        } else if ((c == '\'' && state == State::Quote) || (c == '"' && state == State::DoubleQuote) || c == '\n') {
          state = State::Code;
        }
        break;
      case State::Block:
        if (c == '*' && next == ')') {
          state = State::Code;
          ++k;
        } else if (c == '(' && next == '*') {
          text[k] = ' ';
          ++blanked;
        }
        break;
      case State::Slash:
        if (c == '*' && next == '/') {
          state = State::Code;
          ++k;
        }
        break;
      case State::Line:
        if (c == '\n' || c == '\r') state = State::Code;
        break;
    }
  }
  return blanked;
}

}  // namespace rung::source
