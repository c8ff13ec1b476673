// The three-way merge (`rung merge-file`) fed three versions of a file made of arbitrary bytes,
// checked by the merge property checker of the tests (tests/vcs/merge_properties.hpp): beyond
// no crash and no hang, no side's change lost silently and no unreadable file written. A
// violated property traps, with the properties that failed on stderr.
//
// Input: the first byte picks the file kind (plain ST, TwinCAT, CODESYS .EXP, PLCopen XML by
// content); the rest is base, ours and theirs separated by NUL bytes (PLC sources hold none;
// a missing version is the base). scripts/fuzz seeds the corpus with real files as all three.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string_view>

#include "tests/vcs/merge_properties.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  // Larger inputs only slow the search: the merge's cost grows with the diff, not its kind.
  if (size == 0 || size > 64 * 1024) return 0;
  static const char* kPaths[] = {"fuzz.st", "fuzz.TcPOU", "fuzz.EXP", "fuzz.xml"};
  const char* path = kPaths[data[0] % 4];
  std::string_view rest(reinterpret_cast<const char*>(data + 1), size - 1);
  std::string_view versions[3];
  for (int i = 0; i < 3; ++i) {
    const size_t nul = i < 2 ? rest.find('\0') : std::string_view::npos;
    versions[i] = rest.substr(0, nul);
    rest = nul == std::string_view::npos ? std::string_view() : rest.substr(nul + 1);
    if (nul == std::string_view::npos) {
      for (int j = i + 1; j < 3; ++j) versions[j] = versions[0];
      break;
    }
  }
  const rung::test::MergeCheck check = rung::test::check_merge(path, versions[0], versions[1], versions[2]);
  if (!check.violation.empty()) {
    std::fprintf(stderr, "merge property violated (%s):\n%s", path, check.violation.c_str());
    __builtin_trap();
  }
  return 0;
}
