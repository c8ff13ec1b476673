#include "lsp/json_rpc.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>

namespace rung::lsp {
namespace {

bool equals_ignoring_case(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
         });
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

}  // namespace

std::optional<MessageReader::Item> MessageReader::next() {
  // Drop what earlier calls consumed once it is a large part of the buffer (amortised O(1)).
  if (consumed_ > 0 && consumed_ * 2 >= buffer_.size()) {
    buffer_.erase(0, consumed_);
    consumed_ = 0;
  }
  if (skip_ > 0) {
    const size_t n = std::min(skip_, buffer_.size() - consumed_);
    consumed_ += n;
    skip_ -= n;
    if (skip_ > 0) return std::nullopt;
  }
  if (!in_body_) {
    const size_t end = buffer_.find("\r\n\r\n", consumed_);
    if (end == std::string::npos) {
      // A header block never grows this large; the peer is not speaking LSP.
      if (buffer_.size() - consumed_ > size_t{64} * 1024) {
        consumed_ = buffer_.size();
        return Item{{}, "header block longer than 64 KiB without an end; bytes dropped"};
      }
      return std::nullopt;
    }
    const std::string_view headers(buffer_.data() + consumed_, end - consumed_);
    consumed_ = end + 4;
    std::optional<size_t> length;
    size_t line_start = 0;
    while (line_start <= headers.size()) {
      size_t line_end = headers.find("\r\n", line_start);
      if (line_end == std::string_view::npos) line_end = headers.size();
      const std::string_view line = headers.substr(line_start, line_end - line_start);
      const size_t colon = line.find(':');
      if (colon != std::string_view::npos && equals_ignoring_case(trim(line.substr(0, colon)), "Content-Length")) {
        const std::string_view value = trim(line.substr(colon + 1));
        size_t parsed = 0;
        const auto [ptr, ec] = std::from_chars(value.data(), value.data() + value.size(), parsed);
        if (ec != std::errc() || ptr != value.data() + value.size()) {
          return Item{{}, "Content-Length is not a number: '" + std::string(value) + "'"};
        }
        length = parsed;
      }
      line_start = line_end + 2;
    }
    if (!length) return Item{{}, "message without a Content-Length header"};
    if (*length > max_body_bytes_) {
      skip_ = *length;
      return Item{{}, "message of " + std::to_string(*length) + " bytes refused (limit " +
                          std::to_string(max_body_bytes_) + ")"};
    }
    pending_length_ = *length;
    in_body_ = true;
  }
  if (buffer_.size() - consumed_ < pending_length_) return std::nullopt;
  Item item{buffer_.substr(consumed_, pending_length_), {}};
  consumed_ += pending_length_;
  in_body_ = false;
  return item;
}

std::string frame_message(const Json& message) {
  // Invalid UTF-8 in a string (a cp1252 byte that slipped through) is replaced, never thrown.
  const std::string body = message.dump(-1, ' ', false, Json::error_handler_t::replace);
  return "Content-Length: " + std::to_string(body.size()) + "\r\n\r\n" + body;
}

Json make_response(const Json& id, Json result) {
  return Json{{"jsonrpc", "2.0"}, {"id", id}, {"result", std::move(result)}};
}

Json make_error(const Json& id, ErrorCode code, std::string_view message) {
  return Json{{"jsonrpc", "2.0"},
              {"id", id},
              {"error", Json{{"code", static_cast<int>(code)}, {"message", std::string(message)}}}};
}

Json make_notification(std::string_view method, Json params) {
  return Json{{"jsonrpc", "2.0"}, {"method", std::string(method)}, {"params", std::move(params)}};
}

Json make_request(const Json& id, std::string_view method, Json params) {
  return Json{{"jsonrpc", "2.0"}, {"id", id}, {"method", std::string(method)}, {"params", std::move(params)}};
}

}  // namespace rung::lsp
