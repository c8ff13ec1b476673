// Feeds arbitrary bytes to the whole pipeline of a plain source file: decode, parse, diagnostics,
// the lossless token walk, and an incremental edit.
#include <cstddef>
#include <cstdint>
#include <string>

#include "parser/document.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::string bytes(reinterpret_cast<const char*>(data), size);
  rung::Document doc = rung::Document::from_bytes("fuzz.st", bytes);
  for (const auto& d : doc.diagnostics()) {
    if (d.range.end > doc.file_text().size()) __builtin_trap();
  }
  if (rung::SyntaxTree* tree = doc.mutable_tree()) {
    size_t covered = 0;
    tree->for_each_token([&](const rung::Token& t) { covered += t.range.end - t.range.begin; });
    if (covered != tree->text().size()) __builtin_trap();
    uint32_t mid = static_cast<uint32_t>(tree->text().size() / 2);
    tree->apply_edit(mid, mid + 1, "(*");
  }
  return 0;
}
