#include "cli/check_command.hpp"

#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "checker/check.hpp"
#include "cli/diagnostic_printer.hpp"
#include "cli/project_loading.hpp"
#include "cli/sarif_report.hpp"

namespace rung::cli {

int run_check_command(const CheckCommandOptions& options, std::FILE* out, std::FILE* err) {
  Style style{use_color(options.color, out)};
  std::optional<LoadedProject> loaded = load_project({options.paths, options.profile, options.threads}, style, err);
  if (!loaded) return 2;
  const check::Workspace& workspace = *loaded->workspace;
  const project::ProjectConfig& config = loaded->config.loaded.config;

  const std::vector<check::FileDiagnostics> results = workspace.check_all(options.threads);
  Tally tally;
  nlohmann::json json_diagnostics = nlohmann::json::array();
  std::vector<SarifFinding> findings;
  for (const auto& file : results) {
    if (!loaded->in_scope(file.path)) continue;
    ++tally.files;
    const Document& document = *workspace.model().source(file.source).document;
    for (const Diagnostic& diagnostic : file.diagnostics) {
      tally.add(diagnostic);
      switch (options.format) {
        case CheckFormat::Json: json_diagnostics.push_back(render_json(document, diagnostic)); break;
        case CheckFormat::Sarif: findings.push_back({&document, &diagnostic}); break;
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
                          {"profile", std::string(project::profile_name(config.profile))},
                          {"diagnostics", std::move(json_diagnostics)}};
    fmt::print(out, "{}\n", report.dump(2));
  } else if (options.format == CheckFormat::Sarif) {
    fmt::print(out, "{}\n", sarif_report(findings).dump(2));
  } else if (!options.quiet) {
    std::fflush(out);
    std::string_view color = tally.errors ? style.red() : style.green();
    fmt::print(err, "{}{}{}\n", color, tally.summary(), style.reset());
    if (tally.errors + tally.warnings > 0)
      fmt::print(err, "(run 'rung explain CODE' for what a code means and how to fix it)\n");
  }
  const int exit_code = (!workspace.load_errors.empty() || loaded->config.has_errors) ? 2 : (tally.errors > 0 ? 1 : 0);
  keep_until_exit(std::move(loaded->workspace));
  return exit_code;
}

}  // namespace rung::cli
