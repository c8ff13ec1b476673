#include "cli/fmt_command.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <optional>
#include <sstream>

#include "checker/project/project_config.hpp"
#include "cli/atomic_write.hpp"
#include "cli/diagnostic_printer.hpp"
#include "formatter/container_format.hpp"
#include "formatter/unified_diff.hpp"
#include "parser/containers/detect.hpp"
#include "parser/document.hpp"
#include "parser/file_walk.hpp"
#include "parser/parallel_for.hpp"
#include "parser/source/encode.hpp"
#include "parser/source/line_index.hpp"

namespace rung::cli {
namespace fs = std::filesystem;

namespace {

struct Settings {
  project::FormatSettings format;
  bool flat_comments = false;  // OpenPCS: comments do not nest in plain files
};

// One source formatted in memory: the bytes to write, or why it cannot be formatted.
struct FormattedSource {
  enum class Outcome { Unchanged, Changed, NotFormatted } outcome = Outcome::Unchanged;
  std::string bytes;               // Changed: the new file content, in the file's own encoding
  std::string before, after;       // Changed: both as UTF-8, for --diff
  std::string problem;             // NotFormatted: "file:line:col: not formatted: ..."
  std::vector<std::string> notes;  // parts of a container left alone, when nothing was formatted
};

// "line 12: expected ';'" -> {12, "expected ';'"}; line 1 when the message names no line.
std::pair<uint32_t, std::string> split_line_message(std::string_view message) {
  constexpr std::string_view prefix = "line ";
  if (message.substr(0, prefix.size()) == prefix) {
    uint32_t line = 0;
    const char* end = message.data() + message.size();
    const auto [after, error] = std::from_chars(message.data() + prefix.size(), end, line);
    if (error == std::errc() && line > 0 && after < end && *after == ':') {
      std::string_view rest(after + 1, static_cast<size_t>(end - after - 1));
      while (!rest.empty() && rest.front() == ' ') rest.remove_prefix(1);
      return {line, std::string(rest)};
    }
  }
  return {1, std::string(message)};
}

std::string file_count(size_t count) {
  return fmt::format("{} file{}", count, count == 1 ? "" : "s");
}

// The first syntax error as the checker reports it (line, column and wording of `rung check`);
// the engine's own message when the checker's reading has none.
std::string syntax_problem(const std::string& display, std::string_view bytes, const std::string& engine_message) {
  const Document document = Document::from_bytes(display, bytes);
  for (const Diagnostic& d : document.diagnostics()) {
    if (d.severity != Severity::Error) continue;
    const FilePosition p = document.position_of_file_offset(d.range.begin);
    return fmt::format("{}:{}:{}: not formatted: {}\n", display, p.line, p.column, d.message);
  }
  const auto [line, message] = split_line_message(engine_message);
  return fmt::format("{}:{}:1: not formatted: {}\n", display, line, message);
}

FormattedSource format_source(const std::string& display, std::string_view bytes, const Settings& settings) {
  FormattedSource out;
  const source::DecodedText decoded = source::decode(bytes);
  if (decoded.is_binary) {
    out.outcome = FormattedSource::Outcome::NotFormatted;
    out.problem = fmt::format("{}: not formatted: not a text file\n", display);
    return out;
  }
  if (!decoded.issues.empty()) {
    // Bytes that are not valid in the file's encoding were read as U+FFFD: writing the text back
    // would replace them.
    const source::Position p = source::LineIndex(decoded.utf8).position_of(decoded.issues[0].offset);
    out.outcome = FormattedSource::Outcome::NotFormatted;
    out.problem = fmt::format("{}:{}:{}: not formatted: {} (writing the file would change these bytes)\n", display,
                              p.line + 1, p.char_column + 1, decoded.issues[0].message);
    return out;
  }

  const containers::ContainerKind kind = containers::detect_container(display, decoded.utf8);
  const format::PieceFormatter engine = [&settings](std::string_view piece, const format::FormatRequest& request) {
    format::FormatRequest r = request;
    r.flat_comments = r.flat_comments || settings.flat_comments;
    return format::format_text(piece, settings.format, r);
  };
  format::FileFormatResult result = format::format_file_text(kind, decoded.utf8, engine);
  if (result.pieces == 0) out.notes = std::move(result.notes);
  switch (result.result.status) {
    case format::Status::SyntaxErrors:
      out.outcome = FormattedSource::Outcome::NotFormatted;
      out.problem = syntax_problem(display, bytes, result.result.message);
      return out;
    case format::Status::Unsafe: {
      const auto [line, message] = split_line_message(result.result.message);
      out.outcome = FormattedSource::Outcome::NotFormatted;
      out.problem = fmt::format(
          "{}:{}:1: internal error: the formatter's result failed its safety check ({}); the file was left as it "
          "is. Please report this with the file.\n",
          display, line, message);
      return out;
    }
    case format::Status::Formatted: break;
  }
  if (!result.result.changed || result.result.text == decoded.utf8) return out;

  std::optional<std::string> encoded = source::encode(result.result.text, decoded.encoding, decoded.had_bom);
  if (!encoded) {
    const uint32_t at = source::first_unencodable(result.result.text, decoded.encoding).value_or(0);
    const source::Position p = source::LineIndex(result.result.text).position_of(at);
    out.outcome = FormattedSource::Outcome::NotFormatted;
    out.problem = fmt::format("{}:{}:{}: not formatted: the result holds a character that {} cannot store\n", display,
                              p.line + 1, p.char_column + 1, source::encoding_name(decoded.encoding));
    return out;
  }
  out.outcome = FormattedSource::Outcome::Changed;
  out.bytes = std::move(*encoded);
  out.before = decoded.utf8;
  out.after = std::move(result.result.text);
  return out;
}

std::string colored_diff(const std::string& diff, const Style& style) {
  if (!style.enabled) return diff;
  std::string out;
  for (std::string_view line : format::split_lines(diff)) {
    std::string_view color;
    if (line.rfind("---", 0) == 0 || line.rfind("+++", 0) == 0)
      color = style.bold();
    else if (line.rfind("@@", 0) == 0)
      color = style.cyan();
    else if (line.starts_with('-'))
      color = style.red();
    else if (line.starts_with('+'))
      color = style.green();
    const bool ends = !line.empty() && line.back() == '\n';
    out += color;
    out += ends ? line.substr(0, line.size() - 1) : line;
    if (!color.empty()) out += style.reset();
    if (ends) out += '\n';
  }
  return out;
}

// The project's settings for files in `start`: the nearest rung.toml at or above it. Its findings
// are printed as `rung check` prints them; nullopt when it has errors (a layout from settings the
// user did not mean must not be written).
std::optional<Settings> load_settings(const fs::path& start, const Style& style, std::FILE* err,
                                      project::LoadedConfig* config_out = nullptr,
                                      std::optional<fs::path>* root_out = nullptr) {
  const std::optional<fs::path> root = project::find_project_root(start);
  project::LoadedConfig loaded = project::load_project_config(root ? *root : start);
  bool errors = false;
  for (const Diagnostic& diagnostic : loaded.diagnostics) {
    const Document config_document = Document::from_bytes((loaded.config.root / "rung.toml").string(), loaded.text);
    fmt::print(err, "{}", render_human(config_document, diagnostic, style));
    errors |= diagnostic.severity == Severity::Error;
  }
  if (errors) {
    fmt::print(err, "error: rung.toml has errors; nothing was formatted\n");
    return std::nullopt;
  }
  Settings settings;
  settings.format = loaded.config.format;
  settings.flat_comments = loaded.config.profile == project::Profile::Openpcs;
  if (root_out) *root_out = root;
  if (config_out) *config_out = std::move(loaded);
  return settings;
}

// A path as the user would type it: relative to the current folder when below it.
std::string display_path(const fs::path& file, const fs::path& cwd) {
  const fs::path absolute = fs::absolute(file).lexically_normal();
  const fs::path relative = absolute.lexically_relative(cwd);
  if (!relative.empty() && *relative.begin() != "..") return relative.generic_string();
  return absolute.generic_string();
}

std::optional<std::string> read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) return std::nullopt;
  return buffer.str();
}

