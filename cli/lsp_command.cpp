#include "cli/lsp_command.hpp"

#include <cstdio>
#include <exception>

#include "lsp/transport.hpp"

namespace rung::cli {

int run_lsp_command(const LspCommandOptions& options) {
  lsp::ServerOptions server;
  server.load.threads = options.threads;
  try {
    return options.port ? lsp::serve_tcp(*options.port, server) : lsp::serve_stdio(server);
  } catch (const std::exception& error) {
    // Only the transport's own setup can fail here (a port in use); handlers never throw out.
    std::fprintf(stderr, "error: rung lsp: %s\n", error.what());
    return 2;
  }
}

}  // namespace rung::cli
