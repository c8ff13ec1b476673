#include "tests/runner/run_support.hpp"

#include <gtest/gtest.h>

#include <fmt/format.h>

#include "runner/inspect.hpp"

namespace rung::run::testing {

std::string sequence(Run& run, std::string_view input, const std::vector<std::string>& values, std::string_view output) {
  std::string seen;
  for (const std::string& value : values) {
    run.set(input, value);
    EXPECT_TRUE(run.cycles(1)) << run.error();
    if (!seen.empty()) seen += ",";
    seen += run.text(output);
  }
  return seen;
}

std::string trace(Run& run, uint64_t count, const std::vector<std::string>& outputs) {
  std::string seen;
  for (uint64_t i = 0; i < count; ++i) {
    EXPECT_TRUE(run.cycles(1)) << run.error();
    if (!seen.empty()) seen += ",";
    for (size_t j = 0; j < outputs.size(); ++j) seen += (j ? "/" : "") + run.text(outputs[j]);
  }
  return seen;
}

std::string joined(const std::vector<std::string>& lines) {
  std::string out;
  for (const std::string& line : lines) out += line + "\n";
  return out;
}

bool Run::cycles(uint64_t count) {
  if (!engine) return false;
  for (uint64_t i = 0; i < count; ++i) {
    if (!engine->cycle()) return false;
  }
  return true;
}

std::string Run::text(std::string_view path) const {
  if (!engine) return "<error: not running>";
  std::string why;
  auto ref = resolve_path(project, engine->machine(), path, &why);
  if (!ref) return "<error: " + why + ">";
  return value_text(project, engine->machine(), *ref);
}

void Run::set(std::string_view path, std::string_view value) {
  ASSERT_TRUE(engine);
  std::string why;
  auto ref = resolve_path(project, engine->machine(), path, &why);
  ASSERT_TRUE(ref) << why;
  ASSERT_TRUE(write_value(project, engine->machine(), *ref, value, &why)) << why;
}

std::string Run::error() const {
  if (!engine || !engine->machine().error()) return {};
  return engine->machine().error()->message;
}

std::string Run::described_error() const {
  if (!engine || !engine->machine().error()) return {};
  return describe_error(project, *engine->machine().error());
}

std::unique_ptr<Run> run_files(const std::vector<std::pair<std::string, std::string>>& files,
                               const RunOptions& options) {
  auto run = std::make_unique<Run>();
  project::ProjectConfig config;
  config.profile = options.profile;
  run->workspace = check::Workspace::from_texts(files, config);
  for (const check::FileDiagnostics& file : run->workspace->check_all(1)) {
    const Document& document = *run->workspace->model().source(file.source).document;
    for (const Diagnostic& diagnostic : file.diagnostics) {
      if (diagnostic.severity != Severity::Error) continue;
      const FilePosition position = document.position_of_file_offset(diagnostic.range.begin);
      run->check_errors.push_back(
          fmt::format("{}:{}: [{}] {}", position.line, position.column, diagnostic.code, diagnostic.message));
    }
  }
  if (!run->check_errors.empty()) return run;
  CompileOptions compile_options;
  compile_options.program = options.program;
  run->project = compile_project(run->workspace->model(), compile_options);
  for (const CompileError& error : run->project.errors) {
    std::string where;
    if (error.source != check::kNoSource) {
      const FilePosition position =
          run->workspace->model().source(error.source).document->position_of_tree_offset(error.offset);
      where = fmt::format("{}:{}: ", position.line, position.column);
    }
    run->compile_errors.push_back(where + error.message);
  }
  if (!run->compile_errors.empty()) return run;
  run->engine = std::make_unique<Engine>(run->project, options.tick_ns);
  run->cycles(options.cycles);
  return run;
}

std::unique_ptr<Run> run_text(std::string_view source, const RunOptions& options) {
  return run_files({{"main.st", std::string(source)}}, options);
}

}  // namespace rung::run::testing
