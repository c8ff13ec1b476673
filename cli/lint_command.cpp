#include "cli/lint_command.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "checker/lint/apply_fixes.hpp"
#include "checker/lint/baseline.hpp"
#include "checker/lint/lint.hpp"
#include "cli/atomic_write.hpp"
#include "cli/diagnostic_printer.hpp"
#include "cli/project_loading.hpp"
#include "cli/sarif_report.hpp"
#include "parser/diagnostic_codes.hpp"

namespace rung::cli {
namespace fs = std::filesystem;

namespace {

constexpr int kMaxFixRounds = 3;
constexpr std::string_view kDefaultBaseline = "lint-baseline.json";

// The project's baseline file: --write-baseline FILE, else rung.toml's [lint] baseline, else the
// default name in the project folder.
fs::path baseline_file(const LintCommandOptions& options, const LoadedProject& project) {
  if (options.write_baseline && !options.write_baseline->empty()) return fs::absolute(*options.write_baseline);
  const std::string& configured = project.config.loaded.config.lint.baseline;
  return project.root() / (configured.empty() ? std::string(kDefaultBaseline) : configured);
}

std::optional<std::string> read_text(const fs::path& path) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) return std::nullopt;
  std::ifstream in(path, std::ios::binary);
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (!in) return std::nullopt;
  return buffer.str();
}

// Writes a whole file: replaced atomically when it exists, created otherwise.
bool write_text(const fs::path& path, const std::string& text, std::string* error) {
  std::error_code ec;
  if (fs::exists(path, ec)) return replace_file_atomically(path, text, error);
  if (path.has_parent_path()) fs::create_directories(path.parent_path(), ec);
  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (!file) {
    *error = "cannot create " + path.string();
    return false;
  }
  const bool written = std::fwrite(text.data(), 1, text.size(), file) == text.size();
  if (std::fclose(file) != 0 || !written) {
    *error = "cannot write " + path.string();
    return false;
  }
  return true;
}

// What one run found and did, for the closing lines and the JSON report.
struct LintRun {
  std::vector<lint::FileFindings> files;  // the files in scope, their findings as reported
  size_t fixed = 0;                       // fixes applied
  size_t fixed_files = 0;
  size_t baselined = 0;  // findings the baseline hid
  size_t stale = 0;      // baseline entries of the linted files that matched nothing
  bool failed = false;   // an I/O error or an unreadable baseline: exit 2
};

class LintCommand {
 public:
  LintCommand(const LintCommandOptions& options, LoadedProject& project, const Style& style, std::FILE* out,
              std::FILE* err)
      : options_(options), project_(project), style_(style), out_(out), err_(err) {}

  int run() {
    LintRun run;
    const bool config_ok = !project_.config.has_errors;
    if (!options_.no_baseline && !options_.write_baseline) run.failed |= !read_baseline();
    if (options_.fix && !config_ok) {
      fmt::print(err_, "error: rung.toml has errors; nothing was fixed\n");
    } else if (options_.fix && !run.failed) {
      fix(run);
    }
    run.files = lint_in_scope();
    if (options_.write_baseline) {
      if (!config_ok) {
        fmt::print(err_, "error: rung.toml has errors; the baseline was not written\n");
      } else {
        run.failed |= !write_baseline(run.files);
      }
      return finish(run, /*report=*/false);
    }
    if (baseline_) {
      const lint::BaselineResult matched =
          lint::apply_baseline(*baseline_, *project_.workspace, run.files, project_.root());
      run.baselined = matched.matched;
      run.stale = matched.unmatched;
    }
    add_unreadable_input(run.files);
    return finish(run, /*report=*/true);
  }

 private:
  const project::LintSettings& settings() const { return project_.config.loaded.config.lint; }
  const Document& document_of(const lint::FileFindings& file) const {
    return *project_.workspace->model().source(file.source).document;
  }

