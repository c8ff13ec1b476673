// `rung sevre`: a word where the command belongs that names no command is an error (exit 2) with
// the closest command as a suggestion, as cargo does, so that a CI script calling a command that
// does not exist fails instead of printing the overview.
#pragma once

#include <cstdio>
#include <optional>
#include <string>
#include <string_view>

namespace CLI {
class App;
}  // namespace CLI

namespace rung::cli {

// "no command 'chekc'; did you mean 'check'?" for a word that names none of `app`'s subcommands
// (or their aliases), with the suggestion only when one is close.
std::string unknown_command_message(const CLI::App& app, std::string_view word);

// The first argument that is no option (the command) must name one of `app`'s subcommands. When
// it does not, says so on `err` and returns the exit code 2; nullopt when the command line may be
// parsed. `rung` without a command and `rung --version` are left to the parser.
std::optional<int> reject_unknown_command(const CLI::App& app, int argc, const char* const* argv, std::FILE* err);

}  // namespace rung::cli
