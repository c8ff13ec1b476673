// The language server: takes JSON-RPC message bodies from a transport, answers them on one
// worker thread (so the I/O thread always reads on, and $/cancelRequest reaches a request that is
// queued or running), and hands answers and notifications to a sink.
//
// Order: messages are handled in the order they arrived. Due diagnostics are computed only when
// no message is waiting, so a burst of keystrokes costs one re-check, not one per key.
#pragma once

#include <atomic>
#include <condition_variable>
#include <deque>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include "lsp/router.hpp"
#include "lsp/session.hpp"

namespace rung::lsp {

struct ServerOptions {
  // Tests: every message is handled on the calling thread, due diagnostics included, before
  // receive() returns, so a transcript is deterministic.
  bool synchronous = false;
  check::LoadOptions load;
};

class Server {
 public:
  Server(Sink sink, ServerOptions options = {});
  ~Server();
  Server(const Server&) = delete;
  Server& operator=(const Server&) = delete;

  // One message body, from the transport's thread, in arrival order.
  void receive(const std::string& body);
  // A framing error of the transport: logged to the client, the session goes on.
  void transport_error(const std::string& message);
  // The client went away (end of input, closed socket): the worker stops.
  void close();
  // Waits until the worker stopped; the process exit code: 0 after shutdown + exit, 1 otherwise.
  int wait();
  bool finished() const { return finished_.load(); }

 private:
  void worker_loop();
  void process(Json message);
  void process_request(const Json& id, const std::string& method, const Json& params);
  void send(const Json& message);
  static std::string id_key(const Json& id) { return id.dump(); }

  ServerOptions options_;
  Sink sink_;
  std::mutex sink_mutex_;
  Router router_;
  Session session_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<Json> queue_;
  std::map<std::string, std::shared_ptr<std::atomic<bool>>> cancel_flags_;  // by request id
  bool closed_ = false;
  std::atomic<bool> finished_{false};
  int exit_code_ = 1;
  std::thread worker_;
};

}  // namespace rung::lsp
