#include "cli/explain_command.hpp"

#include <fmt/format.h>

#include "cli/explain_pages.hpp"
#include "parser/diagnostic_codes.hpp"

namespace rung::cli {

int run_explain_command(const std::string& code, std::FILE* out, std::FILE* err) {
  if (code.empty()) {
    for (const auto& info : all_diagnostic_codes()) {
      fmt::print(out, "{}  {:<8} {:<22} {}\n", info.code, severity_name(info.default_severity), info.title,
                 info.summary);
    }
    return 0;
  }
  const DiagnosticCodeInfo* info = find_diagnostic_code(code);
  if (!info) {
    fmt::print(err, "error: no diagnostic code '{}'; run 'rung explain' for the list\n", code);
    return 2;
  }
  for (const auto& page : explain_pages()) {
    if (page.code == info->code) {
      fmt::print(out, "{}", page.markdown);
      return 0;
    }
  }
  // The registry and the docs are kept in step by a test; this is only reached in a broken build.
  fmt::print(out, "{} ({}): {}\n", info->code, info->title, info->summary);
  return 0;
}

}  // namespace rung::cli
