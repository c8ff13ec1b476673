#include "lsp/server.hpp"

#include <exception>

namespace rung::lsp {

Server::Server(Sink sink, ServerOptions options)
    : options_(options),
      sink_(std::move(sink)),
      session_([this](const Json& message) { send(message); }, options.load) {
  register_features(router_);
  session_.set_capabilities(router_.capabilities());
  if (!options_.synchronous) worker_ = std::thread([this] { worker_loop(); });
}

Server::~Server() {
  close();
  if (worker_.joinable()) worker_.join();
}

void Server::send(const Json& message) {
  std::lock_guard lock(sink_mutex_);
  sink_(message);
}

void Server::receive(const std::string& body) {
  Json message = Json::parse(body, nullptr, false);
  if (message.is_discarded()) {
    send(make_error(nullptr, ErrorCode::ParseError, "the message is not valid JSON"));
    return;
  }
  if (!message.is_object()) {
    send(make_error(nullptr, ErrorCode::InvalidRequest, "a message must be a JSON object (batches are not part of LSP)"));
    return;
  }
  const auto method = message.find("method");
  if (method != message.end() && *method == "$/cancelRequest") {
    // Handled here, not queued: the request it names may be waiting behind others or running.
    const Json id = message.contains("params") && message["params"].is_object() ? message["params"].value("id", Json()) : Json();
    std::lock_guard lock(mutex_);
    if (const auto flag = cancel_flags_.find(id_key(id)); flag != cancel_flags_.end()) flag->second->store(true);
    return;
  }
  if (options_.synchronous) {
    if (finished_) return;
    if (message.contains("id") && method != message.end()) {
      std::lock_guard lock(mutex_);
      cancel_flags_[id_key(message["id"])] = std::make_shared<std::atomic<bool>>(false);
    }
    process(std::move(message));
    while (!finished_ && session_.background_step()) {
    }
    return;
  }
  std::lock_guard lock(mutex_);
  if (closed_) return;
  if (message.contains("id") && method != message.end()) {
    cancel_flags_[id_key(message["id"])] = std::make_shared<std::atomic<bool>>(false);
  }
  queue_.push_back(std::move(message));
  wake_.notify_one();
}

void Server::transport_error(const std::string& message) {
  send(make_notification("window/logMessage", Json{{"type", 1}, {"message", "rung: " + message}}));
}

void Server::close() {
  std::lock_guard lock(mutex_);
  closed_ = true;
  wake_.notify_all();
}

int Server::wait() {
  if (worker_.joinable()) worker_.join();
  return exit_code_;
}

void Server::worker_loop() {
  for (;;) {
    Json message;
    {
      std::unique_lock lock(mutex_);
      if (queue_.empty() && !closed_) {
        lock.unlock();
        // Background work only while no message waits; one file per step keeps requests quick.
        if (session_.background_step()) continue;
        lock.lock();
        wake_.wait(lock, [&] { return !queue_.empty() || closed_; });
      }
      if (queue_.empty()) break;  // closed and drained
      message = std::move(queue_.front());
      queue_.pop_front();
    }
    process(std::move(message));
    if (finished_) break;
  }
  finished_ = true;
}

void Server::process(Json message) {
  const auto method_it = message.find("method");
  const Json id = message.contains("id") ? message["id"] : Json();
  const Json params = message.contains("params") ? message["params"] : Json::object();
  if (method_it == message.end()) {
    if (message.contains("result") || message.contains("error")) return;  // answers to our requests
    send(make_error(id, ErrorCode::InvalidRequest, "a message needs a method (or a result)"));
    return;
  }
  if (!method_it->is_string()) {
    send(make_error(id, ErrorCode::InvalidRequest, "method must be a string"));
    return;
  }
  const std::string method = method_it->get<std::string>();
  if (!message.contains("id")) {  // a notification
    if (method == "exit") {
      exit_code_ = session_.shutdown_requested() ? 0 : 1;
      finished_ = true;
      return;
    }
    if (!session_.initialized() || session_.shutdown_requested()) return;
    try {
      Json ignored;
      if (!session_.handle_lifecycle(method, params, &ignored) && method.rfind("$/", 0) != 0) {
        session_.log(4, "rung: notification " + method + " is not supported; ignored");
      }
    } catch (const RpcError& error) {
      session_.log(1, "rung: " + method + ": " + error.message);
    } catch (const std::exception& error) {
      session_.log(1, "rung: " + method + " failed: " + error.what());
    }
    return;
  }
  if (!id.is_string() && !id.is_number_integer()) {
    send(make_error(nullptr, ErrorCode::InvalidRequest, "id must be a string or an integer"));
    return;
  }
  process_request(id, method, params);
  std::lock_guard lock(mutex_);
  cancel_flags_.erase(id_key(id));
}

void Server::process_request(const Json& id, const std::string& method, const Json& params) {
  if (!session_.initialized() && method != "initialize") {
    send(make_error(id, ErrorCode::ServerNotInitialized, "the server is not initialized yet"));
    return;
  }
  if (session_.shutdown_requested()) {
    send(make_error(id, ErrorCode::InvalidRequest, "the server is shutting down"));
    return;
  }
  std::shared_ptr<std::atomic<bool>> flag;
  {
    std::lock_guard lock(mutex_);
    if (const auto found = cancel_flags_.find(id_key(id)); found != cancel_flags_.end()) flag = found->second;
  }
  if (flag && flag->load()) {
    send(make_error(id, ErrorCode::RequestCancelled, "cancelled"));
    return;
  }
  session_.set_current_cancel(flag.get());
  try {
    Json result;
    if (session_.handle_lifecycle(method, params, &result)) {
      send(make_response(id, std::move(result)));
    } else if (const RequestHandler* handler = router_.find(method)) {
      result = (*handler)(session_, params);
      if (flag && flag->load()) {
        send(make_error(id, ErrorCode::RequestCancelled, "cancelled"));
      } else {
        send(make_response(id, std::move(result)));
      }
    } else {
      send(make_error(id, ErrorCode::MethodNotFound, "method not supported: " + method));
    }
  } catch (const RpcError& error) {
    send(make_error(id, error.code, error.message));
  } catch (const std::exception& error) {
    // A bug in a handler fails its request, never the session.
    send(make_error(id, ErrorCode::InternalError, std::string(method) + " failed: " + error.what()));
  }
  session_.set_current_cancel(nullptr);
}

}  // namespace rung::lsp
