// A generated multi-file ST project for the checker benchmarks: "cells" of five files each (data
// types, a global variable list, functions, a function block with methods, a program) that
// reference each other and the cell before them, about 100 lines per file. Deterministic for a
// seed, and written to check without errors in the CODESYS profile (the benchmarks assert it).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace rung::bench {

struct GeneratedFile {
  std::string name;  // file name, e.g. "FB_Axis12.st"
  std::string text;
  size_t lines = 0;
};

struct GeneratedProject {
  std::vector<GeneratedFile> files;
  size_t lines = 0;
  size_t bytes = 0;
};

// Exactly `files` files, in dependency order (a prefix of a larger project is a valid project).
GeneratedProject generate_project(size_t files, unsigned seed = 1);

// The project's files as (path, text) pairs, the input of Workspace::from_texts.
std::vector<std::pair<std::string, std::string>> project_texts(const GeneratedProject& project);

// Writes every file into `folder` (created if missing); existing files of the same name are
// replaced. Returns false (and says why in `error`) if a file cannot be written.
bool write_project(const GeneratedProject& project, const std::filesystem::path& folder, std::string& error);

}  // namespace rung::bench
