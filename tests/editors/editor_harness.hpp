// Running a real editor (Neovim, Emacs) against the freshly built `rung lsp` in a copy of
// tests/editors/fixture: what the end-to-end editor tests share. The editor runs a scenario
// script that writes what it saw as JSON; the tests assert on that JSON. Header-only, like
// tests/support.
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "tests/support/rung_process.hpp"

namespace rung::test {

// The full path of program `name` on PATH, or an empty path when it is not installed.
inline std::filesystem::path find_on_path(const std::string& name) {
  const char* path = std::getenv("PATH");
  std::istringstream dirs(path ? path : "");
  for (std::string dir; std::getline(dirs, dir, ':');) {
    const std::filesystem::path candidate = std::filesystem::path(dir.empty() ? "." : dir) / name;
    if (access(candidate.c_str(), X_OK) == 0) return candidate;
  }
  return {};
}

// The editor must end by itself well before CTest's timeout: the scenario scripts stop
// themselves after kScenarioTimeLimitMs, `timeout` kills the editor a little later.
inline constexpr int kScenarioTimeLimitMs = 20000;
inline constexpr int kEditorKillSeconds = 30;

// A test with a fresh copy of the fixture project in <temp>/project.
class EditorTest : public TempFolderTest {
 protected:
  void SetUp() override {
    TempFolderTest::SetUp();
    std::filesystem::copy(source_dir() / "tests/editors/fixture", project(), std::filesystem::copy_options::recursive);
  }

  std::filesystem::path project() const { return dir_ / "project"; }
  std::filesystem::path scripts() const { return source_dir() / "tests/editors"; }

  // Runs `command` (argument words, quoted here) with `env` added to the environment, HOME and
  // the XDG folders moved into the test folder (the user's editor configuration stays out),
  // under `timeout`. Returns the JSON the scenario wrote; a failure when it wrote none.
  nlohmann::json run_editor(const std::vector<std::pair<std::string, std::string>>& env,
                            const std::vector<std::string>& command) const {
    const std::filesystem::path result = dir_ / "result.json", log = dir_ / "editor.log";
    const std::filesystem::path home = dir_ / "home";
    std::filesystem::create_directories(home);
    std::string line = "cd " + quote(project().string()) + " && env";
    auto set = [&](const std::string& name, const std::string& value) { line += " " + name + "=" + quote(value); };
    set("HOME", home.string());
    for (const char* xdg : {"XDG_CONFIG_HOME", "XDG_DATA_HOME", "XDG_STATE_HOME", "XDG_CACHE_HOME"})
      set(xdg, (home / xdg).string());
    set("RUNG_LSP_COMMAND", rung_binary().string());
    set("RUNG_EDITOR_PROJECT", project().string());
    set("RUNG_EDITOR_RESULT", result.string());
    set("RUNG_EDITOR_TIME_LIMIT_MS", std::to_string(kScenarioTimeLimitMs));
    for (const auto& [name, value] : env) set(name, value);
    line += " timeout -k 5 " + std::to_string(kEditorKillSeconds);
    for (const std::string& word : command) line += " " + quote(word);
    line += " </dev/null >" + quote(log.string()) + " 2>&1";
    const int status = std::system(line.c_str());
    if (!std::filesystem::exists(result)) {
      ADD_FAILURE() << "the editor wrote no result (exit status " << status << "); its output:\n" << read_file(log);
      return nlohmann::json::object();
    }
    return nlohmann::json::parse(read_file(result), nullptr, /*allow_exceptions=*/false);
  }

 private:
  static std::string quote(const std::string& word) {
    std::string quoted = "'";
    for (char c : word) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return quoted + "'";
  }
};

// The scenario ran to its end: no Lua or Lisp error, no time-out.
inline ::testing::AssertionResult finished(const nlohmann::json& result) {
  if (!result.is_object()) return ::testing::AssertionFailure() << "the result is not a JSON object";
  if (result.contains("error")) return ::testing::AssertionFailure() << result["error"].get<std::string>();
  return ::testing::AssertionSuccess();
}

// The first entry of a list of diagnostics with this code, or null.
inline nlohmann::json diagnostic_with_code(const nlohmann::json& list, const std::string& code) {
  for (const auto& d : list)
    if (d.value("code", "") == code) return d;
  return nullptr;
}

}  // namespace rung::test
