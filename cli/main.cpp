// The `rung` command: each subcommand is a thin layer over the libraries (architecture rule 1).
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <string>

#include "cli/check_command.hpp"
#include "cli/command_name.hpp"
#include "cli/diff_command.hpp"
#include "cli/explain_command.hpp"
#include "cli/fmt_command.hpp"
#include "cli/git_command.hpp"
#include "cli/init_command.hpp"
#include "cli/lint_command.hpp"
#include "cli/lsp_command.hpp"
#include "cli/merge_file_command.hpp"
#include "cli/parse_command.hpp"
#include "cli/run_command.hpp"
#include "cli/textconv_command.hpp"

namespace {

constexpr const char* kDescription =
    "rung: a text-first toolchain for IEC 61131-3 PLC code (ST, IL, SFC; TwinCAT and CODESYS files)";

int run(int argc, char** argv);

}  // namespace

// Exceptions never escape: a bug in rung must end with a message, not an abort.
int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "rung: internal error: %s\n(please report it with the input that caused it)\n", e.what());
  } catch (...) {
    std::fprintf(stderr, "rung: internal error\n");
  }
  return 2;
}

namespace {

int run(int argc, char** argv) {
  CLI::App app{kDescription, "rung"};
  app.set_version_flag("-V,--version", std::string("rung ") + RUNG_VERSION);
  app.require_subcommand(0, 1);
  app.footer("Run 'rung <command> --help' for the options of a command.");

  std::string color_text = "auto";

  rung::cli::ParseCommandOptions parse_options;
  std::string format_text = "human";
  CLI::App* parse = app.add_subcommand("parse", "Parse files and folders; print syntax errors (and trees)");
  parse->add_option("paths", parse_options.paths, "Files or folders (folders are searched recursively)")->required();
  parse->add_flag("--tree", parse_options.tree, "Print the syntax tree of each file");
  parse->add_option("--format", format_text, "Output format")->check(CLI::IsMember({"human", "json"}));
  parse->add_option("--color", color_text, "When to use colours")->check(CLI::IsMember({"auto", "always", "never"}));
  parse->add_flag("-q,--quiet", parse_options.quiet, "Do not print the closing summary line");
  parse->add_option("-j,--jobs", parse_options.threads, "Files parsed in parallel (default: one per core)");

  rung::cli::CheckCommandOptions check_options;
  std::string check_format = "human";
  std::string check_profile;
  CLI::App* check =
      app.add_subcommand("check", "Check a project: syntax, names, types, calls and declarations across all its files");
  check->add_option("paths", check_options.paths,
                    "Files or folders to report on (default: the current folder); the whole project is read");
  check->add_option("--format", check_format, "Output format (sarif: SARIF 2.1.0 for code scanning)")
      ->check(CLI::IsMember({"human", "json", "sarif"}));
  check->add_option("--profile", check_profile, "Semantics profile, overrides rung.toml")
      ->check(CLI::IsMember({"codesys", "iec", "twincat", "openpcs"}));
  check->add_option("--color", color_text, "When to use colours")->check(CLI::IsMember({"auto", "always", "never"}));
  check->add_flag("-q,--quiet", check_options.quiet, "Do not print the closing summary line");
  check->add_option("-j,--jobs", check_options.threads, "Threads (default: one per core)");

  rung::cli::FmtCommandOptions fmt_options;
  CLI::App* fmt_command = app.add_subcommand(
      "fmt", "Format source files in place with the project's [format] settings (or check, or show a diff)");
  fmt_command->add_option("paths", fmt_options.paths, "Files or folders (default: the project of the current folder)");
  fmt_command->add_flag("--check", fmt_options.check,
                        "Write nothing; list the files that would change (exit 1 if any)");
  fmt_command->add_flag("--diff", fmt_options.diff,
                        "Write nothing; print the changes as unified diffs (exit 1 if any)");
  fmt_command->add_flag("--stdin", fmt_options.stdin_mode, "Format standard input to standard output");
  fmt_command->add_option("--stdin-filename", fmt_options.stdin_filename,
                          "With --stdin: the file's name (its kind and its project's rung.toml)");
  fmt_command->add_option("--color", color_text, "When to use colours")
      ->check(CLI::IsMember({"auto", "always", "never"}));
  fmt_command->add_flag("-q,--quiet", fmt_options.quiet, "Do not print the closing summary line");
  fmt_command->add_option("-j,--jobs", fmt_options.threads, "Threads (default: one per core)");

  rung::cli::LintCommandOptions lint_options;
  std::string lint_format = "human";
  std::string lint_profile;
  std::string lint_baseline;
  CLI::App* lint = app.add_subcommand(
      "lint", "Lint a project: naming, structure and likely mistakes in legal code (rung.toml [lint])");
  lint->add_option("paths", lint_options.paths,
                   "Files or folders to report on (default: the current folder); the whole project is read");
  lint->add_flag("--fix", lint_options.fix, "Apply the fixes of the reported findings to the files");
  lint->add_option("--format", lint_format, "Output format (sarif: SARIF 2.1.0 for code scanning)")
      ->check(CLI::IsMember({"human", "json", "sarif"}));
  lint->add_option("--profile", lint_profile, "Semantics profile, overrides rung.toml")
      ->check(CLI::IsMember({"codesys", "iec", "twincat", "openpcs"}));
  CLI::Option* write_baseline =
      lint->add_option("--write-baseline", lint_baseline,
                       "Record the current findings in the baseline file (default: rung.toml [lint] baseline, "
                       "else lint-baseline.json); use --write-baseline=FILE for another file")
          ->expected(0, 1);
  lint->add_flag("--no-baseline", lint_options.no_baseline, "Also report the findings the baseline lists");
  lint->add_flag("--list-rules", lint_options.list_rules, "List the rules and how rung.toml sets them");
  lint->add_option("--color", color_text, "When to use colours")->check(CLI::IsMember({"auto", "always", "never"}));
  lint->add_flag("-q,--quiet", lint_options.quiet, "Do not print the closing summary lines");
  lint->add_option("-j,--jobs", lint_options.threads, "Threads (default: one per core)");

  rung::cli::RunCommandOptions run_options;
  std::string run_format = "human";
  std::string run_profile;
  CLI::App* run_command = rung::cli::add_run_subcommand(app, run_options, run_format, run_profile);
  run_command->add_option("--color", color_text, "When to use colours")->check(CLI::IsMember({"auto", "always", "never"}));

  std::string explain_code;
  CLI::App* explain =
      app.add_subcommand("explain", "Explain a diagnostic code (e.g. rung explain S003), or list all codes");
  explain->add_option("code", explain_code, "The code, as printed in brackets: error[S003]");

  std::string init_dir;
  bool init_force = false;
  CLI::App* init = app.add_subcommand("init", "Write a commented rung.toml for a project folder");
  init->add_option("dir", init_dir, "The project folder (default: the current folder)");
  init->add_flag("--force", init_force, "Overwrite an existing rung.toml");

  rung::cli::LspCommandOptions lsp_options;
  uint16_t lsp_port = 0;
  CLI::App* lsp = app.add_subcommand(
      "lsp", "Run the language server (LSP 3.17) for editors: stdio by default, or TCP with --port");
  CLI::Option* port_option = lsp->add_option("--port", lsp_port, "Listen on 127.0.0.1:PORT instead of stdio (0: any free port)");
  bool lsp_stdio = false;
  lsp->add_flag("--stdio", lsp_stdio, "Use standard input/output (the default; accepted for clients that pass it)");
  lsp->add_option("-j,--jobs", lsp_options.threads, "Threads for indexing (default: one per core)");

  std::string textconv_path;
  CLI::App* textconv = app.add_subcommand(
      "textconv", "Print the ST text of a PLC source file (vendor containers without their XML), for git");
  textconv->add_option("file", textconv_path, "The file")->required();

  rung::cli::DiffCommandOptions diff_options;
  CLI::App* diff = app.add_subcommand(
      "diff", "Show what changed in the PLC code of a git repository, by meaning (objects, declarations, bodies)");
  diff->add_option("args", diff_options.arguments, "[REV [REV]] [-- PATH...], as git diff takes them");
  diff->add_flag("--cached,--staged", diff_options.cached, "Compare the index with HEAD (or with REV)");
  diff->add_option("--format", diff_options.format, "Output format")->check(CLI::IsMember({"human", "json"}));
  diff->add_flag("--stat", diff_options.stat, "One line per changed object");
  diff->add_flag("--exit-code", diff_options.exit_code, "Exit with 1 when something changed, 0 otherwise");
  diff->add_flag("--comments", diff_options.comments, "Report comment-only changes too");
  diff->add_option("--color", color_text, "When to use colours")->check(CLI::IsMember({"auto", "always", "never"}));

  bool git_global = false;
  CLI::App* git = app.add_subcommand("git", "Set git up for PLC sources (textconv and merge drivers)");
  git->require_subcommand(1);
  CLI::App* git_setup =
      git->add_subcommand("setup", "Write the .gitattributes lines and git config for rung's diff and merge drivers");
  git_setup->add_flag("--global", git_global, "For every repository of the user (~/.gitconfig)");

  rung::cli::MergeFileOptions merge_file_options;
  CLI::App* merge_file = app.add_subcommand(
      "merge-file", "Three-way merge of a PLC source on its syntax tree; git's merge driver (%O %A %B %P)");
  merge_file->add_option("base", merge_file_options.base, "The common ancestor (%O)")->required();
  merge_file->add_option("ours", merge_file_options.ours, "Our version, replaced by the result (%A)")->required();
  merge_file->add_option("theirs", merge_file_options.theirs, "Their version (%B)")->required();
  merge_file->add_option("path", merge_file_options.path, "The file's path in the repository (%P)");

  std::string help_topic;
  CLI::App* help = app.add_subcommand("help", "Show help for rung or for one command");
  help->add_option("command", help_topic, "The command to explain");

  argc = rung::cli::take_arguments_after_dashes(argc, argv, "diff", &diff_options.paths);
  if (const auto refused = rung::cli::reject_unknown_command(app, argc, argv, stderr)) return *refused;
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return 2;
  }

