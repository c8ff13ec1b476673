// JSON-RPC 2.0 as LSP frames it: "Content-Length: N\r\n" headers, a blank line, N bytes of JSON.
// The reader takes bytes as they arrive (any chunking) and hands out whole message bodies; a
// header it cannot read is reported, and the reader skips to the next header block, so one
// broken message never ends the session.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace rung::lsp {

using Json = nlohmann::json;

// The error codes of JSON-RPC and LSP 3.17.
enum class ErrorCode : int {
  ParseError = -32700,
  InvalidRequest = -32600,
  MethodNotFound = -32601,
  InvalidParams = -32602,
  InternalError = -32603,
  ServerNotInitialized = -32002,
  RequestFailed = -32803,
  ServerCancelled = -32802,
  ContentModified = -32801,
  RequestCancelled = -32800,
};

// Thrown by request handlers: becomes the response's error.
struct RpcError {
  ErrorCode code = ErrorCode::InternalError;
  std::string message;
};

class MessageReader {
 public:
  // Messages larger than this are refused (their bytes are skipped): a client that sends a
  // 2 GB length must not make the server allocate it.
  explicit MessageReader(size_t max_body_bytes = 512u << 20) : max_body_bytes_(max_body_bytes) {}

  void feed(std::string_view bytes) { buffer_.append(bytes); }

  struct Item {
    std::string body;   // the JSON text of one message (valid or not: the caller parses)
    std::string error;  // non-empty: a framing problem, `body` is empty
  };
  // The next complete message or framing error; nullopt when more bytes are needed.
  std::optional<Item> next();

 private:
  std::string buffer_;
  size_t consumed_ = 0;
  size_t pending_length_ = 0;   // body length of the header block already read
  bool in_body_ = false;
  size_t skip_ = 0;             // bytes of a refused body still to drop
  size_t max_body_bytes_;
};

// One message framed for the wire.
std::string frame_message(const Json& message);

Json make_response(const Json& id, Json result);
Json make_error(const Json& id, ErrorCode code, std::string_view message);
Json make_notification(std::string_view method, Json params);
Json make_request(const Json& id, std::string_view method, Json params);

}  // namespace rung::lsp
