// Where tests find their data: the repository, the shared corpus beside it, the rung binary.
#pragma once

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace rung::test {

inline std::filesystem::path source_dir() {
  return RUNG_SOURCE_DIR;
}
inline std::filesystem::path shared_dir() {
  return RUNG_SHARED_DIR;
}
inline std::filesystem::path rung_binary() {
  return RUNG_BINARY;
}

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
