// Linter throughput on the generated 200,000-line project (issue goal: a full lint in under 2 s on
// one core). Results: docs/performance.md, "Linter".
#include <benchmark/benchmark.h>

#include <ctime>
#include <string>

#include "bench/generated_project.hpp"
#include "checker/check.hpp"
#include "checker/lint/lint.hpp"

namespace {
using rung::check::Workspace;

// The checker benchmark's project: 2,000 files, about 200,000 lines.
const rung::bench::GeneratedProject& lint_project() {
  static const rung::bench::GeneratedProject project = rung::bench::generate_project(2000);
  return project;
}

const std::vector<std::pair<std::string, std::string>>& lint_texts() {
  static const auto texts = rung::bench::project_texts(lint_project());
  return texts;
}

rung::check::LoadOptions one_thread() {
  rung::check::LoadOptions options;
  options.threads = 1;
  return options;
}

// Every rule on, the off-by-default ones too: the most work a project can ask for.
rung::project::LintSettings all_rules_on() {
  rung::project::LintSettings settings;
  for (const rung::lint::Rule& rule : rung::lint::all_rules()) settings.rules[std::string(rule.code)] = "on";
  return settings;
}

size_t count_findings(const std::vector<rung::lint::FileFindings>& files) {
  size_t findings = 0;
  for (const auto& file : files) findings += file.findings.size();
  return findings;
}

void report(benchmark::State& state, size_t findings) {
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * lint_project().lines));
  state.counters["lines"] = static_cast<double>(lint_project().lines);
  state.counters["findings"] = static_cast<double>(findings);
}

// `rung lint` without reading and printing: load the project (parse, libraries, link) and run
// every rule, all on one core.
void BM_LintProject(benchmark::State& state) {
  const rung::project::ProjectConfig config;
  const rung::project::LintSettings settings = state.range(0) ? all_rules_on() : config.lint;
  size_t findings = 0;
  for (auto _ : state) {
    auto workspace = Workspace::from_texts(lint_texts(), config, one_thread());
    findings = count_findings(rung::lint::lint_all(*workspace, settings, 1));
  }
  report(state, findings);
}
// 0: the default rules; 1: every rule.
BENCHMARK(BM_LintProject)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

// The rules alone on a loaded project, on state.range(0) threads.
void BM_LintRules(benchmark::State& state) {
  auto workspace = Workspace::from_texts(lint_texts(), rung::project::ProjectConfig{});
  const rung::project::LintSettings settings = all_rules_on();
  const unsigned threads = static_cast<unsigned>(state.range(0));
  size_t findings = 0;
  for (auto _ : state) findings = count_findings(rung::lint::lint_all(*workspace, settings, threads));
  report(state, findings);
}
BENCHMARK(BM_LintRules)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

// The CPU time of this process so far: a busy machine does not inflate it the way it does the
// wall clock.
double cpu_milliseconds() {
  timespec now{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) * 1e3 + static_cast<double>(now.tv_nsec) / 1e6;
}

// Where the time goes: each rule alone over the loaded project, one core; a counter per rule in
// CPU milliseconds (ms_L030 ...) and its findings (n_L030 ...).
void BM_LintEachRule(benchmark::State& state) {
  auto workspace = Workspace::from_texts(lint_texts(), rung::project::ProjectConfig{});
  for (auto _ : state) {
    for (const rung::lint::Rule& rule : rung::lint::all_rules()) {
      rung::project::LintSettings settings;
      for (const rung::lint::Rule& other : rung::lint::all_rules()) settings.rules[std::string(other.code)] = "off";
      settings.rules[std::string(rule.code)] = "on";
      const double start = cpu_milliseconds();
      const size_t findings = count_findings(rung::lint::lint_all(*workspace, settings, 1));
      state.counters["ms_" + std::string(rule.code)] = cpu_milliseconds() - start;
      state.counters["n_" + std::string(rule.code)] = static_cast<double>(findings);
    }
  }
}
BENCHMARK(BM_LintEachRule)->Iterations(1)->Unit(benchmark::kMillisecond)->UseRealTime();

// The floor under every rule that walks whole files: one tree-cursor walk over every node of the
// project (each rule that walks the tree on its own pays this again).
void BM_WalkProjectTrees(benchmark::State& state) {
  auto workspace = Workspace::from_texts(lint_texts(), rung::project::ProjectConfig{});
  size_t nodes = 0;
  for (auto _ : state) {
    nodes = 0;
    for (rung::check::SourceId id = 0; id < workspace->model().source_count(); ++id) {
      const rung::check::Source& source = workspace->model().source(id);
      if (source.library || !source.document->tree()) continue;
      rung::walk_preorder(source.document->tree()->root(), [&](rung::SyntaxNode) { return ++nodes != 0; });
    }
  }
  state.counters["nodes"] = static_cast<double>(nodes);
}
BENCHMARK(BM_WalkProjectTrees)->Unit(benchmark::kMillisecond);

}  // namespace
