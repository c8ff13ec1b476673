// Semantic checker throughput and re-check latency. Results: docs/performance.md.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "bench/generated_project.hpp"
#include "checker/check.hpp"
#include "checker/query/references.hpp"

namespace {
namespace fs = std::filesystem;
using rung::check::FileDiagnostics;
using rung::check::Workspace;

// 2,000 files of about 100 lines: the "large project" (≥ 200,000 lines, ≥ 2,000 files).
constexpr size_t kProjectFiles = 2000;

const rung::bench::GeneratedProject& generated_project() {
  static const rung::bench::GeneratedProject project = rung::bench::generate_project(kProjectFiles);
  return project;
}

const std::vector<std::pair<std::string, std::string>>& project_texts() {
  static const auto texts = rung::bench::project_texts(generated_project());
  return texts;
}

rung::project::ProjectConfig config_for(rung::project::Profile profile) {
  rung::project::ProjectConfig config;
  config.profile = profile;
  return config;
}

rung::check::LoadOptions on_threads(unsigned threads) {
  rung::check::LoadOptions options;
  options.threads = threads;
  return options;
}

size_t count_errors(const std::vector<FileDiagnostics>& results) {
  size_t errors = 0;
  for (const FileDiagnostics& file : results) {
    for (const rung::Diagnostic& diagnostic : file.diagnostics) errors += diagnostic.severity == rung::Severity::Error;
  }
  return errors;
}

// The generated project must check without errors: a benchmark of a project full of errors
// would time error reporting and early exits instead of the real work. Stops the run otherwise.
void require_clean(const Workspace& workspace, const std::vector<FileDiagnostics>& results, const char* what) {
  const size_t errors = count_errors(results);
  if (errors == 0) return;
  std::fprintf(stderr,
               "error: %s: %zu errors in the generated project, which must check clean "
               "(bench/generated_project.cpp); the first ones:\n",
               what, errors);
  size_t shown = 0;
  for (const FileDiagnostics& file : results) {
    const rung::Document& document = *workspace.model().source(file.source).document;
    for (const rung::Diagnostic& diagnostic : file.diagnostics) {
      if (diagnostic.severity != rung::Severity::Error || shown++ == 10) continue;
      const rung::FilePosition at = document.position_of_file_offset(diagnostic.range.begin);
      std::fprintf(stderr, "  %s:%u:%u: %s %s\n", file.path.c_str(), at.line, at.column, diagnostic.code.c_str(),
                   diagnostic.message.c_str());
    }
  }
  std::exit(EXIT_FAILURE);
}

void require_clean(const Workspace& workspace, const char* what) {
  require_clean(workspace, workspace.check_all(), what);
}

void report_lines(benchmark::State& state, size_t lines, size_t files) {
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * lines));
  state.counters["lines"] = static_cast<double>(lines);
  state.counters["files"] = static_cast<double>(files);
}

// --- Full check ------------------------------------------------------------------------------

// What an editor or test does with a project in memory: Workspace::from_texts (parse every file,
// load the CODESYS stub libraries, link) and check_all on state.range(0) threads. from_texts
// parses on one thread, so only the body checks use the second core here.
void BM_CheckProject(benchmark::State& state) {
  const auto& texts = project_texts();
  const auto config = config_for(rung::project::Profile::Codesys);
  const unsigned threads = static_cast<unsigned>(state.range(0));
  for (auto _ : state) {
    auto workspace = Workspace::from_texts(texts, config, on_threads(threads));
    auto results = workspace->check_all(threads);
    state.PauseTiming();
    require_clean(*workspace, results, "BM_CheckProject");
    state.ResumeTiming();
  }
  report_lines(state, generated_project().lines, texts.size());
}
BENCHMARK(BM_CheckProject)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

// The folder written once to a temporary directory, for the benchmarks that read from disk.
const std::vector<fs::path>& project_files_on_disk() {
  static const std::vector<fs::path> files = [] {
    const fs::path folder = fs::temp_directory_path() / "rung_bench_check_project";
    fs::remove_all(folder);
    std::string error;
    if (!rung::bench::write_project(generated_project(), folder, error)) {
      std::fprintf(stderr, "error: %s\n", error.c_str());
      std::exit(EXIT_FAILURE);
    }
    std::vector<fs::path> paths;
    for (const auto& file : generated_project().files) paths.push_back(folder / file.name);
    return paths;
  }();
  return files;
}

