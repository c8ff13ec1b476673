// Where tests find their data: the repository, the shared corpus beside it, the rung binary.
#pragma once

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace rung::test {

// The repository, the shared corpus (../shared) and the built rung. Defined in test_paths.cpp,
// the one file compiled with these paths, so that the other test files do not depend on where the
// clone is (ccache then reuses their objects across clones, as CI's).
std::filesystem::path source_dir();
std::filesystem::path shared_dir();
std::filesystem::path rung_binary();

inline std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

inline void write_file(const std::filesystem::path& path, const std::string& text) {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream out(path, std::ios::binary);
  out << text;
}

// Golden files are rewritten instead of compared when RUNG_UPDATE_GOLDEN=1.
inline bool update_golden() {
  const char* v = std::getenv("RUNG_UPDATE_GOLDEN");
  return v && std::string(v) == "1";
}

}  // namespace rung::test
