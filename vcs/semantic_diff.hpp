// The semantic diff of two versions of a set of files: which objects (POUs, types, GVLs) were
// added, removed, renamed or moved, and for the others which declarations, members and bodies
// changed. Only the files given are read: callers pass the files that differ.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "vcs/object_model.hpp"

namespace rung::vcs {

struct FileVersion {
  std::string path;
  std::string bytes;
};

// One changed file: `before` is empty for a new file, `after` for a deleted one.
struct FilePair {
  std::optional<FileVersion> before;
  std::optional<FileVersion> after;
};

struct DiffOptions {
  bool comments = false;  // comment-only changes count
  size_t context = 3;     // lines of context in body diffs
};

// A declaration that differs: a variable, field or enum value; or, with `name` empty, the
// declaration of a member as a whole (its header, or what the per-name comparison cannot say).
struct DeclarationChange {
  std::string member;  // "" for the object itself, else the member's qualified name
  std::string name;    // the declared name; "" for a change of the whole declaration
  // "added", "removed", or what changed: "retyped", "initial value", "attributes", "block",
  // "address", "comment", "header", "declaration"
  std::vector<std::string> what;
  std::string before;  // "VAR nState : INT" (empty when added)
  std::string after;
  std::string diff;  // for "declaration": unified hunks of the declaration text
};

struct MemberChange {
  std::string member;  // qualified name
  std::string kind;    // "METHOD", "ACTION", "GET", ...
  std::string change;  // "added" or "removed"
};

struct BodyChange {
  std::string member;  // "" for the object's own body
  std::string kind;
  std::string diff;  // unified hunks ("@@ -1,2 +1,2 @@" ...) of the formatted body
  size_t added_lines = 0;
  size_t removed_lines = 0;
};

struct ObjectChange {
  std::string change;  // "added", "removed", "modified", "renamed", "moved"
  std::string kind;
  std::string name;
  std::string path;      // where it is now (for "removed": where it was)
  std::string old_name;  // set when renamed
  std::string old_path;  // set when moved between files
  std::vector<MemberChange> members;
  std::vector<DeclarationChange> declarations;
  std::vector<BodyChange> bodies;
};

struct FileError {
  std::string path;
  std::string message;
};

struct DiffReport {
  std::vector<ObjectChange> changes;  // sorted by path, then name
  std::vector<FileError> errors;      // files or parts that could not be read
  std::vector<FileError> notes;       // parts not compared (graphical bodies)
  size_t files = 0;                   // files compared
};

DiffReport semantic_diff(const std::vector<FilePair>& files, const DiffOptions& options = {});

}  // namespace rung::vcs
