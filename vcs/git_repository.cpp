#include "vcs/git_repository.hpp"

#include <fmt/format.h>
#include <git2.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <sstream>
#include <utility>

namespace rung::vcs {
namespace {

namespace fs = std::filesystem;

// libgit2 is initialised while one of these lives.
class Library {
 public:
  Library() { git_libgit2_init(); }
  ~Library() { git_libgit2_shutdown(); }
  Library(const Library&) = delete;
  Library& operator=(const Library&) = delete;
};

template <typename T, void (*Free)(T*)>
struct Deleter {
  void operator()(T* p) const {
    if (p != nullptr) Free(p);
  }
};
using Repository = std::unique_ptr<git_repository, Deleter<git_repository, git_repository_free>>;
using Tree = std::unique_ptr<git_tree, Deleter<git_tree, git_tree_free>>;
using GitObject = std::unique_ptr<git_object, Deleter<git_object, git_object_free>>;
using Diff = std::unique_ptr<git_diff, Deleter<git_diff, git_diff_free>>;
using Index = std::unique_ptr<git_index, Deleter<git_index, git_index_free>>;
using Blob = std::unique_ptr<git_blob, Deleter<git_blob, git_blob_free>>;
using Config = std::unique_ptr<git_config, Deleter<git_config, git_config_free>>;

std::string last_error(std::string_view what) {
  const git_error* e = git_error_last();
  return e != nullptr && e->message != nullptr ? fmt::format("{}: {}", what, e->message) : std::string(what);
}

Repository open_repository(const std::string& folder, std::string* error) {
  git_repository* repo = nullptr;
  if (git_repository_open_ext(&repo, folder.empty() ? "." : folder.c_str(), 0, nullptr) != 0) {
    *error = last_error(
        fmt::format("not a git repository (or any parent up to the root): {}", folder.empty() ? "." : folder));
    return nullptr;
  }
  return Repository(repo);
}

// The tree of a revision ("HEAD", "main~2", a commit id); null with `error` set when there is
// none. An unborn HEAD is the empty tree (null, no error).
Tree tree_of(git_repository* repo, const std::string& revision, std::string* error) {
  git_object* object = nullptr;
  if (git_revparse_single(&object, repo, revision.c_str()) != 0) {
    if (revision == "HEAD" && git_repository_head_unborn(repo) == 1) return nullptr;
    *error = last_error(fmt::format("unknown revision '{}'", revision));
    return nullptr;
  }
  const GitObject owned(object);
  git_object* peeled = nullptr;
  if (git_object_peel(&peeled, object, GIT_OBJECT_TREE) != 0) {
    *error = last_error(fmt::format("'{}' does not name a tree", revision));
    return nullptr;
  }
  return Tree(reinterpret_cast<git_tree*>(peeled));
}

std::optional<std::string> read_blob(git_repository* repo, const git_oid& id) {
  git_blob* blob = nullptr;
  if (git_blob_lookup(&blob, repo, &id) != 0) return std::nullopt;
  const Blob owned(blob);
  const auto* data = static_cast<const char*>(git_blob_rawcontent(blob));
  return std::string(data, static_cast<size_t>(git_blob_rawsize(blob)));
}

// The pathspec of `path` given relative to `folder`, as relative to the working tree.
std::string repository_relative(const fs::path& workdir, const fs::path& folder, const std::string& path) {
  std::error_code ec;
  const fs::path absolute = fs::weakly_canonical(fs::absolute(folder / path, ec), ec);
  fs::path root = fs::weakly_canonical(workdir, ec);
  if (!root.has_filename()) root = root.parent_path();  // libgit2's workdir ends with '/'
  const fs::path relative = absolute.lexically_relative(root);
  const std::string s = relative.generic_string();
  return s == "." ? std::string() : s;
}

}  // namespace

std::optional<std::string> read_file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream s;
  s << in.rdbuf();
  if (in.bad()) return std::nullopt;
  return s.str();
}

