// Where LSP messages travel: standard input/output (what editors start `rung lsp` with) or one
// TCP connection (`rung lsp --port N`, for clients that connect to a running server).
#pragma once

#include <cstdint>
#include <string>

#include "lsp/server.hpp"

namespace rung::lsp {

// Serves one client over stdin/stdout until it sends exit or closes its end. Returns the exit
// code (0 after shutdown + exit). Log lines go to stderr.
int serve_stdio(const ServerOptions& options = {});

// Listens on 127.0.0.1:`port` (0: any free port), prints "rung lsp: listening on 127.0.0.1:N" to
// stderr, serves the first client that connects and returns when it is done.
int serve_tcp(uint16_t port, const ServerOptions& options = {});

}  // namespace rung::lsp
