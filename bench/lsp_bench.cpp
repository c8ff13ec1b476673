// rung_lsp_bench: a scripted LSP client that drives the language server (its real worker thread,
// every message serialized as on the wire) over a generated workspace, and reports what an editor
// user feels: time to index, keystroke-to-diagnostics latency, request latencies (p50/p95) and
// memory. Results: docs/performance.md ("Language server").
//   rung_lsp_bench [--files N (default 10000)] [--dir DIR] [--seeds] [--samples N (default 40)]
// --seeds indexes ../shared/corpus/seeds instead of a generated project.
#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <optional>
#include <regex>
#include <string>
#include <vector>

#include "bench/generated_project.hpp"
#include "bench/generated_source.hpp"
#include "lsp/server.hpp"
#include "lsp/uri.hpp"

namespace {

namespace fs = std::filesystem;
using rung::lsp::Json;
using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

long status_kb(const char* field) {
  std::ifstream in("/proc/self/status");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind(field, 0) == 0) return std::strtol(line.c_str() + std::strlen(field), nullptr, 10);
  }
  return -1;
}

// The client end: messages from the server, parsed back from their wire form.
class Client {
 public:
  Client()
      : server_(
            [this](const Json& message) {
              const std::string wire = rung::lsp::frame_message(message);
              Json parsed = Json::parse(wire.substr(wire.find("\r\n\r\n") + 4));
              std::lock_guard lock(mutex_);
              inbox_.push_back(std::move(parsed));
              arrived_.notify_all();
            },
            rung::lsp::ServerOptions{}) {}
  ~Client() {
    request("shutdown", nullptr);
    notify("exit", Json::object());
    server_.wait();
  }

  void notify(const char* method, Json params) {
    server_.receive(Json{{"jsonrpc", "2.0"}, {"method", method}, {"params", std::move(params)}}.dump());
  }
  // Sends a request and waits for its response.
  Json request(const char* method, Json params) {
    const int id = ++next_id_;
    server_.receive(Json{{"jsonrpc", "2.0"}, {"id", id}, {"method", method}, {"params", std::move(params)}}.dump());
    return wait_for([&](const Json& m) { return m.contains("id") && m["id"] == id && !m.contains("method"); });
  }
  // Waits for a message `match` accepts; older messages are dropped.
  template <typename Match>
  Json wait_for(const Match& match) {
    std::unique_lock lock(mutex_);
    for (;;) {
      while (!inbox_.empty()) {
        Json message = std::move(inbox_.front());
        inbox_.pop_front();
        if (match(message)) return message;
      }
      arrived_.wait(lock);
    }
  }

 private:
  std::mutex mutex_;
  std::condition_variable arrived_;
  std::deque<Json> inbox_;
  int next_id_ = 0;
  rung::lsp::Server server_;
};

struct Stats {
  std::vector<double> samples;
  void add(double ms) { samples.push_back(ms); }
  double percentile(double p) {
    if (samples.empty()) return 0;
    std::sort(samples.begin(), samples.end());
    return samples[std::min(samples.size() - 1, static_cast<size_t>(p * static_cast<double>(samples.size())))];
  }
};

void report(const char* what, Stats& stats, const char* note = "") {
  std::printf("| %-38s | %8.2f | %8.2f | %8.2f | %zu %s\n", what, stats.percentile(0.5), stats.percentile(0.95),
              stats.percentile(1.0), stats.samples.size(), note);
}

Json text_document(const fs::path& file) { return Json{{"uri", rung::lsp::uri_of_path(file)}}; }

Json position(int line, int character) { return Json{{"line", line}, {"character", character}}; }

// The first `fbAxis.` of a generated program: hover/definition on `fbAxis`, completion after the dot.
std::optional<std::pair<int, int>> find_member_access(const std::string& text) {
  int line = 0;
  size_t start = 0;
  while (start < text.size()) {
    size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    const std::string_view row(text.data() + start, end - start);
    if (const size_t at = row.find("fbAxis."); at != std::string_view::npos && row.find("VAR") == std::string_view::npos) {
      return std::pair{line, static_cast<int>(at)};
    }
    ++line;
    start = end + 1;
  }
  return std::nullopt;
}

std::string read(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

}  // namespace

