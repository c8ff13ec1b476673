#include "tests/lsp/lsp_transcript.hpp"

#include "lsp/uri.hpp"
#include "tests/support/test_paths.hpp"

namespace rung::test {
namespace {

void replace_all(std::string& text, const std::string& from, const std::string& to) {
  if (from.empty()) return;
  for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) {
    text.replace(at, from.size(), to);
  }
}

template <typename F>
lsp::Json map_strings(lsp::Json value, const F& f) {
  if (value.is_string()) return f(value.get<std::string>());
  if (value.is_object()) {
    // Keys too: a WorkspaceEdit's `changes` is keyed by URI.
    lsp::Json mapped = lsp::Json::object();
    for (auto& [key, item] : value.items())
      mapped[f(key).template get<std::string>()] = map_strings(std::move(item), f);
    return mapped;
  }
  if (value.is_array()) {
    for (auto& item : value) item = map_strings(std::move(item), f);
  }
  return value;
}

}  // namespace

LspTranscript::LspTranscript(std::filesystem::path root)
    : root_(std::filesystem::absolute(std::move(root)).lexically_normal()),
      server_(
          [this](const lsp::Json& message) {
            if (recording_) messages_.push_back(normalize(message));
          },
          lsp::ServerOptions{.synchronous = true, .load = {.threads = 1}}) {
  if (root_.filename().empty()) root_ = root_.parent_path();
}

std::string LspTranscript::root_uri() const {
  return lsp::uri_of_path(root_);
}

lsp::Json LspTranscript::expand(lsp::Json value) const {
  const std::string uri = root_uri();
  const std::string path = root_.string();
  return map_strings(std::move(value), [&](std::string text) {
    replace_all(text, "${ROOT}", uri);
    replace_all(text, "${ROOT_PATH}", path);
    return lsp::Json(text);
  });
}

lsp::Json LspTranscript::normalize(lsp::Json value) const {
  const std::string uri = root_uri();
  const std::string path = root_.string();
  const std::string rung_uri = lsp::uri_of_path(source_dir());
  const std::string rung_path = source_dir().string();
  return map_strings(std::move(value), [&](std::string text) {
    replace_all(text, uri, "${ROOT}");
    replace_all(text, path, "${ROOT_PATH}");
    replace_all(text, rung_uri, "${RUNG}");
    replace_all(text, rung_path, "${RUNG_PATH}");
    return lsp::Json(text);
  });
}

void LspTranscript::send(lsp::Json message) {
  server_.receive(expand(std::move(message)).dump());
}

void LspTranscript::initialize(lsp::Json capabilities, bool record) {
  recording_ = record;
  send({{"jsonrpc", "2.0"},
        {"id", "init"},
        {"method", "initialize"},
        {"params",
         {{"processId", nullptr},
          {"rootUri", "${ROOT}"},
          {"capabilities", capabilities.is_null() ? full_client_capabilities() : capabilities},
          {"workspaceFolders", lsp::Json::array({{{"uri", "${ROOT}"}, {"name", "test"}}})}}}});
  recording_ = true;
  send({{"jsonrpc", "2.0"}, {"method", "initialized"}, {"params", lsp::Json::object()}});
}

std::vector<lsp::Json> LspTranscript::take_messages() {
  std::vector<lsp::Json> out;
  out.swap(messages_);
  return out;
}

lsp::Json LspTranscript::response(const lsp::Json& id) const {
  for (const lsp::Json& message : messages_) {
    if (message.contains("id") && message["id"] == id && !message.contains("method")) return message;
  }
  return nullptr;
}

lsp::Json full_client_capabilities() {
  return lsp::Json::parse(R"({
    "general": {"positionEncodings": ["utf-16"]},
    "textDocument": {
      "synchronization": {"didSave": true, "dynamicRegistration": false},
      "completion": {"completionItem": {"snippetSupport": true, "documentationFormat": ["markdown", "plaintext"],
                                        "resolveSupport": {"properties": ["documentation", "detail"]}},
                     "contextSupport": true},
      "hover": {"contentFormat": ["markdown", "plaintext"]},
      "signatureHelp": {"signatureInformation": {"documentationFormat": ["markdown"], "parameterInformation": {"labelOffsetSupport": true}}},
      "definition": {"linkSupport": false},
      "documentSymbol": {"hierarchicalDocumentSymbolSupport": true},
      "codeAction": {"codeActionLiteralSupport": {"codeActionKind": {"valueSet": ["quickfix", "refactor", "refactor.rewrite", "source"]}}, "resolveSupport": {"properties": ["edit"]}},
      "rename": {"prepareSupport": true},
      "publishDiagnostics": {"relatedInformation": true, "versionSupport": true, "codeDescriptionSupport": true, "tagSupport": {"valueSet": [1, 2]}},
      "semanticTokens": {"requests": {"full": {"delta": true}, "range": true}, "tokenTypes": [], "tokenModifiers": [], "formats": ["relative"]},
      "foldingRange": {"lineFoldingOnly": false},
      "inlayHint": {},
      "callHierarchy": {},
      "typeHierarchy": {}
    },
    "workspace": {"workspaceFolders": true, "symbol": {}, "applyEdit": true, "workspaceEdit": {"documentChanges": true},
                  "didChangeWatchedFiles": {"dynamicRegistration": false}},
    "window": {"workDoneProgress": false}
  })");
}

}  // namespace rung::test
