// `rung lint` end to end: the real binary on temporary projects (exit codes, the three output
// formats, --fix on files in other encodings and line ends, the baseline workflow, rung.toml).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "checker/lint/lint_rule.hpp"
#include "tests/support/rung_process.hpp"

namespace rung {
namespace {

using LintRun = test::RungRun;

class LintCommand : public test::TempFolderTest {
 protected:
  // Runs `rung lint ARGS` in the project folder.
  LintRun lint(const std::string& args) const { return test::run_rung_in(dir_, "lint " + args); }
};

// A project file with one self-assignment (L035, a warning with a fix) and nothing else to say.
constexpr const char* kProgram = R"(PROGRAM Main
VAR
    nCount : INT;
END_VAR
nCount := nCount + 1;
nCount := nCount;
END_PROGRAM
)";

// rung.toml with only L031 and L035 on (what these tests look at does not depend on the other
// rules), `rules` added to [lint.rules], `lint` to [lint].
std::string config(const std::string& rules = "", const std::string& lint = "") {
  std::string text = "[lint]\n" + lint + "[lint.rules]\n" + rules;
  for (const lint::Rule& rule : lint::all_rules()) {
    if (rule.code != "L031" && rule.code != "L035") text += std::string(rule.code) + " = \"off\"\n";
  }
  return text;
}

size_t count(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST_F(LintCommand, WarningsExitZeroErrorsExitOneBrokenConfigExitTwo) {
  write("rung.toml", config());
  write("Main.st", kProgram);
  LintRun run = lint("");
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("Main.st:6:1: warning[L035]: 'nCount' is assigned to itself"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("= fix: "), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("(rung lint --fix)"), std::string::npos) << run.out;
  EXPECT_NE(run.err.find("0 errors, 1 warning in 1 file"), std::string::npos) << run.err;

  write("rung.toml", config("self-assignment = \"error\"\n"));
  run = lint("");
  EXPECT_EQ(run.exit_code, 1) << run.err;
  EXPECT_NE(run.out.find("error[L035]"), std::string::npos) << run.out;

  write("rung.toml", config("L035 = \"off\"\n"));
  run = lint("");
  EXPECT_EQ(run.exit_code, 0);
  EXPECT_EQ(run.out.find("L035"), std::string::npos) << run.out;

  write("rung.toml", "[lint.rules]\nL035 = \"loud\"\n");
  run = lint("");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("P003"), std::string::npos) << run.err;

  EXPECT_EQ(lint("no_such_folder").exit_code, 2);
}

TEST_F(LintCommand, JsonAndSarifCarryTheFix) {
  write("rung.toml", config());
  write("Main.st", kProgram);
  LintRun run = lint("--format json");
  EXPECT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::json json = nlohmann::json::parse(run.out);
  EXPECT_EQ(json["files"], 1);
  EXPECT_EQ(json["errors"], 0);
  EXPECT_EQ(json["warnings"], 1);
  ASSERT_EQ(json["diagnostics"].size(), 1u);
  const nlohmann::json& finding = json["diagnostics"][0];
  EXPECT_EQ(finding["code"], "L035");
  EXPECT_EQ(finding["severity"], "warning");
  EXPECT_EQ(finding["start"]["line"], 6);
  ASSERT_TRUE(finding.contains("fix")) << finding.dump();
  EXPECT_FALSE(finding["fix"]["description"].get<std::string>().empty());
  ASSERT_FALSE(finding["fix"]["edits"].empty());
  EXPECT_EQ(finding["fix"]["edits"][0]["start"]["line"], 6);
  EXPECT_TRUE(finding["fix"]["edits"][0]["text"].is_string());

  run = lint("--format sarif");
  EXPECT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::json sarif = nlohmann::json::parse(run.out);
  EXPECT_EQ(sarif["version"], "2.1.0");
  EXPECT_NE(sarif["$schema"].get<std::string>().find("sarif-2.1.0"), std::string::npos);
  const nlohmann::json& sarif_run = sarif["runs"][0];
  EXPECT_EQ(sarif_run["tool"]["driver"]["name"], "rung");
  bool rule_listed = false;
  for (const auto& rule : sarif_run["tool"]["driver"]["rules"]) rule_listed |= rule["id"] == "L035";
  EXPECT_TRUE(rule_listed);
  ASSERT_EQ(sarif_run["results"].size(), 1u);
  const nlohmann::json& result = sarif_run["results"][0];
  EXPECT_EQ(result["ruleId"], "L035");
  EXPECT_EQ(result["level"], "warning");
  EXPECT_EQ(result["locations"][0]["physicalLocation"]["region"]["startLine"], 6);
  const nlohmann::json& change = result["fixes"][0]["artifactChanges"][0];
  EXPECT_TRUE(change["artifactLocation"]["uri"].get<std::string>().ends_with("Main.st"));
  EXPECT_EQ(change["replacements"][0]["deletedRegion"]["startLine"], 6);
  EXPECT_TRUE(change["replacements"][0]["insertedContent"]["text"].is_string());
}

TEST_F(LintCommand, FixRewritesTheFileInItsEncodingAndLineEnds) {
  write("rung.toml", config());
  // cp1252 (0xE9 is 'é') with CRLF line ends; two fixable findings on one line.
  const std::string original =
      "PROGRAM Main\r\nVAR\r\n    nCount : INT; (* Z\xE9hler *)\r\nEND_VAR\r\nnCount := nCount + 1;\r\n"
      "nCount := nCount;;\r\nEND_PROGRAM\r\n";
  write("Main.st", original);
  LintRun run = lint("--fix");
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.err.find("fixed 2 findings in 1 file"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("0 errors, 0 warnings"), std::string::npos) << run.err;
  const std::string fixed = read("Main.st");
  EXPECT_NE(fixed, original);
  EXPECT_EQ(fixed.find("nCount := nCount;"), std::string::npos) << fixed;
  EXPECT_EQ(fixed.find(";;"), std::string::npos) << fixed;
  EXPECT_NE(fixed.find("Z\xE9hler"), std::string::npos) << "the file is no longer cp1252";
  EXPECT_EQ(count(fixed, "\n"), count(fixed, "\r\n")) << "a line lost its CR";
  EXPECT_NE(fixed.find("nCount := nCount + 1;\r\n"), std::string::npos);
  // Nothing left to fix: a second run changes nothing.
  run = lint("--fix");
  EXPECT_EQ(run.exit_code, 0);
  EXPECT_EQ(read("Main.st"), fixed);
}

TEST_F(LintCommand, FixKeepsAUtf8BomAndLeavesFilesWithSyntaxErrorsAlone) {
  write("rung.toml", config());
  write("Main.st", std::string("\xEF\xBB\xBF") + kProgram);
  const std::string broken = "PROGRAM Broken\nVAR x : INT; END_VAR\nx := x;\nIF x THEN\nEND_PROGRAM\n";
  write("Broken.st", broken);
  const LintRun run = lint("--fix");
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(read("Main.st").rfind("\xEF\xBB\xBF", 0), 0u) << "the BOM was dropped";
  EXPECT_EQ(read("Main.st").find("nCount := nCount;"), std::string::npos);
  EXPECT_EQ(read("Broken.st"), broken);
  EXPECT_NE(run.err.find("Broken.st: not fixed"), std::string::npos) << run.err;
}

TEST_F(LintCommand, WriteBaselineThenOnlyNewFindingsAreReported) {
  write("rung.toml", config("", "baseline = \"ci/baseline.json\"\n"));
  write("Main.st", kProgram);
  LintRun run = lint("--write-baseline");
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.err.find("wrote 1 finding of 1 file"), std::string::npos) << run.err;
  const std::string baseline = read("ci/baseline.json");
  EXPECT_NE(baseline.find("\"code\": \"L035\""), std::string::npos) << baseline;
  EXPECT_NE(baseline.find("\"path\": \"Main.st\""), std::string::npos) << baseline;
  EXPECT_NE(baseline.find("\"pou\": \"Main\""), std::string::npos) << baseline;

