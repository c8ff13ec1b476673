// `rung diff` between two revisions of a generated 10,000-file repository that differ in 20
// files (issue 17: under one second; docs/performance.md). The repository is written with
// libgit2 straight into a bare object database (no working tree), once per run.
#include <benchmark/benchmark.h>
#include <git2.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "bench/generated_source.hpp"
#include "vcs/git_repository.hpp"
#include "vcs/semantic_diff.hpp"

namespace {

namespace fs = std::filesystem;

constexpr int kFiles = 10000;
constexpr int kFilesPerFolder = 100;
constexpr int kChanged = 20;

std::string pou_text(int file, int version) {
  // ~50 lines of generated POUs per file; the changed version adds a function.
  std::string text = rung::bench::generate_st(50, static_cast<unsigned>(file + 1));
  if (version > 0)
    text += "(* changed *)\nFUNCTION F_Extra_" + std::to_string(file) + " : INT\nF_Extra_" + std::to_string(file) +
            " := 1;\nEND_FUNCTION\n";
  return text;
}

// Writes a commit whose tree holds kFiles files in folders of kFilesPerFolder; files below
// `changed` get version 1.
git_oid write_commit(git_repository* repo, int changed, const git_oid* parent) {
  git_treebuilder* root = nullptr;
  git_treebuilder_new(&root, repo, nullptr);
  for (int folder = 0; folder < kFiles / kFilesPerFolder; ++folder) {
    git_treebuilder* sub = nullptr;
    git_treebuilder_new(&sub, repo, nullptr);
    for (int i = 0; i < kFilesPerFolder; ++i) {
      const int file = folder * kFilesPerFolder + i;
      const std::string text = pou_text(file, file % (kFiles / kChanged) == 0 && changed > 0 ? 1 : 0);
      git_oid blob{};
      git_blob_create_from_buffer(&blob, repo, text.data(), text.size());
      git_treebuilder_insert(nullptr, sub, ("FB_" + std::to_string(file) + ".st").c_str(), &blob, GIT_FILEMODE_BLOB);
    }
    git_oid sub_id{};
    git_treebuilder_write(&sub_id, sub);
    git_treebuilder_free(sub);
    git_treebuilder_insert(nullptr, root, ("folder" + std::to_string(folder)).c_str(), &sub_id, GIT_FILEMODE_TREE);
  }
  git_oid tree_id{};
  git_treebuilder_write(&tree_id, root);
  git_treebuilder_free(root);
  git_tree* tree = nullptr;
  git_tree_lookup(&tree, repo, &tree_id);
  git_signature* who = nullptr;
  git_signature_new(&who, "bench", "bench@example.com", 1767225600, 0);
  git_commit* parent_commit = nullptr;
  if (parent != nullptr) git_commit_lookup(&parent_commit, repo, parent);
  const git_commit* parents[1] = {parent_commit};
  git_oid commit{};
  git_commit_create(&commit, repo, "HEAD", who, who, nullptr, "bench", tree, parent != nullptr ? 1 : 0, parents);
  if (parent_commit != nullptr) git_commit_free(parent_commit);
  git_signature_free(who);
  git_tree_free(tree);
  return commit;
}

const fs::path& bench_repository() {
  static const fs::path path = [] {
    const fs::path p = fs::temp_directory_path() / ("rung_vcs_bench_" + std::to_string(getpid()));
    fs::remove_all(p);
    git_libgit2_init();
    git_repository* repo = nullptr;
    git_repository_init(&repo, p.c_str(), 1);
    const git_oid first = write_commit(repo, 0, nullptr);
    write_commit(repo, kChanged, &first);
    git_repository_free(repo);
    git_libgit2_shutdown();
    return p;
  }();
  return path;
}

void BM_DiffTwoRevisions10000Files(benchmark::State& state) {
  const fs::path& repo = bench_repository();
  rung::vcs::DiffSpec spec;
  spec.revisions = {"HEAD~1", "HEAD"};
  size_t changes = 0;
  for (auto _ : state) {
    const rung::vcs::ChangedFiles files = rung::vcs::changed_plc_files(repo.string(), spec);
    const rung::vcs::DiffReport report = rung::vcs::semantic_diff(files.files);
    changes = report.changes.size();
    benchmark::DoNotOptimize(report);
  }
  state.counters["changed_objects"] = static_cast<double>(changes);
}
BENCHMARK(BM_DiffTwoRevisions10000Files)->Unit(benchmark::kMillisecond);

}  // namespace
