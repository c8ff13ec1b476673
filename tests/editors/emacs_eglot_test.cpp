// Emacs with eglot (Debian's emacs-nox and elpa-eglot) driving `rung lsp`, with the setup of
// docs/editors/emacs.md (emacs/rung-eglot.el), on a copy of tests/editors/fixture:
// emacs/eglot_test.el opens PLC_PRG.st, starts eglot, waits for flymake's diagnostics, asks for
// hover when the server offers it and jumps to a definition in another file with xref.

#include <gtest/gtest.h>

#include <string>

#include "tests/editors/editor_harness.hpp"

namespace rung::test {
namespace {

using nlohmann::json;

class EmacsEglotTest : public EditorTest {
 protected:
  void SetUp() override {
    emacs_ = find_on_path("emacs");
    if (emacs_.empty()) GTEST_SKIP() << "emacs is not installed (scripts/setup installs emacs-nox and elpa-eglot)";
    EditorTest::SetUp();
  }
  std::filesystem::path emacs_;
};

TEST_F(EmacsEglotTest, DiagnosticsHoverAndDefinition) {
  // --batch skips the user's init file but not Debian's site start, which puts elpa-eglot on
  // the load path.
  const json r = run_editor({}, {emacs_.string(), "--batch", "-l", (scripts() / "emacs/rung-eglot.el").string(), "-l",
                                 (scripts() / "emacs/eglot_test.el").string()});
  ASSERT_TRUE(finished(r));
  EXPECT_EQ(r["mode"], "iec61131-mode");

  // flymake shows rung lint's L030 on the CASE of line 10 as a warning.
  json case_warning;
  for (const auto& d : r["diagnostics"])
    if (d["text"].get<std::string>().find("[L030]") != std::string::npos) case_warning = d;
  ASSERT_FALSE(case_warning.is_null()) << r["diagnostics"].dump(1);
  EXPECT_EQ(case_warning["line"], 10);
  EXPECT_EQ(case_warning["col"], 0);
  EXPECT_EQ(case_warning["type"], "eglot-warning");
  EXPECT_NE(case_warning["text"].get<std::string>().find("CASE on nStep has no ELSE"), std::string::npos);

  // M-. on fbMixer.bMotor in PLC_PRG.st opens FB_Mixer.st at the output's declaration.
  EXPECT_EQ(r["definition"]["file"], "FB_Mixer.st");
  EXPECT_EQ(r["definition"]["line"], 8);
  EXPECT_EQ(r["definition"]["col"], 4);

  // Hover on the type FB_Mixer: its declaration and doc comment, when the server offers hover.
  ASSERT_EQ(r["hover_offered"], true) << r.dump(1);
  const std::string hover = r["hover"]["contents"].dump();
  EXPECT_NE(hover.find("FUNCTION_BLOCK FB_Mixer"), std::string::npos) << hover;
  EXPECT_NE(hover.find("Runs the mixer motor"), std::string::npos) << hover;
}

}  // namespace
}  // namespace rung::test
