#include "checker/lint/project_index.hpp"

#include <algorithm>

#include "checker/symbols/names.hpp"

namespace rung::lint {
namespace {

bool is_word_start(char c) {
  return check::is_identifier_char(c) && !(c >= '0' && c <= '9');
}

}  // namespace

void ProjectIndex::refresh(const check::ProjectModel& model) {
  if (files_.size() > model.source_count()) {
    // Another model (a reloaded project): start over.
    for (check::SourceId id = 0; id < files_.size(); ++id) forget(id, files_[id]);
    files_.clear();
  }
  files_.resize(model.source_count());
  for (check::SourceId id = 0; id < files_.size(); ++id) {
    const check::Source& source = model.source(id);
    FileEntry& entry = files_[id];
    if (entry.revision == source.revision) continue;
    forget(id, entry);
    entry.revision = source.revision;
    if (!source.library) read(model, id, entry);
  }
}

void ProjectIndex::forget(check::SourceId id, FileEntry& entry) {
  for (WordMap::value_type* word : entry.words) {
    std::vector<check::SourceId>& files = word->second;
    const auto at = std::lower_bound(files.begin(), files.end(), id);
    if (at != files.end() && *at == id) files.erase(at);
    if (files.empty()) words_.erase(words_.find(word->first));  // by iterator: the key lives in the node
  }
  for (auto& [name, spelling] : entry.declarations) {
    if (--spelling->second == 0) name->second.erase(spelling);
    if (name->second.empty()) spellings_.erase(spellings_.find(name->first));
  }
  entry.output_address = false;
  entry.words.clear();
  entry.declarations.clear();
}

void ProjectIndex::read(const check::ProjectModel& model, check::SourceId id, FileEntry& entry) {
  const check::Source& source = model.source(id);
  if (const SyntaxTree* tree = source.document->tree()) {
    const std::string_view text = tree->text();
    for (size_t at = 0; at < text.size();) {
      if (!check::is_identifier_char(text[at])) {
        ++at;
        continue;
      }
      size_t end = at;
      while (end < text.size() && check::is_identifier_char(text[end])) ++end;
      if (is_word_start(text[at])) {
        if (at > 0 && text[at - 1] == '%' && (text[at] == 'Q' || text[at] == 'q')) entry.output_address = true;
        const std::string_view word = text.substr(at, end - at);
        auto found = words_.find(word);
        if (found == words_.end()) found = words_.emplace(std::string(word), std::vector<check::SourceId>{}).first;
        // Files are read in id order on the first refresh, later ones may come in any order.
        std::vector<check::SourceId>& files = found->second;
        const auto place = std::lower_bound(files.begin(), files.end(), id);
        if (place == files.end() || *place != id) {
          files.insert(place, id);
          entry.words.push_back(&*found);
        }
      }
      at = end;
    }
  }
  for (const check::Symbol& symbol : source.symbols.storage) {
    if (symbol.name.empty()) continue;
    auto name = spellings_.find(symbol.name);
    if (name == spellings_.end()) name = spellings_.emplace(std::string(symbol.name), Spellings{}).first;
    auto spelling = name->second.find(symbol.name);
    if (spelling == name->second.end()) spelling = name->second.emplace(std::string(symbol.name), 0).first;
    ++spelling->second;
    entry.declarations.emplace_back(&*name, spelling);
  }
}

std::span<const check::SourceId> ProjectIndex::files_mentioning(std::string_view name) const {
  const auto found = words_.find(name);
  if (found == words_.end()) return {};
  return found->second;
}

bool ProjectIndex::spelled_otherwise(std::string_view written) const {
  const auto found = spellings_.find(written);
  if (found == spellings_.end()) return false;
  const Spellings& spellings = found->second;
  return spellings.size() > 1 || spellings.begin()->first != written;
}

bool ProjectIndex::leaves_unresolved(const check::ProjectModel& model, check::SourceId id, std::string_view name,
                                     const std::function<NameSet()>& read) {
  const uint64_t revision = model.source(id).revision;
  {
    std::lock_guard lock(unresolved_mutex_);
    const auto found = unresolved_.find(id);
    if (found != unresolved_.end() && found->second.revision == revision &&
        found->second.link_revision == model.link_revision()) {
      return found->second.names.contains(name);
    }
  }
  // Read outside the lock: other threads go on with other files (two reading the same file at
  // once compute the same set).
  NameSet names = read();
  const bool holds = names.contains(name);
  std::lock_guard lock(unresolved_mutex_);
  unresolved_[id] = UnresolvedEntry{revision, model.link_revision(), std::move(names)};
  return holds;
}

}  // namespace rung::lint
