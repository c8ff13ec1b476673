// The protocol layer: framing, URIs, incremental text sync, and what the server does with a
// client that misbehaves (it answers with an error or a log line, and never stops serving).
#include <gtest/gtest.h>

#include "lsp/json_rpc.hpp"
#include "lsp/text_sync.hpp"
#include "lsp/uri.hpp"
#include "tests/lsp/lsp_transcript.hpp"
#include "tests/support/test_paths.hpp"

namespace rung::test {
namespace {

namespace fs = std::filesystem;
using lsp::Json;

TEST(LspFraming, SplitsMessagesArrivingInAnyChunks) {
  const std::string wire = lsp::frame_message(Json{{"a", 1}}) + lsp::frame_message(Json{{"b", "é"}});
  lsp::MessageReader reader;
  std::vector<std::string> bodies;
  for (char c : wire) {  // one byte at a time: the worst chunking
    reader.feed(std::string_view(&c, 1));
    while (auto item = reader.next()) {
      ASSERT_TRUE(item->error.empty()) << item->error;
      bodies.push_back(item->body);
    }
  }
  ASSERT_EQ(bodies.size(), 2u);
  EXPECT_EQ(Json::parse(bodies[0])["a"], 1);
  EXPECT_EQ(Json::parse(bodies[1])["b"], "é");
}

TEST(LspFraming, ReportsBadHeadersAndRecovers) {
  lsp::MessageReader reader(1000);
  reader.feed("Content-Type: x\r\n\r\n");
  auto missing = reader.next();
  ASSERT_TRUE(missing);
  EXPECT_NE(missing->error.find("without a Content-Length"), std::string::npos);
  reader.feed("Content-Length: abc\r\n\r\n");
  auto bad = reader.next();
  ASSERT_TRUE(bad);
  EXPECT_NE(bad->error.find("not a number"), std::string::npos);
  reader.feed("content-length: 5000\r\n\r\n" + std::string(5000, 'x'));
  auto huge = reader.next();
  ASSERT_TRUE(huge);
  EXPECT_NE(huge->error.find("refused"), std::string::npos);
  reader.feed("Content-Length: 2\r\n\r\n{}");
  auto good = reader.next();
  ASSERT_TRUE(good);
  EXPECT_EQ(good->body, "{}");
  EXPECT_FALSE(reader.next());
}

TEST(LspUri, RoundTripsPathsWithSpacesAndUnicode) {
  const fs::path path = "/home/plc user/Projekt Förderband/MAIN.st";
  const std::string uri = lsp::uri_of_path(path);
  EXPECT_EQ(uri, "file:///home/plc%20user/Projekt%20F%C3%B6rderband/MAIN.st");
  EXPECT_EQ(lsp::path_of_uri(uri), path);
  EXPECT_EQ(lsp::path_of_uri("FILE:///a/b%2Fc.st"), fs::path("/a/b/c.st"));
  EXPECT_FALSE(lsp::path_of_uri("untitled:Untitled-1"));
  EXPECT_FALSE(lsp::path_of_uri("file://otherhost/x.st"));
  EXPECT_FALSE(lsp::path_of_uri("file:///bad%2"));
  EXPECT_FALSE(lsp::path_of_uri("file:///nul%00.st"));
}

TEST(LspTextSync, AppliesUtf16RangesAndClamps) {
  std::string text = "a := 'ä😀';\nb := 2;\n";
  // After the emoji (2 UTF-16 units) on line 0: character 9 is right before the closing quote.
  ASSERT_FALSE(lsp::apply_content_change(
      text, Json{{"range", {{"start", {{"line", 0}, {"character", 9}}}, {"end", {{"line", 0}, {"character", 9}}}}},
                 {"text", "X"}}));
  EXPECT_EQ(text, "a := 'ä😀X';\nb := 2;\n");
  ASSERT_FALSE(lsp::apply_content_change(
      text, Json{{"range", {{"start", {{"line", 1}, {"character", 5}}}, {"end", {{"line", 1}, {"character", 99}}}}},
                 {"text", "3;"}}));
  EXPECT_EQ(text, "a := 'ä😀X';\nb := 3;\n");
  ASSERT_FALSE(lsp::apply_content_change(
      text, Json{{"range", {{"start", {{"line", 7}, {"character", 0}}}, {"end", {{"line", 9}, {"character", 0}}}}},
                 {"text", "c := 4;"}}));
  EXPECT_EQ(text, "a := 'ä😀X';\nb := 3;\nc := 4;");
  EXPECT_TRUE(lsp::apply_content_change(
      text, Json{{"range", {{"start", {{"line", 1}, {"character", 3}}}, {"end", {{"line", 0}, {"character", 0}}}}},
                 {"text", ""}}));
  EXPECT_TRUE(lsp::apply_content_change(text, Json{{"range", {{"start", "x"}}}, {"text", ""}}));
  ASSERT_FALSE(lsp::apply_content_change(text, Json{{"text", "whole"}}));
  EXPECT_EQ(text, "whole");
}

// A scratch workspace with one program, for the robustness tests.
class LspRobustness : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::temp_directory_path() / ("rung-lsp-robust-" + std::to_string(::getpid()) + "-" +
                                         ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(root_);
    write_file(root_ / "main.st", "PROGRAM Main\nVAR\n  x : INT;\nEND_VAR\nx := x + 1;\nEND_PROGRAM\n");
  }
  void TearDown() override { fs::remove_all(root_); }
  fs::path root_;
};

TEST_F(LspRobustness, AnswersGarbageWithErrorsAndKeepsServing) {
  LspTranscript client(root_);
  client.send_text("{not json");
  client.send_text("[1, 2]");
  client.send({{"jsonrpc", "2.0"}, {"id", 1}, {"method", "textDocument/hover"}, {"params", Json::object()}});
  client.initialize();
  client.send({{"jsonrpc", "2.0"}, {"id", 2}, {"method", "no/suchMethod"}, {"params", Json::object()}});
  client.send({{"jsonrpc", "2.0"}, {"id", 3}, {"method", "textDocument/diagnostic"},
               {"params", {{"textDocument", {{"uri", "file:///nowhere/x.st"}}}}}});
  client.send({{"jsonrpc", "2.0"}, {"id", Json::array()}, {"method", "shutdown"}});
  const auto messages = client.messages();
  ASSERT_GE(messages.size(), 6u);
  EXPECT_EQ(messages[0]["error"]["code"], -32700);
  EXPECT_EQ(messages[1]["error"]["code"], -32600);
  EXPECT_EQ(client.response(1)["error"]["code"], -32002);
  EXPECT_EQ(client.response(2)["error"]["code"], -32601);
  EXPECT_EQ(client.response(3)["error"]["code"], -32602);
  // Still serving: a valid request after all that is answered.
  client.send({{"jsonrpc", "2.0"}, {"id", 4}, {"method", "shutdown"}});
  EXPECT_TRUE(client.response(4).contains("result"));
  client.send({{"jsonrpc", "2.0"}, {"method", "exit"}});
  EXPECT_TRUE(client.finished());
}

TEST_F(LspRobustness, DropsStaleVersionsAndEditsOfUnknownDocuments) {
  LspTranscript client(root_);
  client.initialize();
  const std::string uri = client.root_uri() + "/main.st";
  client.send({{"jsonrpc", "2.0"}, {"method", "textDocument/didOpen"},
               {"params", {{"textDocument", {{"uri", uri}, {"languageId", "iec61131"}, {"version", 5},
                                             {"text", read_file(root_ / "main.st")}}}}}});
  client.take_messages();
  // Version 4 is older than the open version 5: ignored, so the text stays valid.
  client.send({{"jsonrpc", "2.0"}, {"method", "textDocument/didChange"},
               {"params", {{"textDocument", {{"uri", uri}, {"version", 4}}},
                           {"contentChanges", Json::array({{{"text", "garbage((("}}})}}}});
  client.send({{"jsonrpc", "2.0"}, {"method", "textDocument/didChange"},
               {"params", {{"textDocument", {{"uri", client.root_uri() + "/other.st"}, {"version", 2}}},
                           {"contentChanges", Json::array({{{"text", "x"}}})}}}});
  client.send({{"jsonrpc", "2.0"}, {"id", 7}, {"method", "textDocument/diagnostic"},
               {"params", {{"textDocument", {{"uri", uri}}}}}});
  const Json report = client.response(7);
  ASSERT_TRUE(report.contains("result")) << report.dump();
  for (const Json& item : report["result"]["items"]) {
    EXPECT_NE(item["code"].get<std::string>()[0], 'S') << "the stale change reached the text: " << item.dump();
  }
  int logs = 0;
  for (const Json& message : client.messages()) logs += message.value("method", "") == "window/logMessage";
  EXPECT_EQ(logs, 2);
}

TEST_F(LspRobustness, ExitWithoutShutdownIsExitCodeOne) {
  LspTranscript client(root_);
  client.initialize();
  client.send({{"jsonrpc", "2.0"}, {"method", "exit"}});
  EXPECT_TRUE(client.finished());
}

}  // namespace
}  // namespace rung::test