// What `rung check DIR -j N` does minus printing: read and parse the files on N threads
// (Workspace::load_files), load the libraries, link, check every body on N threads.
void BM_CheckProjectFromDisk(benchmark::State& state) {
  const auto& files = project_files_on_disk();
  const auto config = config_for(rung::project::Profile::Codesys);
  const unsigned threads = static_cast<unsigned>(state.range(0));
  for (auto _ : state) {
    auto workspace = Workspace::load_files(files, config, on_threads(threads));
    auto results = workspace->check_all(threads);
    state.PauseTiming();
    require_clean(*workspace, results, "BM_CheckProjectFromDisk");
    state.ResumeTiming();
  }
  report_lines(state, generated_project().lines, files.size());
}
BENCHMARK(BM_CheckProjectFromDisk)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

// The two halves of BM_CheckProject apart: loading (parse + libraries + link) ...
void BM_LoadProject(benchmark::State& state) {
  const auto& texts = project_texts();
  const auto config = config_for(rung::project::Profile::Codesys);
  for (auto _ : state) {
    auto workspace = Workspace::from_texts(texts, config);
    benchmark::DoNotOptimize(workspace->model().source_count());
  }
  report_lines(state, generated_project().lines, texts.size());
}
BENCHMARK(BM_LoadProject)->Unit(benchmark::kMillisecond)->UseRealTime();

// ... and check_all on a loaded project (declaration and body checks only).
void BM_CheckBodies(benchmark::State& state) {
  const auto& texts = project_texts();
  auto workspace = Workspace::from_texts(texts, config_for(rung::project::Profile::Codesys));
  require_clean(*workspace, "BM_CheckBodies");
  const unsigned threads = static_cast<unsigned>(state.range(0));
  for (auto _ : state) {
    auto results = workspace->check_all(threads);
    benchmark::DoNotOptimize(results.data());
  }
  report_lines(state, generated_project().lines, texts.size());
}
BENCHMARK(BM_CheckBodies)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

// --- Seed corpus -------------------------------------------------------------------------------

std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

struct SeedFile {
  std::string path;
  std::string text;
  rung::project::Profile profile;
};

// Every .st/.il example of the seed corpus (the .txt files are prose). The examples are
// independent excerpts of four manuals, so each is its own one-file project, checked in its
// manual's profile (003 is the OpenPCS manual), the way tests/checker/seeds checks them.
std::vector<SeedFile> seed_files() {
  std::vector<SeedFile> files;
  const fs::path root = fs::path(RUNG_SHARED_DIR) / "corpus/seeds";
  if (!fs::exists(root)) return files;
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    const fs::path extension = entry.path().extension();
    if (extension != ".st" && extension != ".il") continue;
    const bool openpcs = entry.path().parent_path().filename() == "003";
    files.push_back({entry.path().string(), read_file(entry.path()),
                     openpcs ? rung::project::Profile::Openpcs : rung::project::Profile::Codesys});
  }
  std::sort(files.begin(), files.end(), [](const SeedFile& a, const SeedFile& b) { return a.path < b.path; });
  return files;
}

// `rung check FILE` for every seed example, one after the other: each loads its profile's stub
// libraries again, as a separate rung process would.
void BM_CheckSeedCorpus(benchmark::State& state) {
  const std::vector<SeedFile> files = seed_files();
  if (files.empty()) {
    state.SkipWithError("seed corpus not found next to the repository");
    return;
  }
  size_t lines = 0;
  for (const SeedFile& file : files) lines += static_cast<size_t>(std::count(file.text.begin(), file.text.end(), '\n'));
  size_t diagnostics = 0;
  for (auto _ : state) {
    diagnostics = 0;
    for (const SeedFile& file : files) {
      auto workspace = Workspace::from_texts({{file.path, file.text}}, config_for(file.profile), on_threads(1));
      for (const FileDiagnostics& result : workspace->check_all(1)) diagnostics += result.diagnostics.size();
    }
  }
  report_lines(state, lines, files.size());
  state.counters["diagnostics"] = static_cast<double>(diagnostics);
}
BENCHMARK(BM_CheckSeedCorpus)->Unit(benchmark::kMillisecond)->UseRealTime();

// The fixed cost in every workspace: parsing and linking the CODESYS stub libraries.
void BM_LoadStandardLibraries(benchmark::State& state) {
  const auto config = config_for(rung::project::Profile::Codesys);
  for (auto _ : state) {
    auto workspace = Workspace::from_texts({}, config, on_threads(1));
    benchmark::DoNotOptimize(workspace->model().source_count());
  }
}
BENCHMARK(BM_LoadStandardLibraries)->Unit(benchmark::kMillisecond)->UseRealTime();

// --- Re-check after an edit ----------------------------------------------------------------------

// The loaded, clean project the edit benchmarks change (built once: loading takes seconds).
Workspace& edit_workspace() {
  static const std::unique_ptr<Workspace> workspace = [] {
    auto loaded = Workspace::from_texts(project_texts(), config_for(rung::project::Profile::Codesys));
    require_clean(*loaded, "edit benchmarks");
    return loaded;
  }();
  return *workspace;
}

