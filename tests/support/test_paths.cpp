// The paths of tests/support/test_paths.hpp, from tests/CMakeLists.txt's definitions.
#include "tests/support/test_paths.hpp"

namespace rung::test {

std::filesystem::path source_dir() {
  return RUNG_SOURCE_DIR;
}
std::filesystem::path shared_dir() {
  return RUNG_SHARED_DIR;
}
std::filesystem::path rung_binary() {
  return RUNG_BINARY;
}

}  // namespace rung::test
