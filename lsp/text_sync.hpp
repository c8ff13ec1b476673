// Applying an editor's textDocument/didChange to the text rung holds: whole-text replacements and
// incremental edits whose positions count UTF-16 code units (LSP's default encoding).
#pragma once

#include <optional>
#include <string>

#include "lsp/json_rpc.hpp"

namespace rung::lsp {

// Applies one TextDocumentContentChangeEvent to `text`. Positions past the end of a line or of
// the text clamp (editors and rung disagree about a trailing line end); a range whose end lies
// before its start is an error: returns the reason, and `text` is left as it was.
std::optional<std::string> apply_content_change(std::string& text, const Json& change);

}  // namespace rung::lsp