int run_stdin(const FmtCommandOptions& options, std::FILE* in, std::FILE* out, std::FILE* err) {
  if (!options.paths.empty()) {
    fmt::print(err, "error: --stdin reads standard input and takes no paths\n");
    return 2;
  }
  std::string bytes;
  char buffer[65536];
  for (size_t n; (n = std::fread(buffer, 1, sizeof buffer, in)) > 0;) bytes.append(buffer, n);
  if (std::ferror(in)) {
    fmt::print(err, "error: cannot read standard input\n");
    return 2;
  }
  const std::string display = options.stdin_filename.empty() ? "<stdin>" : options.stdin_filename;
  const fs::path start = options.stdin_filename.empty()
                             ? fs::current_path()
                             : fs::absolute(options.stdin_filename).lexically_normal().parent_path();
  const Style err_style{use_color(options.color, err)};
  const std::optional<Settings> settings = load_settings(start, err_style, err);
  if (!settings) return 2;

  const FormattedSource formatted = format_source(display, bytes, *settings);
  const bool report_only = options.check || options.diff;
  if (formatted.outcome == FormattedSource::Outcome::NotFormatted) {
    fmt::print(err, "{}", formatted.problem);
    // An editor that replaces its buffer with the output must get the text back, not nothing.
    if (!report_only) std::fwrite(bytes.data(), 1, bytes.size(), out);
    return 1;
  }
  const bool changed = formatted.outcome == FormattedSource::Outcome::Changed;
  if (options.diff) {
    if (changed) {
      const Style style{use_color(options.color, out)};
      fmt::print(
          out, "{}",
          colored_diff(format::unified_diff(formatted.before, formatted.after, "a/" + display, "b/" + display), style));
    }
  } else if (options.check) {
    if (changed) fmt::print(out, "{}\n", display);
  } else {
    const std::string& text = changed ? formatted.bytes : bytes;
    std::fwrite(text.data(), 1, text.size(), out);
  }
  return report_only && changed ? 1 : 0;
}

}  // namespace

