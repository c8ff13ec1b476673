// Loads many files on several threads and hands the documents back in input order, one at a time,
// so output stays deterministic and only a window of documents is held in memory.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "parser/document.hpp"

namespace rung {

struct LoadedDocument {
  std::filesystem::path path;
  std::optional<Document> document;  // nullopt when the file could not be read
  std::string error;                 // why it could not be read
};

// Calls `consume` for each path in order. `threads` = 0 picks the hardware concurrency.
void load_documents_in_order(const std::vector<std::filesystem::path>& paths, unsigned threads,
                             const std::function<void(LoadedDocument&)>& consume);

}  // namespace rung
