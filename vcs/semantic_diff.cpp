#include "vcs/semantic_diff.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <map>
#include <string_view>
#include <utility>

#include "formatter/unified_diff.hpp"
#include "parser/keywords.hpp"

namespace rung::vcs {
namespace {

std::string object_key(const Object& object) {
  return fmt::format("{}\x01{}", object.name_space(), keywords::upper(object.name));
}

// "\x01" (the object's own name in keys) spelled as the name again, for people.
std::string shown(std::string_view key, std::string_view name) {
  std::string out;
  for (const char c : key) {
    if (c == '\x01') {
      out += name;
    } else {
      out += c;
    }
  }
  return out;
}

// Hunks of the unified diff of two texts (without the "---"/"+++" lines), and the line counts.
struct Hunks {
  std::string text;
  size_t added = 0;
  size_t removed = 0;
};

Hunks hunks(std::string_view before, std::string_view after, size_t context) {
  Hunks h;
  const std::string diff = format::unified_diff(before, after, "a", "b", context);
  size_t at = 0;
  int header_lines = 2;
  while (at < diff.size()) {
    size_t end = diff.find('\n', at);
    end = end == std::string::npos ? diff.size() : end + 1;
    const std::string_view line(diff.data() + at, end - at);
    if (header_lines > 0) {
      --header_lines;
    } else {
      h.text += line;
      if (!line.empty() && line[0] == '+') ++h.added;
      if (!line.empty() && line[0] == '-') ++h.removed;
    }
    at = end;
  }
  return h;
}

std::string declaration_shown(const Declaration& d) {
  std::string s = d.attributes.empty() ? std::string() : d.attributes + " ";
  return s + d.block + " " + d.text;
}

const Part* find_part(const std::vector<Part>& parts, std::string_view name) {
  const std::string wanted = keywords::upper(name);
  for (const Part& part : parts) {
    if (keywords::upper(part.name) == wanted) return &part;
  }
  return nullptr;
}

const Declaration* find_declaration(const std::vector<Declaration>& declarations, std::string_view name) {
  const std::string wanted = keywords::upper(name);
  for (const Declaration& d : declarations) {
    if (keywords::upper(d.name) == wanted) return &d;
  }
  return nullptr;
}

class Comparer {
 public:
  Comparer(const DiffOptions& options) : options_(options) {}

  void compare_parts(const Object& before, const Object& after, ObjectChange& change) const {
    for (const Part& old_part : before.parts) {
      if (find_part(after.parts, old_part.name) == nullptr)
        change.members.push_back({old_part.name, old_part.kind, "removed"});
    }
    for (const Part& new_part : after.parts) {
      const Part* old_part = find_part(before.parts, new_part.name);
      if (old_part == nullptr) {
        change.members.push_back({new_part.name, new_part.kind, "added"});
        continue;
      }
      compare_declarations(*old_part, new_part, before.name, after.name, change);
      compare_body(*old_part, new_part, before.name, after.name, change);
    }
  }

 private:
  void compare_declarations(const Part& before, const Part& after, std::string_view old_name, std::string_view new_name,
                            ObjectChange& change) const {
    if (before.declaration_key == after.declaration_key) return;
    const size_t first = change.declarations.size();
    if (before.header_key != after.header_key) {
      DeclarationChange c;
      c.member = after.name;
      c.what = {"header"};
      c.before = shown(before.header_key, old_name);
      c.after = shown(after.header_key, new_name);
      change.declarations.push_back(std::move(c));
    }
    for (const Declaration& d : before.declarations) {
      if (find_declaration(after.declarations, d.name) == nullptr) {
        change.declarations.push_back({after.name, d.name, {"removed"}, declaration_shown(d), {}, {}});
      }
    }
    for (const Declaration& d : after.declarations) {
      const Declaration* old = find_declaration(before.declarations, d.name);
      if (old == nullptr) {
        change.declarations.push_back({after.name, d.name, {"added"}, {}, declaration_shown(d), {}});
        continue;
      }
      std::vector<std::string> what;
      if (old->block != d.block) what.emplace_back("block");
      if (old->type_key != d.type_key) what.emplace_back("retyped");
      if (old->value_key != d.value_key) what.emplace_back("initial value");
      if (old->other_key != d.other_key) what.emplace_back("address");
      if (old->attributes != d.attributes) what.emplace_back("attributes");
      if (options_.comments && old->comment != d.comment) what.emplace_back("comment");
      if (old->name != d.name && what.empty()) what.emplace_back("renamed");
      if (what.empty()) continue;
      change.declarations.push_back(
          {after.name, d.name, std::move(what), declaration_shown(*old), declaration_shown(d), {}});
    }
    if (change.declarations.size() == first) {
      // The keys differ, yet no name did: order, block layout, comments between declarations.
      DeclarationChange c;
      c.member = after.name;
      c.what = {"declaration"};
      c.diff = hunks(before.declaration_text, after.declaration_text, options_.context).text;
      if (c.diff.empty())
        c.diff =
            fmt::format("-{}\n+{}\n", shown(before.declaration_key, old_name), shown(after.declaration_key, new_name));
      change.declarations.push_back(std::move(c));
    }
  }

