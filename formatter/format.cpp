#include "formatter/format.hpp"

namespace rung::format {

// Placeholder until the printer lands (issue 4): reports every text as unchanged.
FormatResult format_text(std::string_view text, const project::FormatSettings& settings, const FormatRequest& request) {
  static_cast<void>(settings);
  static_cast<void>(request);
  FormatResult result;
  result.text = std::string(text);
  return result;
}

}  // namespace rung::format
