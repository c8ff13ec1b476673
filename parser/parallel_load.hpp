// Loads many files on several threads and hands the documents back in input order, one at a time,
// so output stays deterministic and only a window of documents is held in memory.
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "parser/document.hpp"

namespace rung {

struct LoadedDocument {
  size_t index = 0;  // position in the list of paths
  std::filesystem::path path;
  // Null when the file could not be read. On the heap so that views into its text and tree
  // (taken by `prepare` on a worker thread) stay valid when the consumer takes it over.
  std::unique_ptr<Document> document;
  std::string error;  // why it could not be read
};

// Calls `consume` for each path in order. `threads` = 0 picks the hardware concurrency.
// `prepare`, if given, runs right after a document is loaded, on the loading thread, so that
// per-file work that needs no other file (the checker's symbol pass) runs in parallel too;
// calls for different documents may run at the same time.
void load_documents_in_order(const std::vector<std::filesystem::path>& paths, unsigned threads,
                             const std::function<void(LoadedDocument&)>& consume,
                             const std::function<void(LoadedDocument&)>& prepare = {});

}  // namespace rung