  std::vector<lint::FileFindings> lint_in_scope() const {
    const check::ProjectModel& model = project_.workspace->model();
    std::vector<check::SourceId> ids;
    for (check::SourceId id = 0; id < model.source_count(); ++id) {
      if (!model.source(id).library && project_.in_scope(model.source(id).document->path())) ids.push_back(id);
    }
    return lint::lint_sources(*project_.workspace, ids, settings(), options_.threads);
  }

  // A file rung could not read (binary, malformed XML, too large, an I/O error) was not linted:
  // like `rung check`, report why as an error in front of its findings. Never baselined.
  void add_unreadable_input(std::vector<lint::FileFindings>& files) const {
    for (lint::FileFindings& file : files) {
      std::vector<lint::Finding> unreadable;
      for (const Diagnostic& diagnostic : document_of(file).diagnostics()) {
        const std::string_view code = diagnostic.code;
        if (code == codes::kBinaryFile || code == codes::kContainer || code == codes::kParseAborted ||
            code == codes::kIoError) {
          unreadable.push_back({diagnostic, std::nullopt});
          unreadable.back().diagnostic.severity = Severity::Error;
        }
      }
      file.findings.insert(file.findings.begin(), std::make_move_iterator(unreadable.begin()),
                           std::make_move_iterator(unreadable.end()));
    }
  }

  bool read_baseline() {
    const fs::path path = baseline_file(options_, project_);
    const std::optional<std::string> text = read_text(path);
    if (!text) {
      // The default file is optional; one rung.toml names must exist.
      if (!settings().baseline.empty()) {
        fmt::print(err_, "warning: the baseline file {} (rung.toml [lint] baseline) does not exist\n", path.string());
      }
      return true;
    }
    std::string error;
    baseline_ = lint::parse_baseline(*text, &error);
    if (!baseline_) fmt::print(err_, "error: {}: not a rung lint baseline: {}\n", path.string(), error);
    return baseline_.has_value();
  }

  // Rounds of fixing: a fix that overlapped another is offered again on the changed text.
  void fix(LintRun& run) {
    std::vector<bool> changed(project_.workspace->model().source_count(), false);
    for (int round = 0; round < kMaxFixRounds; ++round) {
      std::vector<lint::FileFindings> files = lint_in_scope();
      if (baseline_) lint::apply_baseline(*baseline_, *project_.workspace, files, project_.root());
      bool any = false;
      for (const lint::FileFindings& file : files) {
        const lint::FixedFile fixed = lint::fix_file(document_of(file), file.findings);
        if (fixed.outcome == lint::FixedFile::Outcome::NotFixed) {
          // Said once, in the first round (later rounds find the same problem).
          if (round == 0 || changed[file.source]) fmt::print(err_, "{}: {}\n", file.path, fixed.problem);
          continue;
        }
        if (fixed.outcome != lint::FixedFile::Outcome::Changed) continue;
        std::string error;
        if (!replace_file_atomically(file.path, fixed.bytes, &error)) {
          fmt::print(err_, "error: {}\n", error);
          run.failed = true;
          continue;
        }
        project_.workspace->update(file.source, fixed.bytes);
        run.fixed += fixed.applied;
        if (!changed[file.source]) ++run.fixed_files;
        changed[file.source] = true;
        any = true;
      }
      if (!any) break;
    }
  }

