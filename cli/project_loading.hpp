// How a command finds and loads the project it works on (`rung check`, `rung lint`): the nearest
// rung.toml at or above the first path, its findings printed as diagnostics, then the workspace
// of the project (or, without a rung.toml, of the files and folders named).
#pragma once

#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "checker/check.hpp"
#include "checker/project/project_config.hpp"
#include "cli/terminal.hpp"

namespace rung::cli {

struct ConfigLoad {
  project::LoadedConfig loaded;
  std::optional<std::filesystem::path> root;  // the folder of rung.toml; none without one
  bool has_errors = false;                    // rung.toml has errors (P001, P003)
};

// Reads the rung.toml that applies to files in `start` and prints its findings to `err`.
ConfigLoad load_config_reporting(const std::filesystem::path& start, const Style& style, std::FILE* err);

struct ProjectLoadOptions {
  std::vector<std::string> paths;           // files or folders; default: the current folder
  std::optional<project::Profile> profile;  // overrides rung.toml
  unsigned threads = 0;
};

struct LoadedProject {
  ConfigLoad config;
  std::unique_ptr<check::Workspace> workspace;  // its load_errors were printed
  std::vector<std::filesystem::path> scopes;    // the paths named, absolute

  // Whether a file of the workspace is one the user asked about (the whole project is read so
  // that names resolve, but only these files are reported).
  bool in_scope(const std::string& file) const;
  // Where project-relative paths start: the folder of rung.toml, else the first path's folder.
  const std::filesystem::path& root() const { return config.loaded.config.root; }
};

// nullopt (after printing why) when a path does not exist.
std::optional<LoadedProject> load_project(const ProjectLoadOptions& options, const Style& style, std::FILE* err);

// The process ends right after a command: the workspace is left to the operating system.
void keep_until_exit(std::unique_ptr<check::Workspace> workspace);

}  // namespace rung::cli
