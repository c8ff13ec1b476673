// `rung lsp [--port N] [--stdio] [-j N]`: the language server for Neovim, VS Code, Emacs, Helix and
// every LSP client. Speaks LSP 3.17 over standard input/output, or over TCP on 127.0.0.1.
#pragma once

#include <cstdint>
#include <optional>

namespace rung::cli {

struct LspCommandOptions {
  std::optional<uint16_t> port;  // TCP instead of stdio
  unsigned threads = 0;          // for indexing; 0: one per core
};

int run_lsp_command(const LspCommandOptions& options);

}  // namespace rung::cli
