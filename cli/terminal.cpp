#include "cli/terminal.hpp"

#include <unistd.h>

#include <cstdlib>

namespace rung::cli {

bool parse_color_choice(std::string_view text, ColorChoice* out) {
  if (text == "auto")
    *out = ColorChoice::Auto;
  else if (text == "always")
    *out = ColorChoice::Always;
  else if (text == "never")
    *out = ColorChoice::Never;
  else
    return false;
  return true;
}

bool is_terminal(std::FILE* stream) {
  return isatty(fileno(stream)) == 1;
}

bool use_color(ColorChoice choice, std::FILE* stream) {
  if (choice == ColorChoice::Always) return true;
  if (choice == ColorChoice::Never) return false;
  const char* no_color = std::getenv("NO_COLOR");
  if (no_color && *no_color) return false;
  const char* term = std::getenv("TERM");
  if (term && std::string_view(term) == "dumb") return false;
  return is_terminal(stream);
}

Progress::Progress(std::string_view verb, size_t total)
    : verb_(verb), total_(total), enabled_(total >= 50 && is_terminal(stderr)) {}

void Progress::step(size_t done) {
  if (!enabled_) return;
  // Redraw every 1/100th of the work, not on every file.
  size_t stride = total_ / 100 + 1;
  if (done % stride != 0 && done != total_) return;
  std::fprintf(stderr, "\r%s %zu/%zu files", verb_.c_str(), done, total_);
  std::fflush(stderr);
  shown_ = true;
}

void Progress::finish() {
  if (shown_) {
    std::fprintf(stderr, "\r\x1b[2K");
    std::fflush(stderr);
  }
}

}  // namespace rung::cli
