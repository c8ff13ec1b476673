// Neovim 0.7+ driving `rung lsp` through its built-in LSP client, with the setup of
// docs/editors/neovim.md (nvim/rung_lsp_0_7.lua), on a copy of tests/editors/fixture. Each test
// runs one scenario of nvim/lsp_scenarios.lua and checks what Neovim showed or wrote.
//
// A test whose feature the server does not announce yet is skipped with that reason; once
// the server announces the capability, the test must pass.

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <sstream>
#include <string>
#include <vector>

#include "tests/editors/neovim_harness.hpp"

namespace rung::test {
namespace {

using nlohmann::json;

class NeovimLspTest : public NeovimTest {};

// `text` with every whole-word `from` replaced by `to` (std::regex trips g++ 12's warnings).
std::string replace_word(const std::string& text, const std::string& from, const std::string& to) {
  auto is_word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  std::string out;
  for (std::size_t i = 0; i < text.size();) {
    const bool starts_word = i == 0 || !is_word(text[i - 1]);
    const std::size_t end = i + from.size();
    if (starts_word && text.compare(i, from.size(), from) == 0 && (end == text.size() || !is_word(text[end]))) {
      out += to;
      i = end;
    } else {
      out += text[i++];
    }
  }
  return out;
}

bool has_line_starting_with(const std::string& text, const std::string& word) {
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    const std::size_t first = line.find_first_not_of(" \t");
    if (first != std::string::npos && line.compare(first, word.size(), word) == 0) return true;
  }
  return false;
}

std::string joined(const json& lines) {
  std::string text;
  for (const auto& line : lines) text += line.get<std::string>() + "\n";
  return text;
}

TEST_F(NeovimLspTest, ShowsDiagnosticsAndFollowsEdits) {
  const json r = run_scenario("lsp.diagnostics");
  ASSERT_TRUE(finished(r));

  // As opened: rung lint's L030 on the CASE (line 10), a warning.
  const json case_warning = diagnostic_with_code(r["opened"], "L030");
  ASSERT_FALSE(case_warning.is_null()) << r["opened"].dump(1);
  EXPECT_EQ(case_warning["lnum"], 9);
  EXPECT_EQ(case_warning["col"], 0);
  EXPECT_EQ(case_warning["severity"], 2);  // vim.diagnostic.severity.WARN
  EXPECT_TRUE(diagnostic_with_code(r["opened"], "E001").is_null());

  // The typo typed into line 9 (`fbMixr`) is an error on exactly that name.
  const json typo = diagnostic_with_code(r["typo"], "E001");
  ASSERT_FALSE(typo.is_null()) << r["typo"].dump(1);
  EXPECT_EQ(typo["lnum"], 8);
  EXPECT_EQ(typo["col"], 12);
  EXPECT_EQ(typo["end_col"], 18);
  EXPECT_EQ(typo["severity"], 1);  // ERROR
  EXPECT_NE(typo["message"].get<std::string>().find("fbMixr"), std::string::npos) << typo["message"];

  // Undoing the typo clears the error and keeps the lint warning.
  EXPECT_TRUE(diagnostic_with_code(r["fixed"], "E001").is_null()) << r["fixed"].dump(1);
  EXPECT_FALSE(diagnostic_with_code(r["fixed"], "L030").is_null()) << r["fixed"].dump(1);
}

TEST_F(NeovimLspTest, GoesToDefinitionsInOtherFiles) {
  const json r = run_scenario("lsp.definition");
  ASSERT_TRUE(finished(r));
  // FB_Mixer (the type of fbMixer in PLC_PRG.st) -> its FUNCTION_BLOCK line in FB_Mixer.st.
  EXPECT_EQ(r["type"]["file"], "FB_Mixer.st");
  EXPECT_EQ(r["type"]["line"], 2);
  EXPECT_EQ(r["type"]["col"], 15);
  EXPECT_EQ(r["type"]["text"], "FUNCTION_BLOCK FB_Mixer");
  // fbMixer.bMotor -> the output's declaration.
  EXPECT_EQ(r["member"]["file"], "FB_Mixer.st");
  EXPECT_EQ(r["member"]["line"], 8);
  EXPECT_EQ(r["member"]["col"], 4);
  EXPECT_EQ(r["member"]["text"], "    bMotor : BOOL;");
}

TEST_F(NeovimLspTest, HoverShowsDeclarationAndDocComment) {
  const json r = run_scenario("lsp.hover");
  ASSERT_TRUE(r.contains("capabilities")) << r.dump(1);
  ASSERT_TRUE(announces(r, "hoverProvider")) << r["capabilities"].dump(1);
  ASSERT_TRUE(finished(r));
  // The float shows the declaration (markdown code block, rendered by Neovim) and the doc comment.
  EXPECT_EQ(r["type_hover"][0], "FUNCTION_BLOCK FB_Mixer") << r["type_hover"].dump(1);
  const std::string type_hover = joined(r["type_hover"]);
  EXPECT_NE(type_hover.find("    bMotor : BOOL;"), std::string::npos) << type_hover;
  EXPECT_NE(type_hover.find("Runs the mixer motor for the configured time after a start."), std::string::npos)
      << type_hover;
  // The standard TON: its interface and what it does, from rung's library stubs.
  EXPECT_EQ(r["standard_fb_hover"][0], "FUNCTION_BLOCK TON") << r["standard_fb_hover"].dump(1);
  const std::string ton_hover = joined(r["standard_fb_hover"]);
  EXPECT_NE(ton_hover.find("on-delay timer"), std::string::npos) << ton_hover;
}

TEST_F(NeovimLspTest, OmniCompletionListsMembersAfterDot) {
  const json r = run_scenario("lsp.completion");
  ASSERT_TRUE(r.contains("capabilities")) << r.dump(1);
  ASSERT_TRUE(announces(r, "completionProvider")) << r["capabilities"].dump(1);
  ASSERT_TRUE(finished(r));
  // What code outside FB_Mixer may use of the instance: its inputs and outputs; not its
  // internal tRun, not PLC_PRG's own variables, no keywords.
  std::vector<std::string> items = r["items"].get<std::vector<std::string>>();
  std::sort(items.begin(), items.end());
  EXPECT_EQ(items, (std::vector<std::string>{"bDone", "bMotor", "bStart", "stConfig"}));
}

TEST_F(NeovimLspTest, RenamesAcrossFilesAndWritesThem) {
  const std::string fb_before = read_file(project() / "src/FB_Mixer.st");
  const std::string prg_before = read_file(project() / "src/PLC_PRG.st");
  const json r = run_scenario("lsp.rename");
  ASSERT_TRUE(finished(r));
  // Every bMotor, and nothing else, became bMotorOn: the declaration and the assignment in
  // FB_Mixer.st (loaded by Neovim for the edit) and the use in PLC_PRG.st.
  EXPECT_EQ(read_file(project() / "src/FB_Mixer.st"), replace_word(fb_before, "bMotor", "bMotorOn"));
  EXPECT_EQ(read_file(project() / "src/PLC_PRG.st"), replace_word(prg_before, "bMotor", "bMotorOn"));
}

TEST_F(NeovimLspTest, FormatsTheBufferLikeRungFmt) {
  // What `rung fmt` makes of the same file in a pristine copy of the project.
  const std::filesystem::path pristine = dir_ / "pristine";
  std::filesystem::copy(project(), pristine, std::filesystem::copy_options::recursive);
  ASSERT_EQ(run_rung_in(pristine, "fmt src/Messy.st").exit_code, 0);
  const std::string expected = read_file(pristine / "src/Messy.st");

  const json r = run_scenario("lsp.format");
  ASSERT_TRUE(finished(r));
  EXPECT_NE(r["before"], r["after"]);
  EXPECT_EQ(joined(r["after"]), expected);
  EXPECT_EQ(read_file(project() / "src/Messy.st"), expected);
}

TEST_F(NeovimLspTest, CodeActionAddsCaseElse) {
  const std::string before = read_file(project() / "src/PLC_PRG.st");
  const json r = run_scenario("lsp.code_action");
  ASSERT_TRUE(r.contains("capabilities")) << r.dump(1);
  ASSERT_TRUE(announces(r, "codeActionProvider")) << r["capabilities"].dump(1);
  ASSERT_TRUE(finished(r)) << "actions offered: " << r.value("titles", json::array());
  const auto& lines = r["lines"];
  // The lines before the CASE are untouched; an ELSE appears between CASE and END_CASE.
  const std::string text = joined(lines);
  const std::size_t case_at = text.find("CASE nStep OF"), end_at = text.find("END_CASE");
  ASSERT_NE(case_at, std::string::npos) << text;
  ASSERT_NE(end_at, std::string::npos) << text;
  EXPECT_EQ(text.substr(0, case_at), before.substr(0, before.find("CASE nStep OF")));
  EXPECT_TRUE(has_line_starting_with(text.substr(case_at, end_at - case_at), "ELSE")) << text;
  EXPECT_TRUE(diagnostic_with_code(r["diagnostics"], "L030").is_null()) << r["diagnostics"].dump(1);
}

}  // namespace
}  // namespace rung::test