  run = lint("");
  EXPECT_EQ(run.exit_code, 0);
  EXPECT_EQ(run.out, "");
  EXPECT_NE(run.err.find("1 finding hidden by the baseline"), std::string::npos) << run.err;
  EXPECT_NE(lint("--no-baseline").out.find("L035"), std::string::npos);

  // Writing it again from the same findings gives the same bytes.
  EXPECT_EQ(lint("--write-baseline").exit_code, 0);
  EXPECT_EQ(read("ci/baseline.json"), baseline);

  // A new finding is reported; the baselined one stays hidden.
  std::string program = kProgram;
  program.insert(program.find("END_PROGRAM"), "nCount := nCount;\n");
  write("Main.st", program);
  run = lint("");
  EXPECT_EQ(count(run.out, "warning[L035]"), 1u) << run.out;
  EXPECT_NE(run.out.find("Main.st:7:1"), std::string::npos) << run.out;

  // The old finding fixed: its entry is stale.
  write("Main.st", std::string(kProgram).replace(std::string(kProgram).find("nCount := nCount;\n"), 18, ""));
  run = lint("");
  EXPECT_EQ(run.exit_code, 0);
  EXPECT_NE(run.err.find("1 baseline entry no longer match"), std::string::npos) << run.err;
}

TEST_F(LintCommand, BrokenBaselineIsAnError) {
  write("Main.st", kProgram);
  write("lint-baseline.json", "{\"version\": 7}");
  const LintRun run = lint("");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("not a rung lint baseline"), std::string::npos) << run.err;
}