ChangedFiles changed_plc_files(const std::string& folder, const DiffSpec& spec) {
  const Library library;
  ChangedFiles result;
  const Repository repo = open_repository(folder, &result.error);
  if (!repo) return result;
  const char* workdir_c = git_repository_workdir(repo.get());
  const fs::path workdir = workdir_c != nullptr ? fs::path(workdir_c) : fs::path();

  std::vector<std::string> revisions = spec.revisions;
  if (revisions.size() == 1) {
    const size_t dots = revisions[0].find("..");
    if (dots != std::string::npos && revisions[0].find("...") == std::string::npos) {
      const std::string a = revisions[0].substr(0, dots);
      const std::string b = revisions[0].substr(dots + 2);
      revisions = {a.empty() ? "HEAD" : a, b.empty() ? "HEAD" : b};
    }
  }
  if (revisions.size() > 2) {
    result.error = "at most two revisions";
    return result;
  }
  if (revisions.size() == 2 && spec.cached) {
    result.error = "--cached compares a revision with the index: give at most one revision";
    return result;
  }
  const bool needs_workdir = !spec.cached && revisions.size() < 2;
  if (needs_workdir && workdir.empty()) {
    result.error = "a bare repository has no working tree: give two revisions";
    return result;
  }

  std::vector<std::string> pathspecs;
  pathspecs.reserve(spec.paths.size());
  for (const std::string& p : spec.paths)
    pathspecs.push_back(repository_relative(workdir, folder.empty() ? "." : folder, p));
  std::vector<char*> pathspec_pointers;
  pathspec_pointers.reserve(pathspecs.size());
  for (std::string& p : pathspecs) pathspec_pointers.push_back(p.data());

  git_diff_options options = GIT_DIFF_OPTIONS_INIT;
  options.flags = GIT_DIFF_IGNORE_SUBMODULES;
  options.pathspec.strings = pathspec_pointers.data();
  options.pathspec.count = pathspec_pointers.size();

  git_diff* diff = nullptr;
  int rc = 0;
  bool new_side_on_disk = false;
  if (revisions.size() == 2) {
    const Tree a = tree_of(repo.get(), revisions[0], &result.error);
    if (!result.error.empty()) return result;
    const Tree b = tree_of(repo.get(), revisions[1], &result.error);
    if (!result.error.empty()) return result;
    rc = git_diff_tree_to_tree(&diff, repo.get(), a.get(), b.get(), &options);
  } else if (spec.cached) {
    const Tree a = tree_of(repo.get(), revisions.empty() ? "HEAD" : revisions[0], &result.error);
    if (!result.error.empty()) return result;
    rc = git_diff_tree_to_index(&diff, repo.get(), a.get(), nullptr, &options);
  } else if (revisions.size() == 1) {
    const Tree a = tree_of(repo.get(), revisions[0], &result.error);
    if (!result.error.empty()) return result;
    rc = git_diff_tree_to_workdir_with_index(&diff, repo.get(), a.get(), &options);
    new_side_on_disk = true;
  } else {
    rc = git_diff_index_to_workdir(&diff, repo.get(), nullptr, &options);
    new_side_on_disk = true;
  }
  if (rc != 0) {
    result.error = last_error("cannot compare");
    return result;
  }
  const Diff owned_diff(diff);

  const size_t deltas = git_diff_num_deltas(diff);
  for (size_t i = 0; i < deltas; ++i) {
    const git_diff_delta* delta = git_diff_get_delta(diff, i);
    const std::string old_path = delta->old_file.path != nullptr ? delta->old_file.path : "";
    const std::string new_path = delta->new_file.path != nullptr ? delta->new_file.path : old_path;
    const bool has_old = delta->status != GIT_DELTA_ADDED && delta->status != GIT_DELTA_UNTRACKED;
    const bool has_new = delta->status != GIT_DELTA_DELETED;
    // A cheap look at the name first: only PLC sources (and .xml files, judged by content) are read.
    const auto wanted = [](const std::string& path) {
      const bool xml = path.size() >= 4 &&
                       (path.compare(path.size() - 4, 4, ".xml") == 0 || path.compare(path.size() - 4, 4, ".XML") == 0);
      return xml || is_plc_source_path(path);
    };
    if (!(has_old && wanted(old_path)) && !(has_new && wanted(new_path))) continue;
    FilePair pair;
    if (has_old) {
      std::optional<std::string> bytes = read_blob(repo.get(), delta->old_file.id);
      if (!bytes) {
        result.error = last_error(fmt::format("cannot read {} in the old version", old_path));
        return result;
      }
      if (is_plc_source_path(old_path, *bytes)) pair.before = FileVersion{old_path, std::move(*bytes)};
    }
    if (has_new) {
      std::optional<std::string> bytes =
          new_side_on_disk ? read_file_bytes((workdir / new_path).string()) : read_blob(repo.get(), delta->new_file.id);
      if (!bytes && new_side_on_disk &&
          (delta->new_file.mode == GIT_FILEMODE_UNREADABLE || !fs::exists(workdir / new_path))) {
        bytes = std::string();
      }
      if (!bytes) {
        result.error = last_error(fmt::format("cannot read {}", new_path));
        return result;
      }
      if (is_plc_source_path(new_path, *bytes)) pair.after = FileVersion{new_path, std::move(*bytes)};
    }
    if (pair.before || pair.after) result.files.push_back(std::move(pair));
  }
  return result;
}

std::string repository_root(const std::string& folder, std::string* error) {
  const Library library;
  const Repository repo = open_repository(folder, error);
  if (!repo) return {};
  const char* workdir = git_repository_workdir(repo.get());
  if (workdir == nullptr) {
    *error = "a bare repository has no working tree";
    return {};
  }
  return workdir;
}

bool set_git_config(const std::string& folder, bool global, const std::string& name, const std::string& value,
                    std::string* error) {
  const Library library;
  git_config* config = nullptr;
  if (global) {
    git_buf path = GIT_BUF_INIT;
    std::string file;
    if (git_config_find_global(&path) == 0) {
      file = path.ptr;
    } else {
      const char* home = std::getenv("HOME");
      if (home == nullptr) {
        *error = "HOME is not set: cannot find the global git config";
        return false;
      }
      file = (fs::path(home) / ".gitconfig").string();
    }
    git_buf_dispose(&path);
    if (git_config_open_ondisk(&config, file.c_str()) != 0) {
      *error = last_error(fmt::format("cannot open {}", file));
      return false;
    }
  } else {
    const Repository repo = open_repository(folder, error);
    if (!repo) return false;
    git_config* all = nullptr;
    if (git_repository_config(&all, repo.get()) != 0) {
      *error = last_error("cannot open the repository's config");
      return false;
    }
    const Config owned_all(all);
    if (git_config_open_level(&config, all, GIT_CONFIG_LEVEL_LOCAL) != 0) {
      *error = last_error("cannot open the repository's config");
      return false;
    }
  }
  const Config owned(config);
  if (git_config_set_string(config, name.c_str(), value.c_str()) != 0) {
    *error = last_error(fmt::format("cannot set {}", name));
    return false;
  }
  return true;
}

}  // namespace rung::vcs
