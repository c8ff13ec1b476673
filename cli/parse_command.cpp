#include "cli/parse_command.hpp"

#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "cli/diagnostic_printer.hpp"
#include "parser/document.hpp"
#include "parser/file_walk.hpp"
#include "parser/parallel_load.hpp"
#include "parser/tree_printer.hpp"

namespace rung::cli {

int run_parse_command(const ParseCommandOptions& options, std::FILE* out, std::FILE* err) {
  std::vector<std::filesystem::path> inputs(options.paths.begin(), options.paths.end());
  WalkResult walk = collect_source_files(inputs);
  bool io_failed = false;
  for (const auto& e : walk.errors) {
    std::fprintf(err, "error: %s\n", e.c_str());
    io_failed = true;
  }

  Style style{use_color(options.color, out)};
  Tally tally;
  nlohmann::json json_diagnostics = nlohmann::json::array();
  nlohmann::json json_trees = nlohmann::json::array();
  Progress progress("Parsing", walk.files.size());

  size_t done = 0;
  load_documents_in_order(walk.files, options.threads, [&](LoadedDocument& loaded) {
    progress.step(++done);
    if (!loaded.document) {
      std::fprintf(err, "error: %s\n", loaded.error.c_str());
      io_failed = true;
      return;
    }
    const Document& doc = *loaded.document;
    ++tally.files;
    for (const Diagnostic& d : doc.diagnostics()) {
      tally.add(d);
      if (options.format == OutputFormat::Json) {
        json_diagnostics.push_back(render_json(doc, d));
      } else {
        std::string text = render_human(doc, d, style);
        std::fwrite(text.data(), 1, text.size(), out);
      }
    }
    if (options.tree && doc.tree()) {
      if (options.format == OutputFormat::Json) {
        json_trees.push_back({{"file", doc.path()}, {"tree", print_sexp(doc.tree()->root())}});
      } else {
        TreePrintOptions tree_options;
        tree_options.describe_position = [&doc](uint32_t offset) {
          FilePosition p = doc.position_of_tree_offset(offset);
          return fmt::format("{}:{}", p.line, p.column);
        };
        tree_options.describe_end_position = [&doc](uint32_t offset) {
          FilePosition p = doc.position_of_file_offset(doc.file_end_offset_of(offset));
          return fmt::format("{}:{}", p.line, p.column);
        };
        fmt::print(out, "{}{}{}\n{}", style.bold(), doc.path(), style.reset(),
                   print_outline(doc.tree()->root(), tree_options));
      }
    }
  });
  progress.finish();

  if (options.format == OutputFormat::Json) {
    nlohmann::json report{{"files", tally.files},
                          {"errors", tally.errors},
                          {"warnings", tally.warnings},
                          {"diagnostics", std::move(json_diagnostics)}};
    if (options.tree) report["trees"] = std::move(json_trees);
    std::string text = report.dump(2);
    fmt::print(out, "{}\n", text);
  } else if (!options.quiet) {
    // The summary goes to stderr; flush the report first so that both appear in order when the
    // two streams end up in the same pipe or file.
    std::fflush(out);
    std::string_view color = tally.errors ? style.red() : style.green();
    fmt::print(err, "{}{}{}\n", color, tally.summary(), style.reset());
    if (tally.errors + tally.warnings > 0)
      fmt::print(err, "(run 'rung explain CODE' for what a code means and how to fix it)\n");
  }
  if (io_failed) return 2;
  return tally.errors > 0 ? 1 : 0;
}

}  // namespace rung::cli