int run_fmt_command(const FmtCommandOptions& options, std::FILE* in, std::FILE* out, std::FILE* err) {
  if (options.stdin_mode) return run_stdin(options, in, out, err);
  if (!options.stdin_filename.empty()) {
    fmt::print(err, "error: --stdin-filename is for --stdin\n");
    return 2;
  }
  const fs::path cwd = fs::current_path();
  std::vector<fs::path> inputs;
  for (const auto& path : options.paths) inputs.emplace_back(path);
  for (const auto& input : inputs) {
    std::error_code error;
    if (!fs::exists(input, error)) {
      fmt::print(err, "error: {}: no such file or folder\n", input.string());
      return 2;
    }
  }

  // Settings from the nearest rung.toml at or above the first path (or the current folder).
  const fs::path first = inputs.empty() ? cwd : fs::absolute(inputs.front()).lexically_normal();
  const fs::path start = fs::is_directory(first) ? first : first.parent_path();
  const Style err_style{use_color(options.color, err)};
  project::LoadedConfig loaded;
  std::optional<fs::path> root;
  const std::optional<Settings> settings = load_settings(start, err_style, err, &loaded, &root);
  if (!settings) return 2;

  std::vector<fs::path> files;
  std::vector<std::string> walk_errors;
  if (inputs.empty()) {
    // No path: the project of the current folder (its sources minus exclude), else the folder.
    if (root) {
      files = project::project_source_files(loaded.config, &walk_errors);
    } else {
      WalkResult walk = collect_source_files({cwd});
      files = std::move(walk.files);
      walk_errors = std::move(walk.errors);
    }
  } else {
    WalkResult walk = collect_source_files(inputs);
    walk_errors = std::move(walk.errors);
    for (const fs::path& file : walk.files) {
      // Files found in folders obey the project's exclude patterns; files named outright do not.
      const bool named = std::any_of(inputs.begin(), inputs.end(), [&](const fs::path& input) {
        return fs::absolute(input).lexically_normal() == fs::absolute(file).lexically_normal();
      });
      bool excluded = false;
      if (root && !named) {
        const std::string relative = fs::absolute(file).lexically_normal().lexically_relative(*root).generic_string();
        for (const std::string& pattern : loaded.config.exclude) excluded |= project::glob_match(pattern, relative);
      }
      if (!excluded) files.push_back(file);
    }
  }
  for (const std::string& error : walk_errors) fmt::print(err, "error: {}\n", error);

  struct FileReport {
    std::string out, err;
    bool changed = false, failed = false, io_error = false;
  };
  std::vector<FileReport> reports(files.size());
  const Style out_style{use_color(options.color, out)};
  const bool report_only = options.check || options.diff;
  Progress progress(report_only ? "Checking" : "Formatting", files.size());
  std::mutex progress_mutex;
  size_t done = 0;
  parallel_for(files.size(), options.threads, [&](size_t i) {
    FileReport& report = reports[i];
    const std::string display = display_path(files[i], cwd);
    const std::optional<std::string> bytes = read_bytes(files[i]);
    if (!bytes) {
      report.err = fmt::format("error: {}: cannot read the file\n", display);
      report.io_error = true;
    } else {
      FormattedSource formatted = format_source(display, *bytes, *settings);
      for (const std::string& note : formatted.notes) {
        if (!options.quiet) report.err += fmt::format("{}: note: {}\n", display, note);
      }
      if (formatted.outcome == FormattedSource::Outcome::NotFormatted) {
        report.err += formatted.problem;
        report.failed = true;
      } else if (formatted.outcome == FormattedSource::Outcome::Changed) {
        report.changed = true;
        std::string error;
        if (options.diff) {
          report.out = colored_diff(
              format::unified_diff(formatted.before, formatted.after, "a/" + display, "b/" + display), out_style);
        } else if (options.check) {
          report.out = display + "\n";
        } else if (!replace_file_atomically(files[i], formatted.bytes, &error)) {
          report.err += fmt::format("error: {}\n", error);
          report.io_error = true;
        }
      }
    }
    std::lock_guard<std::mutex> lock(progress_mutex);
    progress.step(++done);
  });
  progress.finish();

  size_t changed = 0, failed = 0;
  bool io_error = !walk_errors.empty();
  for (const FileReport& report : reports) {
    std::fwrite(report.out.data(), 1, report.out.size(), out);
    std::fwrite(report.err.data(), 1, report.err.size(), err);
    changed += report.changed && !report.io_error;
    failed += report.failed;
    io_error |= report.io_error;
  }
  if (!options.quiet) {
    std::fflush(out);
    const size_t total = files.size();
    std::string summary;
    if (report_only) {
      summary =
          changed ? fmt::format("{} of {} {} formatting (run 'rung fmt' to format {})", changed, file_count(total),
                                changed == 1 ? "needs" : "need", changed == 1 ? "it" : "them")
                  : fmt::format("{} already formatted", file_count(total - failed));
    } else {
      summary = fmt::format("formatted {} of {}", changed, file_count(total));
    }
    if (failed) summary += fmt::format(", {} not formatted (see above)", failed);
    const std::string_view color = failed || (report_only && changed) ? err_style.red() : err_style.green();
    fmt::print(err, "{}{}{}\n", color, summary, err_style.reset());
  }
  if (io_error) return 2;
  return failed > 0 || (report_only && changed > 0) ? 1 : 0;
}

}  // namespace rung::cli