int main(int argc, char** argv) {
  size_t files = 10000;
  size_t samples = 40;
  fs::path dir = fs::temp_directory_path() / "rung-lsp-bench";
  bool seeds = false;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--files" && i + 1 < argc) files = std::strtoull(argv[++i], nullptr, 10);
    else if (arg == "--samples" && i + 1 < argc) samples = std::strtoull(argv[++i], nullptr, 10);
    else if (arg == "--dir" && i + 1 < argc) dir = argv[++i];
    else if (arg == "--seeds") seeds = true;
    else {
      std::fprintf(stderr, "usage: %s [--files N] [--dir DIR] [--seeds] [--samples N]\n", argv[0]);
      return 2;
    }
  }
  std::vector<fs::path> programs;
  if (seeds) {
    dir = fs::path(RUNG_SHARED_DIR) / "corpus" / "seeds";
  } else {
    fs::remove_all(dir);
    const rung::bench::GeneratedProject project = rung::bench::generate_project(files);
    std::string error;
    if (!rung::bench::write_project(project, dir, error)) {
      std::fprintf(stderr, "error: %s\n", error.c_str());
      return 2;
    }
    // A 5,000-line file for semantic tokens.
    std::ofstream(dir / "FB_Big.st") << rung::bench::generate_st(5000, 7);
    for (const auto& file : project.files) {
      if (file.name.rfind("PRG_", 0) == 0) programs.push_back(dir / file.name);
    }
    std::printf("workspace: %zu files, %zu lines, %.1f MB in %s\n", project.files.size() + 1, project.lines + 5000,
                static_cast<double>(project.bytes) / 1e6, dir.c_str());
  }
  const long rss_before = status_kb("VmRSS:");
  Client client;
  const auto index_start = Clock::now();
  Json capabilities = Json::parse(R"({"window": {"workDoneProgress": true},
      "textDocument": {"completion": {"completionItem": {"snippetSupport": true}}, "hover": {},
                       "semanticTokens": {"requests": {"full": {"delta": true}}}}})");
  client.request("initialize", Json{{"rootUri", rung::lsp::uri_of_path(dir)}, {"capabilities", capabilities}});
  client.notify("initialized", Json::object());
  client.wait_for([](const Json& m) {
    return m.value("method", "") == "$/progress" && m["params"]["value"].value("kind", "") == "end";
  });
  const double index_ms = ms_since(index_start);
  std::printf("\nindex: %.0f ms; resident memory %ld MB (peak %ld MB, before %ld MB)\n", index_ms,
              status_kb("VmRSS:") / 1024, status_kb("VmHWM:") / 1024, rss_before / 1024);
  if (seeds || programs.empty()) return 0;

  std::printf("\n| %-38s | %8s | %8s | %8s | samples\n", "request (ms)", "p50", "p95", "max");
  std::printf("|%s|%s|%s|%s|---\n", std::string(40, '-').c_str(), std::string(10, '-').c_str(),
              std::string(10, '-').c_str(), std::string(10, '-').c_str());
  Stats keystroke, completion, hover, definition, references, rename, tokens;
  for (size_t i = 0; i < samples && i < programs.size(); ++i) {
    const fs::path& file = programs[(i * 7919) % programs.size()];
    const std::string text = read(file);
    const auto access = find_member_access(text);
    if (!access) continue;
    const auto [line, column] = *access;
    const Json document = text_document(file);
    client.notify("textDocument/didOpen", Json{{"textDocument", {{"uri", document["uri"]}, {"languageId", "iec61131"},
                                                                  {"version", 1}, {"text", text}}}});
    client.wait_for([&](const Json& m) {
      return m.value("method", "") == "textDocument/publishDiagnostics" && m["params"]["uri"] == document["uri"] &&
             m["params"].value("version", 0) == 1;
    });
    // A keystroke: a space typed at the start of the member access line, then its diagnostics.
    auto start = Clock::now();
    client.notify("textDocument/didChange",
                  Json{{"textDocument", {{"uri", document["uri"]}, {"version", 2}}},
                       {"contentChanges", Json::array({{{"range", {{"start", position(line, 0)}, {"end", position(line, 0)}}},
                                                        {"text", " "}}})}});
    client.wait_for([&](const Json& m) {
      return m.value("method", "") == "textDocument/publishDiagnostics" && m["params"]["uri"] == document["uri"] &&
             m["params"].value("version", 0) == 2;
    });
    keystroke.add(ms_since(start));
    const int col = column + 1;  // the space shifted the line
    const auto timed = [&](Stats& stats, const char* method, Json params) {
      params["textDocument"] = document;
      const auto begin = Clock::now();
      const Json answer = client.request(method, std::move(params));
      stats.add(ms_since(begin));
      return answer;
    };
    timed(completion, "textDocument/completion", Json{{"position", position(line, col + 7)}});
    timed(hover, "textDocument/hover", Json{{"position", position(line, col + 2)}});
    timed(definition, "textDocument/definition", Json{{"position", position(line, col + 2)}});
    if (i < samples / 4) {
      timed(references, "textDocument/references",
            Json{{"position", position(line, col + 9)}, {"context", {{"includeDeclaration", true}}}});
      timed(rename, "textDocument/rename", Json{{"position", position(line, col + 2)}, {"newName", "fbAxisRenamed"}});
    }
    client.notify("textDocument/didClose", Json{{"textDocument", document}});
  }
  const fs::path big = dir / "FB_Big.st";
  client.notify("textDocument/didOpen", Json{{"textDocument", {{"uri", rung::lsp::uri_of_path(big)}, {"languageId", "iec61131"},
                                                               {"version", 1}, {"text", read(big)}}}});
  for (int i = 0; i < 10; ++i) {
    const auto begin = Clock::now();
    client.request("textDocument/semanticTokens/full", Json{{"textDocument", text_document(big)}});
    tokens.add(ms_since(begin));
  }
  report("keystroke -> its diagnostics", keystroke);
  report("completion after '.'", completion);
  report("hover", hover);
  report("definition", definition);
  report("references (project-wide)", references);
  report("rename (project-wide)", rename);
  report("semantic tokens, 5,000-line file", tokens);
  std::printf("\nresident memory at the end: %ld MB (peak %ld MB)\n", status_kb("VmRSS:") / 1024, status_kb("VmHWM:") / 1024);
  return 0;
}
