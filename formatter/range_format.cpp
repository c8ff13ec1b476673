#include "formatter/format.hpp"

namespace rung::format {

// Placeholder until range formatting lands (issue 4): formats the whole text.
FormatResult format_range(std::string_view text, TextRange range, const project::FormatSettings& settings,
                          const FormatRequest& request) {
  static_cast<void>(range);
  return format_text(text, settings, request);
}

}  // namespace rung::format