  void compare_body(const Part& before, const Part& after, std::string_view old_name, std::string_view new_name,
                    ObjectChange& change) const {
    if (before.has_body == after.has_body && before.body_key == after.body_key) return;
    BodyChange body;
    body.member = after.name;
    body.kind = after.kind;
    Hunks h = hunks(before.body_text, after.body_text, options_.context);
    if (h.text.empty()) {
      // Same text, different meaning to the key (a renamed object referring to itself).
      h = hunks(shown(before.body_key, old_name) + "\n", shown(after.body_key, new_name) + "\n", options_.context);
    }
    body.diff = std::move(h.text);
    body.added_lines = h.added;
    body.removed_lines = h.removed;
    change.bodies.push_back(std::move(body));
  }

  const DiffOptions& options_;
};

bool has_details(const ObjectChange& change) {
  return !change.members.empty() || !change.declarations.empty() || !change.bodies.empty();
}

}  // namespace

DiffReport semantic_diff(const std::vector<FilePair>& files, const DiffOptions& options) {
  DiffReport report;
  ReadOptions read;
  read.comments = options.comments;
  std::vector<FileObjects> before_files;
  std::vector<FileObjects> after_files;
  for (const FilePair& pair : files) {
    ++report.files;
    for (const auto& [version, side] : {std::pair{&pair.before, &before_files}, std::pair{&pair.after, &after_files}}) {
      if (!*version) continue;
      FileObjects objects = read_objects((*version)->path, (*version)->bytes, read);
      for (const std::string& error : objects.errors) report.errors.push_back({(*version)->path, error});
      if (side == &after_files) {
        for (const std::string& note : objects.notes) report.notes.push_back({(*version)->path, note});
      }
      side->push_back(std::move(objects));
    }
  }
  // Same message from both versions of a file: once.
  std::sort(report.errors.begin(), report.errors.end(), [](const FileError& a, const FileError& b) {
    return std::tie(a.path, a.message) < std::tie(b.path, b.message);
  });
  report.errors.erase(
      std::unique(report.errors.begin(), report.errors.end(),
                  [](const FileError& a, const FileError& b) { return a.path == b.path && a.message == b.message; }),
      report.errors.end());

  std::vector<const Object*> old_objects;
  std::vector<const Object*> new_objects;
  for (const FileObjects& f : before_files) {
    for (const Object& o : f.objects) old_objects.push_back(&o);
  }
  for (const FileObjects& f : after_files) {
    for (const Object& o : f.objects) new_objects.push_back(&o);
  }
  std::vector<bool> old_used(old_objects.size(), false);
  std::vector<const Object*> new_match(new_objects.size(), nullptr);

  // 1. Same name (same file first).
  std::multimap<std::string, size_t> old_by_key;
  for (size_t i = 0; i < old_objects.size(); ++i) old_by_key.emplace(object_key(*old_objects[i]), i);
  for (int same_path = 1; same_path >= 0; --same_path) {
    for (size_t n = 0; n < new_objects.size(); ++n) {
      if (new_match[n] != nullptr) continue;
      const auto [begin, end] = old_by_key.equal_range(object_key(*new_objects[n]));
      for (auto it = begin; it != end; ++it) {
        if (old_used[it->second]) continue;
        if (same_path == 1 && old_objects[it->second]->path != new_objects[n]->path) continue;
        old_used[it->second] = true;
        new_match[n] = old_objects[it->second];
        break;
      }
    }
  }
  // 2. Same content under another name: renamed.
  std::multimap<std::string, size_t> old_by_content;
  for (size_t i = 0; i < old_objects.size(); ++i) {
    if (!old_used[i]) old_by_content.emplace(old_objects[i]->content_key(), i);
  }
  for (size_t n = 0; n < new_objects.size(); ++n) {
    if (new_match[n] != nullptr) continue;
    const auto [begin, end] = old_by_content.equal_range(new_objects[n]->content_key());
    for (auto it = begin; it != end; ++it) {
      if (old_used[it->second]) continue;
      old_used[it->second] = true;
      new_match[n] = old_objects[it->second];
      break;
    }
  }

  const Comparer comparer(options);
  for (size_t n = 0; n < new_objects.size(); ++n) {
    const Object& after = *new_objects[n];
    ObjectChange change;
    change.kind = after.kind;
    change.name = after.name;
    change.path = after.path;
    const Object* before = new_match[n];
    if (before == nullptr) {
      change.change = "added";
      report.changes.push_back(std::move(change));
      continue;
    }
    if (before->name != after.name) change.old_name = before->name;
    if (before->path != after.path) change.old_path = before->path;
    comparer.compare_parts(*before, after, change);
    if (!has_details(change) && change.old_name.empty() && change.old_path.empty()) continue;
    change.change = has_details(change) ? "modified" : !change.old_name.empty() ? "renamed" : "moved";
    report.changes.push_back(std::move(change));
  }
  for (size_t i = 0; i < old_objects.size(); ++i) {
    if (old_used[i]) continue;
    ObjectChange change;
    change.change = "removed";
    change.kind = old_objects[i]->kind;
    change.name = old_objects[i]->name;
    change.path = old_objects[i]->path;
    report.changes.push_back(std::move(change));
  }
  std::stable_sort(report.changes.begin(), report.changes.end(), [](const ObjectChange& a, const ObjectChange& b) {
    return std::tie(a.path, a.name) < std::tie(b.path, b.name);
  });
  return report;
}

}  // namespace rung::vcs
