// Parser throughput and incremental re-parse latency. Results: docs/performance.md.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "bench/generated_source.hpp"
#include "parser/document.hpp"
#include "parser/parallel_load.hpp"
#include "parser/source/decode.hpp"
#include "parser/syntax_tree.hpp"

namespace {

std::string read(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Full parse of a generated file of state.range(0) lines.
void BM_ParseGenerated(benchmark::State& state) {
  std::string text = rung::bench::generate_st(static_cast<size_t>(state.range(0)));
  for (auto _ : state) {
    rung::SyntaxTree tree = rung::SyntaxTree::parse(text);
    benchmark::DoNotOptimize(tree.root());
  }
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations() * text.size()));
}
BENCHMARK(BM_ParseGenerated)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);

// The whole pipeline a `rung parse` does per file: decode, parse, syntax diagnostics.
void BM_DocumentGenerated(benchmark::State& state) {
  std::string text = rung::bench::generate_st(static_cast<size_t>(state.range(0)));
  for (auto _ : state) {
    rung::Document doc = rung::Document::from_bytes("gen.st", text);
    benchmark::DoNotOptimize(doc.diagnostics());
  }
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations() * text.size()));
}
BENCHMARK(BM_DocumentGenerated)->Arg(10000)->Unit(benchmark::kMillisecond);

// Every example of the seed corpus, decoded and parsed.
void BM_ParseSeedCorpus(benchmark::State& state) {
  std::vector<std::pair<std::string, std::string>> files;
  size_t bytes = 0;
  std::filesystem::path root = std::filesystem::path(RUNG_SHARED_DIR) / "corpus/seeds";
  if (std::filesystem::exists(root)) {
    for (const auto& e : std::filesystem::recursive_directory_iterator(root)) {
      auto ext = e.path().extension();
      if (ext == ".st" || ext == ".il") {
        files.emplace_back(e.path().string(), read(e.path()));
        bytes += files.back().second.size();
      }
    }
  }
  if (files.empty()) {
    state.SkipWithError("seed corpus not found next to the repository");
    return;
  }
  for (auto _ : state) {
    for (const auto& [path, text] : files) {
      rung::Document doc = rung::Document::from_bytes(path, text);
      benchmark::DoNotOptimize(doc.tree());
    }
  }
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations() * bytes));
  state.counters["files"] = static_cast<double>(files.size());
}
BENCHMARK(BM_ParseSeedCorpus)->Unit(benchmark::kMillisecond);

// A one-character edit in the middle of a 10,000-line file, re-parsed incrementally (the parse
// tree kept) and the node table rebuilt. Each iteration types a digit and then deletes it again,
// so the text stays the same size.
void BM_IncrementalOneCharEdit(benchmark::State& state) {
  std::string text = rung::bench::generate_st(10000);
  rung::SyntaxTree::Options keep;
  keep.keep_parse_tree = true;
  rung::SyntaxTree tree = rung::SyntaxTree::parse(text, keep);
  size_t at = text.find("iState := iState + 1;", text.size() / 2);
  uint32_t pos = static_cast<uint32_t>(at + 19);  // just before the '1'
  for (auto _ : state) {
    tree.apply_edit(pos, pos, "7");
    tree.apply_edit(pos, pos + 1, "");
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * 2));
  state.SetLabel("2 edits per iteration");
}
BENCHMARK(BM_IncrementalOneCharEdit)->Unit(benchmark::kMicrosecond);

void BM_DecodeCp1252(benchmark::State& state) {
  std::string text = rung::bench::generate_st(10000);
  for (size_t i = 0; i < text.size(); i += 97) text[i] = '\xE4';
  for (auto _ : state) {
    auto decoded = rung::source::decode(text);
    benchmark::DoNotOptimize(decoded.utf8);
  }
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations() * text.size()));
}
BENCHMARK(BM_DecodeCp1252)->Unit(benchmark::kMillisecond);

}  // namespace

namespace {

// `rung parse` of a whole project: 200 generated files of ~500 lines each, read from disk,
// decoded, parsed and checked for syntax errors, on state.range(0) threads.
void BM_ParseProjectFromDisk(benchmark::State& state) {
  static std::vector<std::filesystem::path> files;
  static size_t bytes = 0;
  if (files.empty()) {
    auto dir = std::filesystem::temp_directory_path() / "rung_bench_project";
    std::filesystem::create_directories(dir);
    for (unsigned i = 0; i < 200; ++i) {
      auto path = dir / ("FB_" + std::to_string(i) + ".st");
      std::string text = rung::bench::generate_st(500, i + 1);
      std::ofstream(path, std::ios::binary) << text;
      files.push_back(path);
      bytes += text.size();
    }
  }
  for (auto _ : state) {
    size_t diagnostics = 0;
    rung::load_documents_in_order(files, static_cast<unsigned>(state.range(0)), [&](rung::LoadedDocument& d) {
      if (d.document) diagnostics += d.document->diagnostics().size();
    });
    benchmark::DoNotOptimize(diagnostics);
  }
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations() * bytes));
  state.counters["files"] = static_cast<double>(files.size());
}
BENCHMARK(BM_ParseProjectFromDisk)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
