// What the output stream is: colours only on a terminal (and never with NO_COLOR set).
#pragma once

#include <cstdio>
#include <string>
#include <string_view>

namespace rung::cli {

enum class ColorChoice { Auto, Always, Never };

bool parse_color_choice(std::string_view text, ColorChoice* out);
bool use_color(ColorChoice choice, std::FILE* stream);
bool is_terminal(std::FILE* stream);

// ANSI styles; each returns "" when colours are off.
struct Style {
  bool enabled = false;
  std::string_view bold() const { return enabled ? "\x1b[1m" : ""; }
  std::string_view red() const { return enabled ? "\x1b[1;31m" : ""; }
  std::string_view yellow() const { return enabled ? "\x1b[1;33m" : ""; }
  std::string_view blue() const { return enabled ? "\x1b[1;34m" : ""; }
  std::string_view cyan() const { return enabled ? "\x1b[1;36m" : ""; }
  std::string_view green() const { return enabled ? "\x1b[1;32m" : ""; }
  std::string_view reset() const { return enabled ? "\x1b[0m" : ""; }
};

// "Parsing 120/2000 files" on stderr, overwritten in place; silent when stderr is not a terminal.
class Progress {
 public:
  Progress(std::string_view verb, size_t total);
  void step(size_t done);
  void finish();

 private:
  std::string verb_;
  size_t total_;
  bool enabled_;
  bool shown_ = false;
};

}  // namespace rung::cli