  if (*help || app.get_subcommands().empty()) {
    if (!help_topic.empty()) {
      CLI::App* sub = nullptr;
      try {
        sub = app.get_subcommand(help_topic);
      } catch (const CLI::OptionNotFound&) {
        std::fprintf(stderr, "error: %s\n", rung::cli::unknown_command_message(app, help_topic).c_str());
        return 2;
      }
      std::fputs(sub->get_formatter()->make_help(sub, "rung " + sub->get_name(), CLI::AppFormatMode::Normal).c_str(),
                 stdout);
      return 0;
    }
    // app.help() would describe the selected subcommand ("help" itself); show the overview.
    std::fputs(app.get_formatter()->make_help(&app, "rung", CLI::AppFormatMode::Normal).c_str(), stdout);
    return app.get_subcommands().empty() && argc > 1 ? 2 : 0;
  }

  rung::cli::ColorChoice color = rung::cli::ColorChoice::Auto;
  rung::cli::parse_color_choice(color_text, &color);

  if (*lsp) {
    if (port_option->count() > 0) lsp_options.port = lsp_port;
    return rung::cli::run_lsp_command(lsp_options);
  }
  if (*textconv) return rung::cli::run_textconv_command(textconv_path, stdout, stderr);
  if (*diff) {
    diff_options.color = color;
    return rung::cli::run_diff_command(diff_options, stdout, stderr);
  }
  if (*git) return rung::cli::run_git_setup_command(git_global, stdout, stderr);
  if (*merge_file) return rung::cli::run_merge_file_command(merge_file_options, stdout, stderr);
  if (*init) return rung::cli::run_init_command(init_dir, init_force, stdout, stderr);
  if (*explain) return rung::cli::run_explain_command(explain_code, stdout, stderr);
  if (*fmt_command) {
    fmt_options.color = color;
    return rung::cli::run_fmt_command(fmt_options, stdin, stdout, stderr);
  }

