// Replacing a file's content so that a crash or a kill never leaves it half written: the new bytes
// go to a temporary file beside it, which then replaces the original in one rename.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace rung::cli {

// Writes `bytes` as the new content of the existing file `path` (through symbolic links: the
// file they point at is replaced), keeping its permission bits. False with `error` set when it
// could not; the original is then unchanged.
bool replace_file_atomically(const std::filesystem::path& path, std::string_view bytes, std::string* error);

}  // namespace rung::cli
