#include "cli/diagnostic_printer.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace rung::cli {
namespace {

std::string_view severity_color(Severity s, const Style& style) {
  switch (s) {
    case Severity::Error: return style.red();
    case Severity::Warning: return style.yellow();
    default: return style.cyan();
  }
}

// The source line holding `pos`, and a marker line under [pos, end) that keeps tabs aligned.
void append_excerpt(std::string& out, const Document& doc, const FilePosition& pos, uint32_t end_offset,
                    std::string_view marker_message, const Style& style, std::string_view color) {
  const auto& lines = doc.file_lines();
  uint32_t line0 = pos.line - 1;
  if (line0 >= lines.line_count()) return;
  std::string_view text = doc.file_text();
  uint32_t ls = lines.line_start(line0);
  uint32_t le = lines.line_end(line0);
  std::string number = std::to_string(pos.line);
  std::string gutter(number.size(), ' ');

  std::string shown;
  std::string marks;
  uint32_t mark_begin = pos.offset;
  uint32_t mark_end = std::min(std::max(end_offset, pos.offset), le);
  for (uint32_t i = ls; i < le; ++i) {
    unsigned char c = static_cast<unsigned char>(text[i]);
    bool lead = (c & 0xC0) != 0x80;
    shown += static_cast<char>(c);
    if (!lead) continue;
    char pad = c == '\t' ? '\t' : ' ';
    if (i < mark_begin)
      marks += pad;
    else if (i < mark_end)
      marks += '^';
  }
  if (mark_end <= mark_begin) marks += '^';
  fmt::format_to(std::back_inserter(out), "{} {}|{}\n", gutter, style.blue(), style.reset());
  fmt::format_to(std::back_inserter(out), "{}{} |{} {}\n", style.blue(), number, style.reset(), shown);
  fmt::format_to(std::back_inserter(out), "{} {}|{} {}{}{}", gutter, style.blue(), style.reset(), color, marks,
                 style.reset());
  if (!marker_message.empty()) fmt::format_to(std::back_inserter(out), " {}{}{}", color, marker_message, style.reset());
  out += '\n';
}

}  // namespace

std::string render_human(const Document& doc, const Diagnostic& d, const Style& style) {
  std::string out;
  FilePosition pos = doc.position_of_file_offset(d.range.begin);
  std::string_view color = severity_color(d.severity, style);
  fmt::format_to(std::back_inserter(out), "{}{}:{}:{}:{} {}{}[{}]{}: {}{}{}\n", style.bold(), doc.path(), pos.line,
                 pos.column, style.reset(), color, severity_name(d.severity), d.code, style.reset(), style.bold(),
                 d.message, style.reset());
  append_excerpt(out, doc, pos, d.range.end, {}, style, color);
  for (const auto& label : d.labels) {
    FilePosition lp = doc.position_of_file_offset(label.range.begin);
    fmt::format_to(std::back_inserter(out), "  {}note{}: {}:{}:{}\n", style.cyan(), style.reset(), doc.path(), lp.line,
                   lp.column);
    append_excerpt(out, doc, lp, label.range.end, label.message, style, style.cyan());
  }
  if (!d.help.empty())
    fmt::format_to(std::back_inserter(out), "  {}= help{}: {}\n", style.green(), style.reset(), d.help);
  return out;
}

nlohmann::json render_json(const Document& doc, const Diagnostic& d) {
  auto position = [&](uint32_t offset) {
    FilePosition p = doc.position_of_file_offset(offset);
    return nlohmann::json{{"line", p.line}, {"column", p.column}, {"offset", p.offset}};
  };
  nlohmann::json j{{"file", doc.path()},
                   {"code", d.code},
                   {"severity", std::string(severity_name(d.severity))},
                   {"message", d.message},
                   {"start", position(d.range.begin)},
                   {"end", position(d.range.end)}};
  if (!d.help.empty()) j["help"] = d.help;
  if (!d.labels.empty()) {
    nlohmann::json labels = nlohmann::json::array();
    for (const auto& label : d.labels) {
      labels.push_back(
          {{"message", label.message}, {"start", position(label.range.begin)}, {"end", position(label.range.end)}});
    }
    j["labels"] = std::move(labels);
  }
  return j;
}

void Tally::add(const Diagnostic& d) {
  if (d.severity == Severity::Error)
    ++errors;
  else if (d.severity == Severity::Warning)
    ++warnings;
}

std::string Tally::summary() const {
  auto plural = [](size_t n, std::string_view word) { return fmt::format("{} {}{}", n, word, n == 1 ? "" : "s"); };
  return fmt::format("{}, {} in {}", plural(errors, "error"), plural(warnings, "warning"), plural(files, "file"));
}

}  // namespace rung::cli
