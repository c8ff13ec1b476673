#include "cli/command_name.hpp"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <vector>

#include "checker/symbols/names.hpp"

namespace rung::cli {
namespace {

std::vector<std::string_view> command_names(const CLI::App& app) {
  std::vector<std::string_view> names;
  for (const CLI::App* command : app.get_subcommands([](const CLI::App*) { return true; })) {
    names.emplace_back(command->get_name());
    for (const std::string& alias : command->get_aliases()) names.emplace_back(alias);
  }
  return names;
}

}  // namespace

std::string unknown_command_message(const CLI::App& app, std::string_view word) {
  const std::vector<std::string_view> names = command_names(app);
  const std::string_view suggestion = check::closest_name(word, names);
  if (suggestion.empty()) return fmt::format("no command '{}'; run 'rung help' for the list of commands", word);
  return fmt::format("no command '{}'; did you mean '{}'?", word, suggestion);
}

std::optional<int> reject_unknown_command(const CLI::App& app, int argc, const char* const* argv, std::FILE* err) {
  for (int i = 1; i < argc; ++i) {
    const std::string_view word = argv[i];
    if (word.starts_with("-")) continue;  // rung's own options are flags (--help, --version)
    for (std::string_view name : command_names(app)) {
      if (name == word) return std::nullopt;
    }
    fmt::print(err, "error: {}\n", unknown_command_message(app, word));
    return 2;
  }
  return std::nullopt;
}

}  // namespace rung::cli
