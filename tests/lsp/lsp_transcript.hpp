// Drives an in-process language server (synchronous mode) with a scripted client and records
// what the server sends: the protocol-level golden tests and the robustness tests use it.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "lsp/server.hpp"

namespace rung::test {

class LspTranscript {
 public:
  // `root`: the workspace folder the client opens (files are read from there).
  explicit LspTranscript(std::filesystem::path root);

  // Sends one client message; ${ROOT} in string values becomes the workspace folder's URI
  // (file:///...), ${ROOT_PATH} its path.
  void send(lsp::Json message);
  void send_text(const std::string& raw_body) { server_.receive(raw_body); }
  // initialize (with full client capabilities unless `capabilities` is given) + initialized; the
  // initialize response is not recorded.
  void initialize(lsp::Json capabilities = nullptr, bool record = false);

  // Everything the server sent so far, with the folder's URI and path and rung's source folder
  // written as ${ROOT}, ${ROOT_PATH} and ${RUNG}.
  const std::vector<lsp::Json>& messages() const { return messages_; }
  std::vector<lsp::Json> take_messages();
  // The response to request `id` among the messages (null if none).
  lsp::Json response(const lsp::Json& id) const;
  bool finished() const { return server_.finished(); }

  std::string root_uri() const;
  const std::filesystem::path& root() const { return root_; }

 private:
  lsp::Json expand(lsp::Json value) const;
  lsp::Json normalize(lsp::Json value) const;

  std::filesystem::path root_;
  std::vector<lsp::Json> messages_;
  bool recording_ = true;
  lsp::Server server_;
};

// Client capabilities of a modern client (VS Code-like, push diagnostics).
lsp::Json full_client_capabilities();

}  // namespace rung::test