  bool write_baseline(const std::vector<lint::FileFindings>& files) {
    const fs::path path = baseline_file(options_, project_);
    std::vector<lint::BaselineEntry> entries;
    std::set<std::string> linted;
    for (const lint::FileFindings& file : files) {
      linted.insert(lint::baseline_path(file.path, project_.root()));
      for (const lint::Finding& finding : file.findings) {
        entries.push_back(lint::baseline_entry(*project_.workspace, file, finding, project_.root()));
      }
    }
    // Linting part of the project keeps the entries of its other files (not of deleted ones).
    const size_t found = entries.size();
    std::set<std::string> others;
    const check::ProjectModel& model = project_.workspace->model();
    for (check::SourceId id = 0; id < model.source_count(); ++id) {
      if (model.source(id).library) continue;
      std::string file = lint::baseline_path(model.source(id).document->path(), project_.root());
      if (!linted.count(file)) others.insert(std::move(file));
    }
    if (const std::optional<std::string> old_text = read_text(path); old_text && !others.empty()) {
      if (auto old = lint::parse_baseline(*old_text, nullptr)) {
        for (lint::BaselineEntry& entry : *old) {
          if (others.count(entry.path)) entries.push_back(std::move(entry));
        }
      }
    }
    std::string error;
    if (!write_text(path, lint::baseline_json(std::move(entries)), &error)) {
      fmt::print(err_, "error: {}\n", error);
      return false;
    }
    if (!options_.quiet) {
      fmt::print(err_, "wrote {} finding{} of {} file{} to the baseline {}\n", found, found == 1 ? "" : "s",
                 files.size(), files.size() == 1 ? "" : "s", path.string());
    }
    return true;
  }

  nlohmann::json fix_json(const Document& document, const lint::Fix& fix) const {
    auto position = [&](uint32_t offset) {
      const FilePosition p = document.position_of_file_offset(offset);
      return nlohmann::json{{"line", p.line}, {"column", p.column}, {"offset", p.offset}};
    };
    nlohmann::json edits = nlohmann::json::array();
    for (const lint::TextEdit& edit : fix.edits) {
      edits.push_back(
          {{"start", position(edit.range.begin)}, {"end", position(edit.range.end)}, {"text", edit.replacement}});
    }
    return {{"description", fix.description}, {"edits", std::move(edits)}};
  }

  int finish(const LintRun& run, bool report) {
    Tally tally;
    size_t notes = 0;
    size_t fixable = 0;
    nlohmann::json json_findings = nlohmann::json::array();
    std::vector<SarifFinding> sarif;
    for (const lint::FileFindings& file : run.files) {
      ++tally.files;
      if (!report) continue;
      const Document& document = document_of(file);
      for (const lint::Finding& finding : file.findings) {
        const Diagnostic& diagnostic = finding.diagnostic;
        tally.add(diagnostic);
        notes += diagnostic.severity != Severity::Error && diagnostic.severity != Severity::Warning;
        fixable += finding.fix.has_value();
        const lint::Fix* fix = finding.fix ? &*finding.fix : nullptr;
        if (options_.format == CheckFormat::Json) {
          nlohmann::json item = render_json(document, diagnostic);
          if (fix) item["fix"] = fix_json(document, *fix);
          json_findings.push_back(std::move(item));
        } else if (options_.format == CheckFormat::Sarif) {
          sarif.push_back({&document, &diagnostic, fix});
        } else {
          std::string text = render_human(document, diagnostic, style_);
          if (fix) {
            text +=
                fmt::format("  {}= fix{}: {} (rung lint --fix)\n", style_.green(), style_.reset(), fix->description);
          }
          std::fwrite(text.data(), 1, text.size(), out_);
        }
      }
    }
    if (report && options_.format == CheckFormat::Json) {
      const nlohmann::json json{{"files", tally.files},
                                {"errors", tally.errors},
                                {"warnings", tally.warnings},
                                {"notes", notes},
                                {"fixed", run.fixed},
                                {"baselined", run.baselined},
                                {"stale_baseline_entries", run.stale},
                                {"profile", std::string(project::profile_name(project_.config.loaded.config.profile))},
                                {"diagnostics", std::move(json_findings)}};
      fmt::print(out_, "{}\n", json.dump(2));
    } else if (report && options_.format == CheckFormat::Sarif) {
      fmt::print(out_, "{}\n", sarif_report(sarif).dump(2));
    } else if (report && !options_.quiet) {
      std::fflush(out_);
      print_summary(run, tally, notes, fixable);
    }
    const bool broken = run.failed || project_.config.has_errors || !project_.workspace->load_errors.empty();
    return broken ? 2 : (tally.errors > 0 ? 1 : 0);
  }

