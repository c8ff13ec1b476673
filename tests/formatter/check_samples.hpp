// Inputs the formatter's safety-check tests share: a small program with comments, a string and
// an IF, and the files of the seed corpus.
#pragma once

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "tests/support/test_paths.hpp"

namespace rung::format::test_samples {

inline const std::string kProgram =
    "PROGRAM Main\n"
    "VAR\n"
    "    x : INT; // counter\n"
    "    s : STRING := 'abc';\n"
    "END_VAR\n"
    "(* body *)\n"
    "IF x > 0 THEN\n"
    "    x := x - 1;\n"
    "END_IF\n"
    "END_PROGRAM\n";

// Every file of ../shared/corpus/seeds, sorted; empty when the corpus is not there.
inline std::vector<std::filesystem::path> seed_files() {
  const std::filesystem::path root = test::shared_dir() / "corpus" / "seeds";
  std::vector<std::filesystem::path> files;
  if (!std::filesystem::is_directory(root)) return files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(root))
    if (entry.is_regular_file()) files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace rung::format::test_samples
