#include "lsp/features/formatting_edits.hpp"

#include <toml++/toml.h>

#include "formatter/unified_diff.hpp"

namespace rung::lsp {
namespace {

// Which [format] keys rung.toml itself sets (a rung.toml that does not parse sets none).
struct FormatKeys {
  bool indent_width = false;
  bool use_tabs = false;
};

FormatKeys keys_set(const project::LoadedConfig& config) {
  FormatKeys keys;
  if (config.text.empty()) return keys;
  try {
    const toml::table table = toml::parse(config.text);
    const toml::table* format = table["format"].as_table();
    if (!format) return keys;
    const bool preset = format->contains("preset");
    keys.indent_width = preset || format->contains("indent_width");
    keys.use_tabs = preset || format->contains("use_tabs");
  } catch (const toml::parse_error&) {
    // rung.toml's own diagnostics report it; the defaults apply
  }
  return keys;
}

}  // namespace

project::FormatSettings formatting_settings(const project::LoadedConfig& config, const Json& options) {
  project::FormatSettings settings = config.config.format;
  if (!options.is_object()) return settings;
  const FormatKeys keys = keys_set(config);
  const auto tab_size = options.find("tabSize");
  if (!keys.indent_width && tab_size != options.end() && tab_size->is_number_unsigned()) {
    const uint64_t width = tab_size->get<uint64_t>();
    if (width >= 1 && width <= 16) settings.indent_width = static_cast<uint32_t>(width);
  }
  const auto insert_spaces = options.find("insertSpaces");
  if (!keys.use_tabs && insert_spaces != options.end() && insert_spaces->is_boolean()) {
    settings.use_tabs = !insert_spaces->get<bool>();
  }
  return settings;
}

Json line_edits(const Session& session, const DocumentRef& document, std::string_view after) {
  const std::string_view before = document.document().file_text();
  Json edits = Json::array();
  if (before == after) return edits;
  const std::vector<std::string_view> old_lines = format::split_lines(before);
  const std::vector<std::string_view> new_lines = format::split_lines(after);
  // Byte offset where each old line starts; one more entry for the end of the text.
  std::vector<uint32_t> starts{0};
  for (std::string_view line : old_lines) starts.push_back(starts.back() + static_cast<uint32_t>(line.size()));
  for (const format::LineChange& change : format::diff_lines(old_lines, new_lines)) {
    std::string text;
    for (size_t k = 0; k < change.after_count; ++k) text += new_lines[change.after_begin + k];
    const TextRange range{starts[change.before_begin], starts[change.before_begin + change.before_count]};
    edits.push_back(Json{{"range", session.range_of(document, range)}, {"newText", std::move(text)}});
  }
  return edits;
}

}  // namespace rung::lsp
