// One entry point for every source file: unwraps containers, passes plain text through.
#pragma once

#include <string_view>

#include "parser/containers/container_document.hpp"
#include "parser/containers/detect.hpp"

namespace rung::containers {

// `decoded_text` is the file's text after source::decode; `kind` is what
// detect_container said about the file. Ordinary files (None) come back as a
// document whose virtual text is the file text (one identity segment);
// Unsupported containers come back empty, with the kind set so the caller can
// say the file was skipped.
ContainerDocument read_container(ContainerKind kind, std::string_view path, std::string_view decoded_text);

// Detects the kind first.
ContainerDocument read_container(std::string_view path, std::string_view decoded_text);

}  // namespace rung::containers
