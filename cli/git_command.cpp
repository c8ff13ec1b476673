#include "cli/git_command.hpp"

#include <fmt/format.h>

#include <cstdlib>
#include <filesystem>
#include <string_view>
#include <system_error>

#include "vcs/git_setup.hpp"

namespace rung::cli {

namespace fs = std::filesystem;

std::string rung_command_for_git() {
  std::error_code ec;
  const fs::path self = fs::canonical("/proc/self/exe", ec);
  if (ec) return "rung";
  const char* path = std::getenv("PATH");
  std::string_view dirs = path != nullptr ? path : "";
  while (!dirs.empty()) {
    const size_t colon = dirs.find(':');
    const std::string_view dir = dirs.substr(0, colon);
    if (!dir.empty()) {
      const fs::path candidate = fs::path(std::string(dir)) / "rung";
      if (fs::exists(candidate, ec)) {
        // The first rung on PATH is the one git would start.
        return fs::equivalent(candidate, self, ec) ? "rung" : self.string();
      }
    }
    if (colon == std::string_view::npos) break;
    dirs.remove_prefix(colon + 1);
  }
  return self.string();
}

int run_git_setup_command(bool global, std::FILE* out, std::FILE* err) {
  const vcs::SetupResult result = vcs::setup_git(".", global, rung_command_for_git());
  if (!result.error.empty()) {
    fmt::print(err, "rung git setup: {}\n", result.error);
    return 2;
  }
  if (result.added_lines.empty()) {
    fmt::print(out, "{}: already set up\n", result.attributes_file);
  } else {
    fmt::print(out, "{}: added\n", result.attributes_file);
    for (const std::string& line : result.added_lines) fmt::print(out, "  {}\n", line);
  }
  fmt::print(out, "git config{}:\n", global ? " --global" : "");
  for (const auto& [name, value] : result.config) fmt::print(out, "  {} = {}\n", name, value);
  return 0;
}

}  // namespace rung::cli
