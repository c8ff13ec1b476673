#include "lsp/transport.hpp"

#include <csignal>
#include <iostream>
#include <sys/stat.h>
#include <unistd.h>

#include <boost/asio.hpp>

#include "lsp/json_rpc.hpp"

namespace rung::lsp {
namespace asio = boost::asio;

namespace {

// Feeds bytes to the framer and the framed bodies to the server.
void deliver(MessageReader& reader, Server& server) {
  while (auto item = reader.next()) {
    if (item->error.empty()) {
      server.receive(item->body);
    } else {
      server.transport_error(item->error);
    }
  }
}

bool write_all(int fd, const std::string& bytes) {
  size_t written = 0;
  while (written < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + written, bytes.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    written += static_cast<size_t>(n);
  }
  return true;
}

}  // namespace

int serve_stdio(const ServerOptions& options) {
  // A client that disappears must not kill the server with SIGPIPE mid-write.
  std::signal(SIGPIPE, SIG_IGN);
  std::atomic<bool> output_broken{false};
  Server server(
      [&](const Json& message) {
        if (!output_broken && !write_all(STDOUT_FILENO, frame_message(message))) output_broken = true;
      },
      options);
  MessageReader reader;
  std::array<char, size_t{64} * 1024> buffer{};
  struct stat info {};
  const bool pollable = ::fstat(STDIN_FILENO, &info) == 0 && !S_ISREG(info.st_mode);
  if (pollable) {
    asio::io_context io;
    asio::posix::stream_descriptor input(io, ::dup(STDIN_FILENO));
    std::function<void()> read_more = [&] {
      input.async_read_some(asio::buffer(buffer), [&](const boost::system::error_code& error, size_t n) {
        if (error) {
          server.close();
          return;
        }
        reader.feed(std::string_view(buffer.data(), n));
        deliver(reader, server);
        if (server.finished()) return;
        read_more();
      });
    };
    read_more();
    // The reader stops when the worker finishes (exit) too: poll it between reads.
    while (!server.finished() && !io.stopped()) {
      io.run_one_for(std::chrono::milliseconds(100));
    }
  } else {
    // A regular file as input (a recorded session): epoll cannot watch it, plain reads can.
    for (;;) {
      const ssize_t n = ::read(STDIN_FILENO, buffer.data(), buffer.size());
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) break;
      reader.feed(std::string_view(buffer.data(), static_cast<size_t>(n)));
      deliver(reader, server);
      if (server.finished()) break;
    }
    server.close();
  }
  server.close();
  return server.wait();
}

int serve_tcp(uint16_t port, const ServerOptions& options) {
  std::signal(SIGPIPE, SIG_IGN);
  asio::io_context io;
  asio::ip::tcp::acceptor acceptor(io, asio::ip::tcp::endpoint(asio::ip::make_address("127.0.0.1"), port));
  std::cerr << "rung lsp: listening on 127.0.0.1:" << acceptor.local_endpoint().port() << std::endl;
  asio::ip::tcp::socket socket(io);
  acceptor.accept(socket);
  std::atomic<bool> output_broken{false};
  Server server(
      [&](const Json& message) {
        if (output_broken) return;
        boost::system::error_code error;
        asio::write(socket, asio::buffer(frame_message(message)), error);
        if (error) output_broken = true;
      },
      options);
  MessageReader reader;
  std::array<char, size_t{64} * 1024> buffer{};
  for (;;) {
    boost::system::error_code error;
    const size_t n = socket.read_some(asio::buffer(buffer), error);
    if (error) break;
    reader.feed(std::string_view(buffer.data(), n));
    deliver(reader, server);
    if (server.finished()) break;
  }
  server.close();
  return server.wait();
}

}  // namespace rung::lsp
