#include "cli/init_command.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <fstream>

#include "checker/project/project_config.hpp"

namespace rung::cli {

int run_init_command(const std::string& directory, bool force, std::FILE* out, std::FILE* err) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::path dir = directory.empty() ? fs::current_path(ec) : fs::path(directory);
  if (!fs::is_directory(dir, ec)) {
    fmt::print(err, "error: {}: not a folder\n", dir.string());
    return 2;
  }
  fs::path file = dir / "rung.toml";
  if (fs::exists(file, ec) && !force) {
    fmt::print(err, "error: {} already exists (use --force to overwrite it)\n", file.string());
    return 2;
  }
  std::string name = fs::absolute(dir, ec).lexically_normal().filename().string();
  if (name.empty()) name = fs::absolute(dir, ec).lexically_normal().parent_path().filename().string();
  std::ofstream stream(file, std::ios::binary | std::ios::trunc);
  stream << project::default_config_text(name);
  stream.close();
  if (!stream) {
    fmt::print(err, "error: {}: cannot write the file\n", file.string());
    return 2;
  }
  fmt::print(out, "Created {}\n", file.string());
  return 0;
}

}  // namespace rung::cli
