// file:// URIs <-> file system paths, the way editors write them (RFC 8089 with percent-encoding).
// Only the file scheme names files rung can read; other schemes (untitled:, git:) are kept as
// opaque keys so such buffers can still be checked on their own.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace rung::lsp {

// "file:///home/a%20b/x.st" -> "/home/a b/x.st"; nullopt for other schemes or a malformed URI.
std::optional<std::filesystem::path> path_of_uri(std::string_view uri);

// The inverse: an absolute path to a file URI; characters outside the unreserved set and '/' are
// percent-encoded, as VS Code and Neovim do.
std::string uri_of_path(const std::filesystem::path& path);

}  // namespace rung::lsp
