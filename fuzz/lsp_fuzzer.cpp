// libFuzzer target for the language server: the input is read as a script of client actions
// (open, edit at random positions, requests of every method at random positions, raw bytes as a
// message, cancel, close) against an in-process server in synchronous mode. Any crash, sanitizer
// report or hang is a bug: the server must answer garbage with errors and keep serving.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "lsp/server.hpp"

namespace {

using rung::lsp::Json;

constexpr const char* kMethods[] = {
    "textDocument/hover",          "textDocument/completion",      "textDocument/definition",
    "textDocument/references",     "textDocument/documentSymbol",  "textDocument/semanticTokens/full",
    "textDocument/formatting",     "textDocument/codeAction",      "textDocument/signatureHelp",
    "textDocument/rename",         "textDocument/prepareRename",   "textDocument/foldingRange",
    "textDocument/selectionRange", "textDocument/documentHighlight", "textDocument/inlayHint",
    "textDocument/diagnostic",     "textDocument/typeDefinition",  "textDocument/implementation",
    "textDocument/codeLens",       "workspace/symbol",             "textDocument/rangeFormatting",
    "textDocument/onTypeFormatting", "textDocument/prepareCallHierarchy", "textDocument/prepareTypeHierarchy",
};

class Reader {
 public:
  Reader(const uint8_t* data, size_t size) : data_(data), size_(size) {}
  bool done() const { return at_ >= size_; }
  uint8_t byte() { return at_ < size_ ? data_[at_++] : 0; }
  std::string text(size_t max) {
    const size_t n = std::min<size_t>(byte() % (max + 1), size_ - at_);
    std::string out(reinterpret_cast<const char*>(data_ + at_), n);
    at_ += n;
    return out;
  }

 private:
  const uint8_t* data_;
  size_t size_;
  size_t at_ = 0;
};

Json position(Reader& in) { return Json{{"line", in.byte() % 12}, {"character", in.byte() % 40}}; }

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  Reader in(data, size);
  rung::lsp::Server server([](const Json&) {}, rung::lsp::ServerOptions{.synchronous = true, .load = {.threads = 1}});
  const std::string uri = "file:///rung-fuzz/nonexistent/main.st";
  auto send = [&](const Json& message) { server.receive(message.dump(-1, ' ', false, Json::error_handler_t::replace)); };
  send({{"jsonrpc", "2.0"}, {"id", 0}, {"method", "initialize"}, {"params", {{"capabilities", Json::object()}}}});
  send({{"jsonrpc", "2.0"}, {"method", "initialized"}, {"params", Json::object()}});
  send({{"jsonrpc", "2.0"},
        {"method", "textDocument/didOpen"},
        {"params", {{"textDocument", {{"uri", uri}, {"languageId", "iec61131"}, {"version", 1},
                                      {"text", "PROGRAM Main\nVAR\n  x : INT;\n  t : TON;\nEND_VAR\nx := x + 1;\nt(IN := TRUE, PT := T#1s);\nEND_PROGRAM\n"}}}}}});
  int version = 1;
  int id = 1;
  while (!in.done() && !server.finished()) {
    switch (in.byte() % 6) {
      case 0: {  // an edit at a random range
        const Json start = position(in);
        send({{"jsonrpc", "2.0"},
              {"method", "textDocument/didChange"},
              {"params", {{"textDocument", {{"uri", uri}, {"version", ++version}}},
                          {"contentChanges", Json::array({{{"range", {{"start", start}, {"end", position(in)}}},
                                                           {"text", in.text(24)}}})}}}});
        break;
      }
      case 1:
      case 2: {  // a request at a random position
        const char* method = kMethods[in.byte() % std::size(kMethods)];
        const Json where = position(in);
        send({{"jsonrpc", "2.0"},
              {"id", ++id},
              {"method", method},
              {"params", {{"textDocument", {{"uri", uri}}},
                          {"position", where},
                          {"range", {{"start", where}, {"end", position(in)}}},
                          {"newName", in.text(8)},
                          {"query", in.text(4)},
                          {"ch", ";"},
                          {"options", {{"tabSize", 2}, {"insertSpaces", true}}},
                          {"context", {{"includeDeclaration", true}, {"diagnostics", Json::array()}}}}}});
        break;
      }
      case 3:  // raw bytes as a message body
        server.receive(in.text(64));
        break;
      case 4:  // cancel something
        send({{"jsonrpc", "2.0"}, {"method", "$/cancelRequest"}, {"params", {{"id", id + 1}}}});
        break;
      default:  // a whole-text replacement
        send({{"jsonrpc", "2.0"},
              {"method", "textDocument/didChange"},
              {"params", {{"textDocument", {{"uri", uri}, {"version", ++version}}},
                          {"contentChanges", Json::array({{{"text", in.text(200)}}})}}}});
        break;
    }
  }
  send({{"jsonrpc", "2.0"}, {"id", ++id}, {"method", "shutdown"}});
  send({{"jsonrpc", "2.0"}, {"method", "exit"}});
  return 0;
}
