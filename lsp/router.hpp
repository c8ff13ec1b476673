// Which handler answers which LSP request, and the capabilities the server announces. Each
// feature file (features/*.cpp) registers its requests and sets its own part of the
// ServerCapabilities, so a feature and its announcement never drift apart.
#pragma once

#include <functional>
#include <map>
#include <string>
#include <string_view>

#include "lsp/json_rpc.hpp"

namespace rung::lsp {

class Session;

// Answers one request on the server's worker thread. Throws RpcError for a request it cannot
// answer (bad params, unknown document); returns the `result` otherwise (null is a valid result).
using RequestHandler = std::function<Json(Session& session, const Json& params)>;

class Router {
 public:
  void on_request(std::string method, RequestHandler handler) { handlers_[std::move(method)] = std::move(handler); }
  const RequestHandler* find(std::string_view method) const {
    const auto found = handlers_.find(method);
    return found == handlers_.end() ? nullptr : &found->second;
  }
  // ServerCapabilities (LSP 3.17), filled by the registering features.
  Json& capabilities() { return capabilities_; }
  const Json& capabilities() const { return capabilities_; }

 private:
  std::map<std::string, RequestHandler, std::less<>> handlers_;
  Json capabilities_ = Json::object();
};

// features/register.cpp: every feature's registration.
void register_features(Router& router);

}  // namespace rung::lsp