TEST_F(LintCommand, SuppressionCommentsHideFindings) {
  write("rung.toml", config());
  std::string program = kProgram;
  program.replace(program.find("nCount := nCount;\n"), 18, "nCount := nCount; // rung-lint: ignore L035\n");
  write("Main.st", program);
  const LintRun run = lint("");
  EXPECT_EQ(run.exit_code, 0);
  EXPECT_EQ(run.out, "");
  // The attribute form is a pragma `rung check` accepts.
  write("Main.st", std::string("{attribute 'rung-lint' := 'ignore self-assignment'}\n") + kProgram);
  EXPECT_EQ(lint("").out, "");
  const test::RungRun check = test::run_rung_in(dir_, "check");
  EXPECT_EQ(check.exit_code, 0);
  EXPECT_EQ(check.out.find("E604"), std::string::npos) << check.out;
}

TEST_F(LintCommand, UnreadableInputIsAnErrorAsInCheck) {
  write("rung.toml", config());
  write("Main.st", kProgram);
  write("Blob.st", std::string("\x7F"
                               "ELF\x02\x01\x01\x00\x00\x00\x00\x00\x00\x00\x00\x00",
                               16));
  write("FB_Broken.TcPOU",
        "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<TcPlcObject Version=\"1.1.0.1\">\n"
        "  <POU Name=\"FB_Broken\">\n    <Declaration><![CDATA[FUNCTION_BLOCK FB_Broken]]></Declaration>\n"
        "</TcPlcObject>\n");
  const LintRun run = lint("");
  EXPECT_EQ(run.exit_code, 1) << run.err;
  EXPECT_NE(run.out.find("Blob.st:1:1: error[S009]: binary file, not PLC source text"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("FB_Broken.TcPOU:"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find(": error[S010]: "), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("warning[L035]"), std::string::npos) << run.out;
  EXPECT_NE(run.err.find("2 errors, 1 warning in 3 files"), std::string::npos) << run.err;
  // An unreadable file is never written to the baseline: it stays an error.
  EXPECT_EQ(lint("--write-baseline").exit_code, 0);
  EXPECT_EQ(lint("").exit_code, 1);
}

TEST_F(LintCommand, ListRulesShowsEveryRuleAndTheProjectSetting) {
  write("rung.toml", "[lint.rules]\nself-assignment = \"error\"\ntodo-comment = \"on\"\n");
  const LintRun run = lint("--list-rules");
  EXPECT_EQ(run.exit_code, 0) << run.err;
  for (const lint::Rule& rule : lint::all_rules()) {
    EXPECT_NE(run.out.find(std::string(rule.code) + " "), std::string::npos) << rule.code;
  }
  const size_t line = run.out.find("L035 ");
  ASSERT_NE(line, std::string::npos);
  const std::string row = run.out.substr(line, run.out.find('\n', line) - line);
  EXPECT_NE(row.find("self-assignment"), std::string::npos) << row;
  EXPECT_NE(row.find("warning"), std::string::npos) << row;
  EXPECT_TRUE(row.ends_with("error")) << row;
}

}  // namespace
}  // namespace rung