  void print_summary(const LintRun& run, const Tally& tally, size_t notes, size_t fixable) const {
    if (run.fixed > 0) {
      fmt::print(err_, "fixed {} finding{} in {} file{}\n", run.fixed, run.fixed == 1 ? "" : "s", run.fixed_files,
                 run.fixed_files == 1 ? "" : "s");
    }
    std::string summary = tally.summary();
    if (notes > 0) summary += fmt::format(" (and {} info/hint finding{})", notes, notes == 1 ? "" : "s");
    fmt::print(err_, "{}{}{}\n", tally.errors ? style_.red() : style_.green(), summary, style_.reset());
    if (run.baselined > 0) {
      fmt::print(err_, "{} finding{} hidden by the baseline (--no-baseline shows them)\n", run.baselined,
                 run.baselined == 1 ? "" : "s");
    }
    if (run.stale > 0) {
      fmt::print(err_, "info: {} baseline entr{} no longer match (fixed?); 'rung lint --write-baseline' drops them\n",
                 run.stale, run.stale == 1 ? "y" : "ies");
    }
    if (fixable > 0 && !options_.fix) {
      fmt::print(err_, "{} finding{} can be fixed with 'rung lint --fix'\n", fixable, fixable == 1 ? "" : "s");
    }
    if (tally.errors + tally.warnings + notes > 0) {
      fmt::print(err_, "(run 'rung explain CODE' for what a rule checks and why)\n");
    }
  }

  const LintCommandOptions& options_;
  LoadedProject& project_;
  const Style& style_;
  std::FILE* out_;
  std::FILE* err_;
  std::optional<std::vector<lint::BaselineEntry>> baseline_;
};

// `--list-rules`: every rule, its defaults, and what this project's rung.toml makes of it.
int list_rules(const LintCommandOptions& options, const Style& style, std::FILE* out, std::FILE* err) {
  const fs::path first = fs::absolute(options.paths.empty() ? "." : options.paths.front()).lexically_normal();
  std::error_code ec;
  const ConfigLoad config =
      load_config_reporting(fs::is_directory(first, ec) ? first : first.parent_path(), style, err);
  fmt::print(out, "{:<6} {:<34} {:<9} {:<8} {:<4} {}\n", "code", "name", "severity", "default", "fix", "this project");
  for (const lint::Rule& rule : lint::all_rules()) {
    const DiagnosticCodeInfo* info = find_diagnostic_code(rule.code);
    const std::optional<Severity> level = lint::rule_severity(rule, config.loaded.config.lint);
    fmt::print(out, "{:<6} {:<34} {:<9} {:<8} {:<4} {}\n", rule.code, rule.name,
               info ? severity_name(info->default_severity) : "warning", rule.enabled_by_default ? "on" : "off",
               rule.has_fix ? "yes" : "no", level ? severity_name(*level) : "off");
  }
  return config.has_errors ? 2 : 0;
}

}  // namespace

int run_lint_command(const LintCommandOptions& options, std::FILE* out, std::FILE* err) {
  const Style style{use_color(options.color, out)};
  if (options.list_rules) return list_rules(options, style, out, err);
  if (options.write_baseline && options.fix) {
    fmt::print(err, "error: --write-baseline and --fix do not go together: fix first, then write the baseline\n");
    return 2;
  }
  if (options.write_baseline && !options.write_baseline->empty() && fs::is_directory(*options.write_baseline)) {
    // `--write-baseline src` took the folder to lint as the baseline file.
    fmt::print(err, "error: --write-baseline {} names a folder; write --write-baseline=FILE, or the paths first\n",
               *options.write_baseline);
    return 2;
  }
  std::optional<LoadedProject> project = load_project({options.paths, options.profile, options.threads}, style, err);
  if (!project) return 2;
  const int exit_code = LintCommand(options, *project, style, out, err).run();
  keep_until_exit(std::move(project->workspace));
  return exit_code;
}

}  // namespace rung::cli
