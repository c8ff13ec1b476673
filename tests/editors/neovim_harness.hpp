// Neovim for the end-to-end tests: `nvim --headless -u nvim/init.lua` running one scenario of
// nvim/<group>_scenarios.lua. Skips the test when nvim is not installed (scripts/setup installs
// Debian's neovim), never otherwise.
#pragma once

#include "tests/editors/editor_harness.hpp"

namespace rung::test {

class NeovimTest : public EditorTest {
 protected:
  void SetUp() override {
    nvim_ = find_on_path("nvim");
    if (nvim_.empty()) GTEST_SKIP() << "nvim is not installed (scripts/setup installs it)";
    EditorTest::SetUp();
  }

  // Runs scenario "<group>.<name>" and returns what it recorded.
  nlohmann::json run_scenario(const std::string& scenario,
                              std::vector<std::pair<std::string, std::string>> env = {}) const {
    env.emplace_back("RUNG_EDITOR_SCENARIO", scenario);
    return run_editor(env,
                      {nvim_.string(), "--headless", "-u", (scripts() / "nvim/init.lua").string(), "-i", "NONE", "-n"});
  }

  std::filesystem::path nvim_;
};

// Whether the server announced `capability` in its initialize answer, as Neovim recorded it.
inline bool announces(const nlohmann::json& result, const std::string& capability) {
  const auto& caps = result.value("capabilities", nlohmann::json::object());
  return caps.contains(capability) && !caps[capability].is_null() && caps[capability] != false;
}

}  // namespace rung::test
