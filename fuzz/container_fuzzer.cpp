// Feeds arbitrary bytes to the vendor container readers (TwinCAT XML, CODESYS .EXP) through the
// document pipeline; the first byte picks the reader.
#include <cstddef>
#include <cstdint>
#include <string>

#include "parser/document.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  static const char* kNames[] = {"f.TcPOU", "f.TcDUT", "f.TcGVL", "f.TcIO", "f.EXP"};
  std::string name = kNames[data[0] % 5];
  std::string bytes(reinterpret_cast<const char*>(data + 1), size - 1);
  rung::Document doc = rung::Document::from_bytes(name, bytes);
  for (const auto& d : doc.diagnostics()) {
    if (d.range.end > doc.file_text().size()) __builtin_trap();
  }
  return 0;
}