  if (*lint) {
    lint_options.color = color;
    lint_options.format = lint_format == "json"    ? rung::cli::CheckFormat::Json
                          : lint_format == "sarif" ? rung::cli::CheckFormat::Sarif
                                                   : rung::cli::CheckFormat::Human;
    if (!lint_profile.empty()) lint_options.profile = rung::project::parse_profile(lint_profile);
    if (write_baseline->count() > 0) lint_options.write_baseline = lint_baseline;
    return rung::cli::run_lint_command(lint_options, stdout, stderr);
  }
  if (*run_command) {
    run_options.color = color;
    run_options.format = run_format == "json" ? rung::cli::RunFormat::Json : rung::cli::RunFormat::Human;
    if (!run_profile.empty()) run_options.profile = rung::project::parse_profile(run_profile);
    return rung::cli::run_run_command(run_options, stdout, stderr);
  }
  if (*check) {
    check_options.color = color;
    check_options.format = check_format == "json"    ? rung::cli::CheckFormat::Json
                           : check_format == "sarif" ? rung::cli::CheckFormat::Sarif
                                                     : rung::cli::CheckFormat::Human;
    if (!check_profile.empty()) check_options.profile = rung::project::parse_profile(check_profile);
    return rung::cli::run_check_command(check_options, stdout, stderr);
  }
  if (*parse) {
    parse_options.color = color;
    parse_options.format = format_text == "json" ? rung::cli::OutputFormat::Json : rung::cli::OutputFormat::Human;
    return rung::cli::run_parse_command(parse_options, stdout, stderr);
  }
  return 0;
}

}  // namespace
