// What the project-wide lint analyses need from every project file's text and declarations: which
// files hold a name as a word (the usage rules' prefilter) and how the project's declarations spell
// each name (L006). Building it reads the whole project's text, about 0.3 s for a million lines, so
// a caller that lints the same project again and again (the language server, after every
// keystroke) keeps one and lets each lint run refresh it: a refresh re-reads only the files whose
// revision changed since the last one (check::Source::revision).
//
// One pass over each file's words gathers everything here, since reading the text is the cost.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <mutex>
#include <unordered_set>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "checker/project_model.hpp"
#include "checker/symbols/names.hpp"

namespace rung::lint {

class ProjectIndex {
 public:
  // Brings the index up to date with `model`: files added or changed since the last refresh are
  // read again, the others cost one comparison. Not thread-safe; AnalysisCache calls it once per
  // lint run, before the run's threads read the index.
  void refresh(const check::ProjectModel& model);

  // Project files (not stub libraries) whose text holds `name` as a whole word (case-insensitive),
  // in id order. Comments count too: a prefilter, the caller's analysis decides.
  std::span<const check::SourceId> files_mentioning(std::string_view name) const;
  // Whether some project declaration spells `written` with other upper/lower case.
  bool spelled_otherwise(std::string_view written) const;
  // Whether project file `id`'s text holds a %Q address (comments count too: a prefilter).
  bool mentions_output_address(check::SourceId id) const { return id < files_.size() && files_[id].output_address; }

  // Names a file could not resolve, or leaves out by conditional compilation (see FileUsage).
  using NameSet = std::unordered_set<std::string, check::NameHash, check::NameEqual>;
  // Whether file `id` leaves `name` unresolved; `read` gives the file's names when they are not
  // known yet, or changed: they are kept while neither the file nor the project's declarations
  // change (Source::revision, ProjectModel::link_revision). Thread-safe.
  bool leaves_unresolved(const check::ProjectModel& model, check::SourceId id, std::string_view name,
                         const std::function<NameSet()>& read);

 private:
  // Spellings of one name (case-insensitive) among the project's declarations, with how many
  // declarations use each.
  using Spellings = std::map<std::string, uint32_t, std::less<>>;
  using WordMap = std::unordered_map<std::string, std::vector<check::SourceId>, check::NameHash, check::NameEqual>;
  using SpellingMap = std::unordered_map<std::string, Spellings, check::NameHash, check::NameEqual>;

  // What one file contributed, so that a refresh can take it back. Map nodes do not move when
  // their map grows, so the file keeps pointers to them.
  struct FileEntry {
    uint64_t revision = 0;
    bool output_address = false;
    std::vector<WordMap::value_type*> words;
    std::vector<std::pair<SpellingMap::value_type*, Spellings::iterator>> declarations;
  };

  void forget(check::SourceId id, FileEntry& entry);
  void read(const check::ProjectModel& model, check::SourceId id, FileEntry& entry);

  struct UnresolvedEntry {
    uint64_t revision = 0;
    uint64_t link_revision = 0;
    NameSet names;
  };

  std::vector<FileEntry> files_;
  std::mutex unresolved_mutex_;
  std::unordered_map<check::SourceId, UnresolvedEntry> unresolved_;
  WordMap words_;
  SpellingMap spellings_;
};

}  // namespace rung::lint
