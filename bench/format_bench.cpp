// Formatter throughput (`rung fmt`'s engine). Results: docs/performance.md, "Formatter".
#include <benchmark/benchmark.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "bench/generated_source.hpp"
#include "formatter/format.hpp"
#include "formatter/layout_walk.hpp"
#include "formatter/printer.hpp"
#include "parser/syntax_tree.hpp"

namespace {

// A generated file as the formatter meets it in a real project: the generator's layout with the
// indentation removed, so that every line changes.
std::string unformatted_source(size_t lines) {
  const std::string text = rung::bench::generate_st(lines);
  std::string out;
  out.reserve(text.size());
  bool line_start = true;
  for (char c : text) {
    if (line_start && (c == ' ' || c == '\t')) continue;
    line_start = c == '\n';
    out += c;
  }
  return out;
}

// The whole of format_text: parse, layout, print, and the safety check.
void BM_FormatGenerated(benchmark::State& state) {
  const std::string text = unformatted_source(static_cast<size_t>(state.range(0)));
  const rung::project::FormatSettings settings;
  for (auto _ : state) {
    rung::format::FormatResult result = rung::format::format_text(text, settings);
    if (result.status != rung::format::Status::Formatted) {
      state.SkipWithError(result.message.c_str());
      return;
    }
    benchmark::DoNotOptimize(result.text);
  }
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations() * text.size()));
}
BENCHMARK(BM_FormatGenerated)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);

// What the language server does: format a document whose tree it already has (layout, print and
// the safety check; the check parses the result only when it cannot prove it safe otherwise).
void BM_FormatParsed(benchmark::State& state) {
  const std::string text = unformatted_source(static_cast<size_t>(state.range(0)));
  const rung::SyntaxTree tree = rung::SyntaxTree::parse(text);
  const rung::project::FormatSettings settings;
  for (auto _ : state) {
    rung::format::FormatResult result = rung::format::format_parsed(tree, text, settings);
    if (result.status != rung::format::Status::Formatted) {
      state.SkipWithError(result.message.c_str());
      return;
    }
    benchmark::DoNotOptimize(result.text);
  }
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations() * text.size()));
}
BENCHMARK(BM_FormatParsed)->Arg(10000)->Unit(benchmark::kMillisecond);

// The formatter's own work on an already parsed tree: the leaf walk, spacing, alignment and
// printing, without the two parses and the token comparison.
void BM_FormatLayoutOnly(benchmark::State& state) {
  const std::string text = unformatted_source(static_cast<size_t>(state.range(0)));
  const rung::SyntaxTree tree = rung::SyntaxTree::parse(text);
  const rung::project::FormatSettings settings;
  for (auto _ : state) {
    rung::format::WalkOptions options;
    const rung::format::WalkResult walk = rung::format::walk_leaves(tree, text, options);
    const rung::format::Layout layout = rung::format::lay_out(walk, text, settings);
    std::string out = rung::format::print(walk, layout, text, settings);
    benchmark::DoNotOptimize(out);
  }
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations() * text.size()));
}
BENCHMARK(BM_FormatLayoutOnly)->Arg(10000)->Unit(benchmark::kMillisecond);

// Every .st/.il example of the seed corpus that formats (most are a few lines: per-file costs).
void BM_FormatSeedCorpus(benchmark::State& state) {
  std::vector<std::string> texts;
  size_t bytes = 0;
  const std::filesystem::path root = std::filesystem::path(RUNG_SHARED_DIR) / "corpus/seeds";
  if (std::filesystem::exists(root)) {
    for (const auto& e : std::filesystem::recursive_directory_iterator(root)) {
      const auto ext = e.path().extension();
      if (ext != ".st" && ext != ".il") continue;
      std::ifstream in(e.path(), std::ios::binary);
      std::ostringstream s;
      s << in.rdbuf();
      texts.push_back(s.str());
      bytes += texts.back().size();
    }
  }
  if (texts.empty()) {
    state.SkipWithError("seed corpus not found next to the repository");
    return;
  }
  const rung::project::FormatSettings settings;
  for (auto _ : state) {
    for (const std::string& text : texts) benchmark::DoNotOptimize(rung::format::format_text(text, settings));
  }
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations() * bytes));
  state.counters["files"] = static_cast<double>(texts.size());
}
BENCHMARK(BM_FormatSeedCorpus)->Unit(benchmark::kMillisecond);

}  // namespace
