#include "cli/check_command.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "checker/check.hpp"
#include "cli/diagnostic_printer.hpp"
#include "parser/diagnostic_codes.hpp"
#include "parser/file_walk.hpp"

namespace rung::cli {
namespace fs = std::filesystem;

namespace {

// Whether `file` is `root` or lies below it.
bool is_within(const fs::path& file, const fs::path& root) {
  const fs::path relative = file.lexically_relative(root);
  return !relative.empty() && *relative.begin() != "..";
}

std::string sarif_level(Severity severity) {
  switch (severity) {
    case Severity::Error:
      return "error";
    case Severity::Warning:
      return "warning";
    default:
      return "note";
  }
}

nlohmann::json sarif_report(const std::vector<std::pair<const Document*, const Diagnostic*>>& findings) {
  nlohmann::json rules = nlohmann::json::array();
  for (const DiagnosticCodeInfo& info : all_diagnostic_codes()) {
    rules.push_back({{"id", std::string(info.code)},
                     {"name", std::string(info.title)},
                     {"shortDescription", {{"text", std::string(info.summary)}}},
                     {"helpUri", fmt::format("https://github.com/rung-plc/rung/blob/main/docs/diagnostics/{}.md", info.code)},
                     {"defaultConfiguration", {{"level", sarif_level(info.default_severity)}}}});
  }
  nlohmann::json results = nlohmann::json::array();
  for (const auto& [document, diagnostic] : findings) {
    const FilePosition start = document->position_of_file_offset(diagnostic->range.begin);
    const FilePosition end = document->position_of_file_offset(diagnostic->range.end);
    std::string text = diagnostic->message;
    if (!diagnostic->help.empty()) text += " (" + diagnostic->help + ")";
    results.push_back(
        {{"ruleId", diagnostic->code},
         {"level", sarif_level(diagnostic->severity)},
         {"message", {{"text", text}}},
         {"locations",
          {{{"physicalLocation",
             {{"artifactLocation", {{"uri", fs::path(document->path()).generic_string()}}},
              {"region",
               {{"startLine", start.line}, {"startColumn", start.column}, {"endLine", end.line}, {"endColumn", end.column}}}}}}}}});
  }
  return {{"$schema", "https://json.schemastore.org/sarif-2.1.0.json"},
          {"version", "2.1.0"},
          {"runs",
           {{{"tool", {{"driver", {{"name", "rung"}, {"informationUri", "https://github.com/rung-plc/rung"}, {"rules", rules}}}}},
             {"results", results}}}}};
}

// The process ends right after a check. Freeing the syntax trees of a large project node by node
// took 5% of a whole check (like compilers, which leave their ASTs to the operating system), so
// the workspace is left to the process exit. Sanitizer builds free it: leak checks stay useful.
void keep_until_exit(std::unique_ptr<check::Workspace> workspace) {
#if defined(__SANITIZE_ADDRESS__)
  workspace.reset();
#else
  static_cast<void>(workspace.release());
#endif
}

}  // namespace

int run_check_command(const CheckCommandOptions& options, std::FILE* out, std::FILE* err) {
  std::vector<fs::path> inputs;
  for (const auto& path : options.paths) inputs.push_back(path);
  if (inputs.empty()) inputs.emplace_back(".");
  for (const auto& input : inputs) {
    std::error_code error;
    if (!fs::exists(input, error)) {
      fmt::print(err, "error: {}: no such file or folder\n", input.string());
      return 2;
    }
  }
  // The project: the nearest rung.toml at or above the first path; else that folder alone.
  const fs::path first = fs::absolute(inputs.front()).lexically_normal();
  const fs::path start = fs::is_directory(first) ? first : first.parent_path();
  const std::optional<fs::path> root = project::find_project_root(start);
  project::LoadedConfig loaded = project::load_project_config(root ? *root : start);
  Style style{use_color(options.color, out)};
  bool config_errors = false;
  for (const Diagnostic& diagnostic : loaded.diagnostics) {
    Document config_document = Document::from_bytes((loaded.config.root / "rung.toml").string(), loaded.text);
    fmt::print(err, "{}", render_human(config_document, diagnostic, style));
    config_errors |= diagnostic.severity == Severity::Error;
  }
  if (options.profile) loaded.config.profile = *options.profile;

  check::LoadOptions load_options;
  load_options.threads = options.threads;
  std::unique_ptr<check::Workspace> workspace;
  if (root) {
    workspace = check::Workspace::load(loaded.config, load_options);
  } else {
    WalkResult walk = collect_source_files(inputs);
    workspace = check::Workspace::load_files(walk.files, loaded.config, load_options);
    for (const auto& error : walk.errors) workspace->load_errors.push_back(error);
  }
  for (const auto& error : workspace->load_errors) fmt::print(err, "error: {}\n", error);

  std::vector<fs::path> scopes;
  scopes.reserve(inputs.size());
  for (const auto& input : inputs) scopes.push_back(fs::absolute(input).lexically_normal());
  const std::vector<check::FileDiagnostics> results = workspace->check_all(options.threads);
  Tally tally;
  nlohmann::json json_diagnostics = nlohmann::json::array();
  std::vector<std::pair<const Document*, const Diagnostic*>> findings;
  for (const auto& file : results) {
    const fs::path path = fs::absolute(file.path).lexically_normal();
    bool wanted = false;
    for (const auto& scope : scopes) wanted |= path == scope || is_within(path, scope);
    if (!wanted) continue;
    ++tally.files;
    const Document& document = *workspace->model().source(file.source).document;
    for (const Diagnostic& diagnostic : file.diagnostics) {
      tally.add(diagnostic);
      switch (options.format) {
        case CheckFormat::Json:
          json_diagnostics.push_back(render_json(document, diagnostic));
          break;
        case CheckFormat::Sarif:
          findings.emplace_back(&document, &diagnostic);
          break;
        case CheckFormat::Human: {
          const std::string text = render_human(document, diagnostic, style);
          std::fwrite(text.data(), 1, text.size(), out);
          break;
        }
      }
    }
  }
  if (options.format == CheckFormat::Json) {
    nlohmann::json report{{"files", tally.files},
                          {"errors", tally.errors},
                          {"warnings", tally.warnings},
                          {"profile", std::string(project::profile_name(loaded.config.profile))},
                          {"diagnostics", std::move(json_diagnostics)}};
    fmt::print(out, "{}\n", report.dump(2));
  } else if (options.format == CheckFormat::Sarif) {
    fmt::print(out, "{}\n", sarif_report(findings).dump(2));
  } else if (!options.quiet) {
    std::fflush(out);
    std::string_view color = tally.errors ? style.red() : style.green();
    fmt::print(err, "{}{}{}\n", color, tally.summary(), style.reset());
    if (tally.errors + tally.warnings > 0) fmt::print(err, "(run 'rung explain CODE' for what a code means and how to fix it)\n");
  }
  const int exit_code = (!workspace->load_errors.empty() || config_errors) ? 2 : (tally.errors > 0 ? 1 : 0);
  keep_until_exit(std::move(workspace));
  return exit_code;
}

}  // namespace rung::cli
