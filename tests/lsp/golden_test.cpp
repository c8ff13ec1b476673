// Protocol-level golden tests: each folder of tests/lsp/golden/ is a scripted session. The
// client's messages are session.jsonl (one JSON message a line; blank and '#' lines skipped), the
// files the server sees are workspace/ (copied to a scratch folder, so scripts may change them),
// and expected.json is every message the server sent, in order, with paths written ${ROOT}.
//
// Script lines with a "rung-test" key are actions of the test client, not LSP messages:
//   {"rung-test": "initialize"}                   initialize + initialized (response not recorded;
//                                                  "capabilities": {...} replaces the default client's)
//   {"rung-test": "open", "path": "a.st"}          didOpen with the file's text, version 1
//   {"rung-test": "write", "path": "a.st", "text": "..."}   writes a file in the workspace
//   {"rung-test": "delete", "path": "a.st"}        deletes a file of the workspace
// RUNG_UPDATE_GOLDEN=1 rewrites expected.json.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "tests/lsp/lsp_transcript.hpp"
#include "tests/support/test_paths.hpp"

namespace rung::test {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> golden_cases() {
  std::vector<std::string> names;
  const fs::path dir = source_dir() / "tests/lsp/golden";
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.is_directory() && fs::exists(entry.path() / "session.jsonl")) names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

class LspGolden : public ::testing::TestWithParam<std::string> {};

TEST_P(LspGolden, Transcript) {
  const fs::path case_dir = source_dir() / "tests/lsp/golden" / GetParam();
  const fs::path scratch = fs::temp_directory_path() / ("rung-lsp-golden-" + std::to_string(::getpid())) / GetParam();
  fs::remove_all(scratch);
  fs::create_directories(scratch);
  if (fs::exists(case_dir / "workspace")) fs::copy(case_dir / "workspace", scratch, fs::copy_options::recursive);

  LspTranscript client(scratch);
  std::istringstream script(read_file(case_dir / "session.jsonl"));
  std::string line;
  int line_number = 0;
  while (std::getline(script, line)) {
    ++line_number;
    if (line.find_first_not_of(" \t\r") == std::string::npos || line[line.find_first_not_of(" \t")] == '#') continue;
    const lsp::Json message = lsp::Json::parse(line, nullptr, false);
    ASSERT_FALSE(message.is_discarded()) << "session.jsonl:" << line_number << ": not JSON";
    if (!message.contains("rung-test")) {
      client.send(message);
      continue;
    }
    const std::string action = message["rung-test"];
    const fs::path path = scratch / message.value("path", "");
    if (action == "initialize") {
      client.initialize(message.value("capabilities", lsp::Json()), message.value("record", false));
    } else if (action == "open") {
      client.send({{"jsonrpc", "2.0"},
                   {"method", "textDocument/didOpen"},
                   {"params",
                    {{"textDocument",
                      {{"uri", client.root_uri() + "/" + message["path"].get<std::string>()},
                       {"languageId", "iec61131"},
                       {"version", 1},
                       {"text", read_file(path)}}}}}});
    } else if (action == "write") {
      write_file(path, message["text"].get<std::string>());
    } else if (action == "delete") {
      fs::remove(path);
    } else {
      FAIL() << "session.jsonl:" << line_number << ": unknown rung-test action " << action;
    }
  }
  const std::string actual = lsp::Json(client.messages()).dump(2) + "\n";
  const fs::path expected_file = case_dir / "expected.json";
  if (update_golden()) {
    write_file(expected_file, actual);
  } else {
    ASSERT_TRUE(fs::exists(expected_file)) << "no expected.json; run with RUNG_UPDATE_GOLDEN=1 and review it";
    EXPECT_EQ(read_file(expected_file), actual) << "case " << GetParam();
  }
  fs::remove_all(scratch);
}

INSTANTIATE_TEST_SUITE_P(Cases, LspGolden, ::testing::ValuesIn(golden_cases()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           std::string name = info.param;
                           for (char& c : name) {
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           }
                           return name;
                         });

}  // namespace
}  // namespace rung::test
