// Drives the real `rung` binary the way a user or a CI script does: exit codes, output formats.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/support/test_paths.hpp"

namespace rung {
namespace {

struct RunResult {
  int exit_code;
  std::string out;
  std::string err;
};

RunResult run_rung(const std::string& args) {
  // CTest runs tests in parallel processes: every run gets its own output files.
  static int counter = 0;
  auto dir = std::filesystem::temp_directory_path();
  std::string stem = "rung_cli_test_" + std::to_string(getpid()) + "_" + std::to_string(counter++);
  auto out = dir / (stem + ".out");
  auto err = dir / (stem + ".err");
  std::string cmd = "cd '" + test::source_dir().string() + "' && '" + test::rung_binary().string() + "' " + args +
                    " >'" + out.string() + "' 2>'" + err.string() + "' </dev/null";
  int status = std::system(cmd.c_str());
  RunResult r{WIFEXITED(status) ? WEXITSTATUS(status) : -1, test::read_file(out), test::read_file(err)};
  std::filesystem::remove(out);
  std::filesystem::remove(err);
  return r;
}

TEST(Cli, Version) {
  RunResult r = run_rung("--version");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(r.out.rfind("rung ", 0), 0u) << r.out;
}

TEST(Cli, HelpListsCommandsAndEachCommandHasHelp) {
  RunResult r = run_rung("help");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find("parse"), std::string::npos);
  RunResult p = run_rung("parse --help");
  EXPECT_EQ(p.exit_code, 0);
  EXPECT_NE(p.out.find("--tree"), std::string::npos);
  EXPECT_NE(p.out.find("--format"), std::string::npos);
  RunResult h = run_rung("help parse");
  EXPECT_EQ(h.exit_code, 0);
  EXPECT_EQ(h.out, p.out);
}

TEST(Cli, ExplainPrintsTheDocsPageOfACode) {
  RunResult list = run_rung("explain");
  EXPECT_EQ(list.exit_code, 0);
  EXPECT_NE(list.out.find("S003"), std::string::npos);
  EXPECT_NE(list.out.find("missing-end-keyword"), std::string::npos);
  RunResult page = run_rung("explain s003");  // codes are case-insensitive
  EXPECT_EQ(page.exit_code, 0);
  EXPECT_EQ(page.out, test::read_file(test::source_dir() / "docs/diagnostics/S003.md"));
  RunResult unknown = run_rung("explain S999");
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_NE(unknown.err.find("S999"), std::string::npos);
}

TEST(Cli, InitWritesACommentedRungTomlOnce) {
  auto dir = std::filesystem::temp_directory_path() / ("rung_init_test_" + std::to_string(getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  RunResult first = run_rung("init '" + dir.string() + "'");
  EXPECT_EQ(first.exit_code, 0) << first.err;
  std::string text = test::read_file(dir / "rung.toml");
  EXPECT_NE(text.find("profile = \"codesys\""), std::string::npos);
  EXPECT_NE(text.find("name = \"" + dir.filename().string() + "\""), std::string::npos);
  RunResult again = run_rung("init '" + dir.string() + "'");
  EXPECT_EQ(again.exit_code, 2);
  EXPECT_NE(again.err.find("already exists"), std::string::npos);
  EXPECT_EQ(run_rung("init --force '" + dir.string() + "'").exit_code, 0);
  std::filesystem::remove_all(dir);
}

TEST(Cli, UsageErrorsExitTwo) {
  EXPECT_EQ(run_rung("frobnicate").exit_code, 2);
  EXPECT_EQ(run_rung("parse --format xml examples").exit_code, 2);
  EXPECT_EQ(run_rung("parse").exit_code, 2);
  RunResult missing = run_rung("parse no/such/dir");
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.err.find("no/such/dir"), std::string::npos);
}

TEST(Cli, UnknownCommandIsAnErrorWithASuggestion) {
  // As cargo does: a CI script that calls a command that does not exist must fail.
  RunResult typo = run_rung("chekc examples");
  EXPECT_EQ(typo.exit_code, 2);
  EXPECT_EQ(typo.out, "");
  EXPECT_EQ(typo.err, "error: no command 'chekc'; did you mean 'check'?\n");
  RunResult far = run_rung("sevre");
  EXPECT_EQ(far.exit_code, 2);
  EXPECT_EQ(far.out, "");
  EXPECT_EQ(far.err, "error: no command 'sevre'; run 'rung help' for the list of commands\n");
  RunResult help = run_rung("help lnt");
  EXPECT_EQ(help.exit_code, 2);
  EXPECT_EQ(help.err, "error: no command 'lnt'; did you mean 'lint'?\n");
  EXPECT_EQ(run_rung("").exit_code, 0);  // no command: the overview
}

TEST(Cli, CleanProjectExitsZero) {
  RunResult r = run_rung("parse examples/conveyor");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_EQ(r.out, "");
  EXPECT_NE(r.err.find("0 errors"), std::string::npos) << r.err;
}

TEST(Cli, BrokenFileExitsOneWithFileLineColumnAndCaret) {
  RunResult r = run_rung("parse --color never examples/broken");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.out.find("examples/broken/Mistakes.st:"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("error[S"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find('^'), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("\x1b["), std::string::npos) << "no colours when not on a terminal";
  RunResult colored = run_rung("parse --color always examples/broken");
  EXPECT_NE(colored.out.find("\x1b["), std::string::npos);
}

TEST(Cli, JsonOutputIsMachineReadable) {
  RunResult r = run_rung("parse --format json examples/broken examples/conveyor");
  EXPECT_EQ(r.exit_code, 1);
  auto j = nlohmann::json::parse(r.out);
  EXPECT_GE(j["files"].get<int>(), 7);
  EXPECT_GE(j["errors"].get<int>(), 1);
  ASSERT_FALSE(j["diagnostics"].empty());
  const auto& d = j["diagnostics"][0];
  EXPECT_EQ(d["file"], "examples/broken/Mistakes.st");
  EXPECT_TRUE(d["start"]["line"].is_number());
  EXPECT_TRUE(d["code"].get<std::string>().starts_with("S"));
}

TEST(Cli, TreeOutput) {
  RunResult r = run_rung("parse --tree examples/conveyor/src/PLC_PRG.st");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find("program_declaration [1:1-"), std::string::npos) << r.out.substr(0, 400);
  EXPECT_NE(r.out.find("\"PLC_PRG\""), std::string::npos);
}

}  // namespace
}  // namespace rung
