#include "cli/textconv_command.hpp"

#include <fmt/format.h>

#include <optional>
#include <string>

#include "vcs/git_repository.hpp"
#include "vcs/object_model.hpp"

namespace rung::cli {

int run_textconv_command(const std::string& path, std::FILE* out, std::FILE* err) {
  const std::optional<std::string> read = vcs::read_file_bytes(path);
  if (!read) {
    fmt::print(err, "rung textconv: {}: cannot open file\n", path);
    return 2;
  }
  const std::string& bytes = *read;
  const vcs::TextView view = vcs::text_view(path, bytes);
  for (const std::string& error : view.errors) fmt::print(err, "rung textconv: {}: {}\n", path, error);
  if (view.text.empty() && !view.errors.empty()) {
    // Nothing readable: the bytes as they are, so git still shows a change.
    fmt::print(err, "rung textconv: {}: shown as it is\n", path);
    std::fwrite(bytes.data(), 1, bytes.size(), out);
    return 0;
  }
  std::fwrite(view.text.data(), 1, view.text.size(), out);
  for (const std::string& note : view.notes) fmt::print(out, "// rung: {}\n", note);
  return 0;
}

}  // namespace rung::cli
