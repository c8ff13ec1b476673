#include "checker/project/format_settings.hpp"

#include <fmt/format.h>

#include <cctype>
#include <optional>

#include "checker/project/config_sections.hpp"

namespace rung::project {
namespace {

constexpr std::string_view kKnownKeys =
    "preset, keyword_case, elementary_types_follow_keyword_case, indent_width, use_tabs, "
    "spaces_around_operators, space_after_comma, align_types, align_initial_values, align_comments, "
    "max_line_width, max_blank_lines, end_semicolon, else_if_to_elsif";

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

// A string value of a fixed set of words, compared without case ("Upper" is as good as "upper").
std::optional<std::string> word_of(const toml::node& value) {
  if (!value.is_string()) return std::nullopt;
  return lower(*value.value<std::string>());
}

std::optional<KeywordCase> parse_keyword_case(const toml::node& value) {
  auto w = word_of(value);
  if (w == "upper") return KeywordCase::Upper;
  if (w == "lower") return KeywordCase::Lower;
  if (w == "preserve") return KeywordCase::Preserve;
  return std::nullopt;
}

std::optional<EndSemicolon> parse_end_semicolon(const toml::node& value) {
  auto w = word_of(value);
  if (w == "keep") return EndSemicolon::Keep;
  if (w == "always") return EndSemicolon::Always;
  if (w == "never") return EndSemicolon::Never;
  return std::nullopt;
}

class FormatSectionReader {
 public:
  FormatSectionReader(FormatSettings& settings, ConfigReport& report) : settings_(settings), report_(report) {}

  // Returns false when the key is not a [format] key.
  bool read(std::string_view key, const toml::node& value) {
    if (key == "preset") return true;  // applied before every other key
    if (key == "keyword_case") {
      if (auto c = parse_keyword_case(value))
        settings_.keyword_case = *c;
      else
        report_.bad_value(value, "'keyword_case' must be \"upper\", \"lower\" or \"preserve\"",
                          "keyword_case = \"upper\"");
      return true;
    }
    if (key == "end_semicolon") {
      if (auto e = parse_end_semicolon(value))
        settings_.end_semicolon = *e;
      else
        report_.bad_value(value, "'end_semicolon' must be \"keep\", \"always\" or \"never\"",
                          "end_semicolon = \"keep\"");
      return true;
    }
    if (key == "indent_width") return number(key, value, {1, 16, false, 4}, settings_.indent_width);
    if (key == "max_line_width") return number(key, value, {40, 1000, true, 120}, settings_.max_line_width);
    if (key == "max_blank_lines") return number(key, value, {0, 10, false, 1}, settings_.max_blank_lines);
    if (key == "elementary_types_follow_keyword_case")
      return flag(key, value, settings_.elementary_types_follow_keyword_case);
    if (key == "use_tabs") return flag(key, value, settings_.use_tabs);
    if (key == "spaces_around_operators") return flag(key, value, settings_.spaces_around_operators);
    if (key == "space_after_comma") return flag(key, value, settings_.space_after_comma);
    if (key == "align_types") return flag(key, value, settings_.align_types);
    if (key == "align_initial_values") return flag(key, value, settings_.align_initial_values);
    if (key == "align_comments") return flag(key, value, settings_.align_comments);
    if (key == "else_if_to_elsif") return flag(key, value, settings_.else_if_to_elsif);
    return false;
  }

 private:
  // Asks the node for its own kind: value<bool>() would also convert numbers.
  bool flag(std::string_view key, const toml::node& value, bool& out) {
    if (value.is_boolean())
      out = *value.value<bool>();
    else
      report_.bad_value(value, fmt::format("'{}' must be true or false", key), fmt::format("{} = true", key));
    return true;
  }

  // An integer key's valid values: `min` to `max`, and 0 ("off") when `zero_allowed`.
  struct Range {
    int64_t min;
    int64_t max;
    bool zero_allowed;
    int64_t example;  // shown in the help line
  };

  bool number(std::string_view key, const toml::node& value, Range range, uint32_t& out) {
    std::optional<int64_t> n;
    if (value.is_integer()) n = *value.value<int64_t>();
    if (n && ((*n >= range.min && *n <= range.max) || (range.zero_allowed && *n == 0))) {
      out = static_cast<uint32_t>(*n);
      return true;
    }
    std::string message = range.zero_allowed
                              ? fmt::format("'{}' must be 0 (off) or a number from {} to {}", key, range.min, range.max)
                              : fmt::format("'{}' must be a number from {} to {}", key, range.min, range.max);
    report_.bad_value(value, std::move(message), fmt::format("{} = {}", key, range.example));
    return true;
  }

  FormatSettings& settings_;
  ConfigReport& report_;
};

}  // namespace

bool apply_format_preset(std::string_view preset, FormatSettings& settings) {
  std::string name = lower(preset);
  FormatSettings base;  // the struct's defaults are the CODESYS editor's habits
  if (name == "codesys" || name == "twincat") {
    // TwinCAT 3's ST editor indents with tabs of width 4 and shows keywords in upper case, like
    // CODESYS (it is built on it): the two presets lay code out the same way.
  } else if (name == "rung") {
    base.use_tabs = false;
    base.indent_width = 4;
    base.max_line_width = 100;
  } else {
    return false;
  }
  base.preset = name;
  settings = base;
  return true;
}

void read_format_section(const toml::node& node, FormatSettings& settings, ConfigReport& report) {
  const toml::table* table = node.as_table();
  if (!table) return report.bad_value(node, "[format] must be a table", "[format]\npreset = \"codesys\"");
  // The preset gives the defaults wherever it stands in the table; the other keys override them.
  if (const toml::node* preset = table->get("preset")) {
    auto name = preset->value<std::string>();
    if (!preset->is_string() || !apply_format_preset(*name, settings))
      report.bad_value(*preset, "'preset' must be \"codesys\", \"twincat\" or \"rung\"", "preset = \"codesys\"");
  }
  FormatSectionReader reader(settings, report);
  for (auto&& [key, value] : *table) {
    if (!reader.read(key.str(), value)) report.unknown_key(key, "[format]", kKnownKeys);
  }
}

}  // namespace rung::project
