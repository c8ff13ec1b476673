// rung's tree-sitter parser and grammar/queries loaded into a real Neovim the way
// docs/editors/neovim.md sets them up (parser/iec61131.so and queries/iec61131/ on the
// runtimepath): the highlight captures Neovim computes for highlight_sample.st, and every query
// file accepted by this Neovim's query engine (Debian's 0.7 is older than the documented 0.9).
// The parser is compiled by the build (tests/editors/CMakeLists.txt) with the documented
// `cc -shared` command.

#include <gtest/gtest.h>

#include <string>

#include "tests/editors/neovim_harness.hpp"

namespace rung::test {
namespace {

using nlohmann::json;

class NeovimHighlightTest : public NeovimTest {
 protected:
  json run(const std::string& scenario) {
    const std::filesystem::path runtime = dir_ / "runtime";
    std::filesystem::create_directories(runtime / "parser");
    std::filesystem::create_directories(runtime / "queries");
    std::filesystem::create_symlink(RUNG_EDITOR_PARSER, runtime / "parser/iec61131.so");
    std::filesystem::create_directory_symlink(source_dir() / "grammar/queries", runtime / "queries/iec61131");
    return run_scenario(scenario, {{"RUNG_EDITOR_RUNTIME", runtime.string()},
                                   {"RUNG_EDITOR_SAMPLE", (scripts() / "highlight_sample.st").string()}});
  }
};

// The capture Neovim colours a token with: of the captures of exactly that text at its first
// place on the line, the last one (later patterns win). @spell only marks text for spell checking.
std::string capture_of(const json& captures, int line, const std::string& text) {
  std::string name = "(no capture)";
  int col = -1;
  for (const auto& c : captures) {
    if (c["line"] != line || c["text"] != text || c["name"] == "spell") continue;
    if (col == -1) col = c["col"].get<int>();
    if (c["col"] == col) name = c["name"].get<std::string>();
  }
  return name;
}

TEST_F(NeovimHighlightTest, CapturesOfTheSampleFile) {
  ASSERT_TRUE(std::filesystem::exists(RUNG_EDITOR_PARSER)) << "build target rung_editor_parser";
  const json r = run("highlight.captures");
  ASSERT_TRUE(finished(r));
  EXPECT_EQ(r["has_error"], false) << "the sample file has a syntax error";
  const json& c = r["captures"];
  struct Token {
    int line;
    const char* text;
    const char* capture;
  };
  const Token tokens[] = {
      {1, "(** Scales a raw analog value. *)", "comment.documentation"},
      {2, "FUNCTION_BLOCK", "keyword.function"},
      {2, "FB_Scale", "type"},
      {3, "VAR_INPUT", "keyword"},
      {4, "iRaw", "variable.parameter"},
      {4, "INT", "type.builtin"},
      {4, "// raw value from the card", "comment"},
      {9, "CONSTANT", "keyword.modifier"},
      {10, "MAX_RAW", "constant"},
      {10, ":=", "operator"},
      {10, "27648", "number"},
      {13, "STRING", "type.builtin"},
      {13, "'bar'", "string"},
      {14, "TON", "type.builtin"},
      {15, "TRUE", "boolean"},
      {17, "tDelay", "function.call"},
      {17, "IN", "variable.parameter"},
      {17, "bReady", "variable"},
      {17, "T#500MS", "string.special"},
      {17, ";", "punctuation.delimiter"},
      {18, "IF", "keyword.conditional"},
      {18, "Q", "variable.member"},
      {19, "INT_TO_REAL", "function.builtin"},
      {19, "LIMIT", "function.builtin"},
      {19, "1.5", "number.float"},
      {20, "Report", "function.call"},
      {22, "END_FUNCTION_BLOCK", "keyword.function"},
  };
  for (const Token& t : tokens)
    EXPECT_EQ(capture_of(c, t.line, t.text), t.capture) << "line " << t.line << " '" << t.text << "'";
}

TEST_F(NeovimHighlightTest, EveryQueryFileLoads) {
  const json r = run("highlight.query_files");
  ASSERT_TRUE(finished(r));
  for (const char* name : {"highlights", "folds", "indents", "locals", "injections"})
    EXPECT_EQ(r["loaded"][name], true) << name << ".scm was not found";
}

}  // namespace
}  // namespace rung::test
