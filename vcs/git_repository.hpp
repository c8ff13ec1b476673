// The git side of `rung diff` and `rung git setup`, over libgit2 (never the git command): which
// PLC source files differ between two revisions, the index and the working tree, with the bytes
// of both versions. Only the blobs of files that differ are read.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "vcs/semantic_diff.hpp"

namespace rung::vcs {

// What to compare, as `git diff` takes it:
//   no revision:  the index and the working tree (with `cached`: HEAD and the index)
//   one:          that revision and the working tree (with `cached`: and the index)
//   two, or A..B: the two revisions
struct DiffSpec {
  std::vector<std::string> revisions;
  bool cached = false;
  std::vector<std::string> paths;  // pathspecs, relative to `folder`
};

struct ChangedFiles {
  std::vector<FilePair> files;  // repository-relative paths, sorted
  std::string error;            // set when the repository or a revision cannot be read
};

// `folder` is any folder inside the repository's working tree (or the repository itself).
ChangedFiles changed_plc_files(const std::string& folder, const DiffSpec& spec);

// The bytes of a file; nullopt when it cannot be opened or read.
std::optional<std::string> read_file_bytes(const std::string& path);

// The repository's working tree holding `folder` ("" and `error` set when there is none).
std::string repository_root(const std::string& folder, std::string* error);

// Sets `name` = `value` in the repository's config (`global`: the user's ~/.gitconfig).
bool set_git_config(const std::string& folder, bool global, const std::string& name, const std::string& value,
                    std::string* error);

}  // namespace rung::vcs