// One file of the middle of the project and the same file with one edit applied.
struct Edit {
  rung::check::SourceId id = rung::check::kNoSource;
  std::string original;
  std::string edited;
};

Edit make_edit(const std::string& file_name, const std::string& find, const std::string& replace) {
  const std::optional<rung::check::SourceId> id = edit_workspace().model().find_source(file_name);
  const auto& files = generated_project().files;
  const auto file = std::find_if(files.begin(), files.end(), [&](const auto& f) { return f.name == file_name; });
  if (!id || file == files.end()) {
    std::fprintf(stderr, "error: %s is not in the generated project\n", file_name.c_str());
    std::exit(EXIT_FAILURE);
  }
  Edit edit;
  edit.id = *id;
  edit.original = file->text;
  const size_t at = edit.original.find(find);
  if (at == std::string::npos) {
    std::fprintf(stderr, "error: '%s' not found in %s\n", find.c_str(), file_name.c_str());
    std::exit(EXIT_FAILURE);
  }
  edit.edited = edit.original;
  edit.edited.replace(at, find.size(), replace);
  return edit;
}

// The middle cell's function block: instantiated by the next cell's FB and by its program.
std::string middle_function_block() {
  return "FB_Axis" + std::to_string(kProjectFiles / 5 / 2) + ".st";
}

// What an editor does per keystroke batch: Workspace::update, then check_source of every file
// update() says may have changed. Each iteration applies the edit or takes it back, so the
// project alternates between two states.
void run_edit(benchmark::State& state, const Edit& edit, bool expect_interface_change, const char* what) {
  Workspace& workspace = edit_workspace();
  bool edited = false;
  std::vector<FileDiagnostics> results;
  for (auto _ : state) {
    edited = !edited;
    const std::vector<rung::check::SourceId> changed = workspace.update(edit.id, edited ? edit.edited : edit.original);
    results.clear();
    for (rung::check::SourceId id : changed) results.push_back(workspace.check_source(id));
  }
  // The benchmark must measure the case it is named after, on a project that stays clean.
  require_clean(workspace, results, what);
  if ((results.size() > 1) != expect_interface_change) {
    std::fprintf(stderr, "error: %s: the edit of %s re-checked %zu files, expected %s\n", what,
                 middle_function_block().c_str(), results.size(), expect_interface_change ? "all" : "one");
    std::exit(EXIT_FAILURE);
  }
  if (edited) workspace.update(edit.id, edit.original);
  state.counters["files_rechecked"] = static_cast<double>(results.size());
}

// A statement inside the FB body changes; the interface (everything outside bodies) does not.
void BM_RecheckAfterBodyEdit(benchmark::State& state) {
  static const Edit edit = make_edit(middle_function_block(), "nLoops := nLoops + 1;", "nLoops := nLoops + 2;");
  run_edit(state, edit, false, "BM_RecheckAfterBodyEdit, after Workspace::update");
}
BENCHMARK(BM_RecheckAfterBodyEdit)->Unit(benchmark::kMillisecond)->UseRealTime();

// A new VAR_INPUT in the FB: its callers and instances may be affected.
void BM_RecheckAfterInterfaceEdit(benchmark::State& state) {
  static const Edit edit = make_edit(middle_function_block(), "VAR_INPUT\n", "VAR_INPUT\n    bExtraInput : BOOL;\n");
  run_edit(state, edit, true, "BM_RecheckAfterInterfaceEdit, after Workspace::update");
}
BENCHMARK(BM_RecheckAfterInterfaceEdit)->Unit(benchmark::kMillisecond)->UseRealTime();

// --- Language server queries ---------------------------------------------------------------------

// Find references in the loaded project. Arg 0: TON, the library FB every program declares an
// instance of (the stubs are searched too). Arg 1: the middle cell's GVL_CellN.bStart, whose name
// every cell's list and program spell: the text prefilter passes hundreds of occurrences that
// resolution must reject as another cell's bStart.
void BM_FindReferences(benchmark::State& state) {
  const Workspace& workspace = edit_workspace();
  const rung::check::ProjectModel& model = workspace.model();
  const rung::check::Symbol* symbol = nullptr;
  if (state.range(0) == 0) {
    symbol = model.find_global("TON");
  } else if (const rung::check::Symbol* list = model.find_global("GVL_Cell" + std::to_string(kProjectFiles / 5 / 2))) {
    symbol = model.find_member(list, "bStart");
  }
  if (!symbol) {
    state.SkipWithError("the symbol is not in the generated project");
    return;
  }
  size_t found = 0;
  for (auto _ : state) {
    found = rung::check::query::find_references(workspace, symbol, true).size();
    benchmark::DoNotOptimize(found);
  }
  state.counters["references"] = static_cast<double>(found);
}
BENCHMARK(BM_FindReferences)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
