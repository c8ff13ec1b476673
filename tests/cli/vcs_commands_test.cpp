// `rung diff`, `rung textconv`, `rung git setup` and `rung merge-file` on real repositories made
// by the test with the git command (and one with libgit2), as a user or CI job runs them.
#include <git2.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "tests/support/test_paths.hpp"
#include "tests/vcs/git_fixture.hpp"

namespace rung {
namespace {

namespace fs = std::filesystem;
using test::crlf;

std::string example(const std::string& name) {
  return test::read_file(test::source_dir() / "examples/conveyor" / name);
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

class VcsCommands : public test::GitRepoTest {
 protected:
  // The example project, committed.
  void commit_example() {
    for (const char* f : {"src/E_ConveyorState.st", "src/FB_Conveyor.st", "src/GVL_IO.st", "src/PLC_PRG.st",
                          "src/ST_ConveyorConfig.st", "src/config.st", "twincat/FB_Lamp.TcPOU"}) {
      put(f, example(f));
    }
    put("README.md", "not PLC code\n");
    commit("example");
  }
};

TEST_F(VcsCommands, DiffBetweenTwoCommitsGolden) {
  commit_example();
  put("src/FB_Conveyor.st", replaced(replaced(example("src/FB_Conveyor.st"), "iSpeed  : INT;", "iSpeed  : DINT;"),
                                     "nParts := nParts + 1;", "nParts := nParts + 2;"));
  put("twincat/FB_Lamp.TcPOU",
      replaced(example("twincat/FB_Lamp.TcPOU"), "tPeriod : TIME := T#1S;", "tPeriod : TIME := T#2S;"));
  fs::rename(repo_ / "src/PLC_PRG.st", repo_ / "src/Main.st");
  put("README.md", "changed, but not PLC code\n");
  commit("second");
  const test::RungRun human = rung("diff HEAD~1 HEAD");
  EXPECT_EQ(human.exit_code, 0) << human.err;
  EXPECT_EQ(human.err, "");
  expect_golden("two_commits.txt", human.out);
  const test::RungRun json = rung("diff HEAD~1 HEAD --format json");
  EXPECT_EQ(json.exit_code, 0);
  expect_golden("two_commits.json", json.out);
  const test::RungRun stat = rung("diff --stat HEAD~1..HEAD");
  expect_golden("two_commits_stat.txt", stat.out);
  // Paths limit the comparison.
  const test::RungRun one = rung("diff HEAD~1 HEAD --format json -- twincat");
  EXPECT_NE(one.out.find("\"name\": \"FB_Lamp\""), std::string::npos);
  EXPECT_EQ(one.out.find("FB_Conveyor"), std::string::npos);
  EXPECT_EQ(rung("diff --exit-code HEAD~1 HEAD").exit_code, 1);
}

TEST_F(VcsCommands, FormattingOnlyCommitAndMovedLineIdsAreNoChange) {
  commit_example();
  // Layout and keyword case of an ST file; LineIds and a GUID of the TwinCAT file.
  put("src/PLC_PRG.st", test::read_file(repo_ / "src/PLC_PRG.st") + "\n\n");
  std::string conveyor = example("src/FB_Conveyor.st");
  conveyor = replaced(conveyor, "END_IF\nELSE", "end_if\nelse");
  conveyor = replaced(conveyor, "    bStart  : BOOL;", "bStart:BOOL;");
  put("src/FB_Conveyor.st", conveyor);
  std::string lamp = example("twincat/FB_Lamp.TcPOU");
  lamp =
      replaced(lamp, "  </POU>",
               crlf("    <LineIds Name=\"FB_Lamp\">\n      <LineId Id=\"5\" Count=\"3\" />\n    </LineIds>\n  </POU>"));
  lamp = replaced(lamp, "{6a1d3c52-0b7e-4d8e-9a55-2f0c6d9e1a02}", "{00000000-0b7e-4d8e-9a55-2f0c6d9e1a02}");
  put("twincat/FB_Lamp.TcPOU", lamp);
  // Unstaged: the working tree against the index.
  const test::RungRun working = rung("diff --exit-code");
  EXPECT_EQ(working.exit_code, 0) << working.out << working.err;
  EXPECT_EQ(working.out, "");
  commit("format");
  const test::RungRun committed = rung("diff --exit-code HEAD~1 HEAD --format json");
  EXPECT_EQ(committed.exit_code, 0) << committed.out;
  EXPECT_EQ(committed.out, "{\n  \"files\": 3,\n  \"changes\": [],\n  \"errors\": [],\n  \"notes\": []\n}\n");
}

TEST_F(VcsCommands, RenamedPouAndRetypedVariableInTheIndex) {
  commit_example();
  put("src/ST_ConveyorConfig.st", replaced(example("src/ST_ConveyorConfig.st"), "ST_ConveyorConfig", "ST_BeltConfig"));
  ASSERT_EQ(git("add src/ST_ConveyorConfig.st").exit_code, 0);
  put("src/E_ConveyorState.st", replaced(example("src/E_ConveyorState.st"), "Idle", "Waiting"));  // unstaged
  const test::RungRun cached = rung("diff --cached");
  EXPECT_EQ(cached.exit_code, 0) << cached.err;
  EXPECT_EQ(cached.out, "renamed TYPE ST_BeltConfig (was ST_ConveyorConfig) (src/ST_ConveyorConfig.st)\n");
  const test::RungRun unstaged = rung("diff --stat");
  EXPECT_EQ(unstaged.out.rfind(" modified  TYPE E_ConveyorState | src/E_ConveyorState.st", 0), 0u) << unstaged.out;
}

TEST_F(VcsCommands, HostileFilesAreNamedInWarnings) {
  commit_example();
  put("twincat/FB_Broken.TcPOU", "<?xml version=\"1.0\"?>\n<TcPlcObject><POU Name=\"FB_Broken\">\n");
  put("src/Blob.st", std::string("\x00\x01\x02 binary \x00\xff", 12));
  commit("hostile");
  const test::RungRun r = rung("diff HEAD~1 HEAD");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.err.find("rung diff: warning: src/Blob.st: binary file; not PLC source\n"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("rung diff: warning: twincat/FB_Broken.TcPOU: malformed XML"), std::string::npos) << r.err;
  const test::RungRun textconv = rung("textconv twincat/FB_Broken.TcPOU");
  EXPECT_EQ(textconv.exit_code, 0);
  EXPECT_NE(textconv.err.find("rung textconv: twincat/FB_Broken.TcPOU: malformed XML"), std::string::npos)
      << textconv.err;
}

TEST_F(VcsCommands, UsageAndRepositoryErrorsExitWithTwo) {
  const test::RungRun outside = test::run_rung_in(dir_, "diff");
  EXPECT_EQ(outside.exit_code, 2);
  EXPECT_EQ(outside.err.rfind("rung diff: not a git repository", 0), 0u) << outside.err;
  commit_example();
  const test::RungRun unknown = rung("diff no-such-revision HEAD");
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_EQ(unknown.err.rfind("rung diff: unknown revision 'no-such-revision'", 0), 0u) << unknown.err;
  EXPECT_EQ(rung("diff --format yaml").exit_code, 2);
  EXPECT_EQ(rung("textconv no/such/file.st").exit_code, 2);
}

TEST_F(VcsCommands, TextconvThroughGitLog) {
  commit_example();
  const test::RungRun setup = rung("git setup");
  ASSERT_EQ(setup.exit_code, 0) << setup.err;
  EXPECT_EQ(setup.out.rfind(fs::canonical(repo_).string() + "/.gitattributes: added\n", 0), 0u) << setup.out;
  EXPECT_EQ(get(".gitattributes"),
            "# rung: PLC sources as ST text in diffs, merged on the syntax tree (rung git setup)\n"
            "*.TcPOU diff=rung merge=rung\n*.TcDUT diff=rung merge=rung\n*.TcGVL diff=rung merge=rung\n"
            "*.TcIO diff=rung merge=rung\n*.TcITF diff=rung merge=rung\n*.EXP diff=rung merge=rung\n"
            "*.exp diff=rung merge=rung\n*.st diff=rung merge=rung\n");
  EXPECT_EQ(git("config diff.rung.textconv").out, test::rung_binary().string() + " textconv\n");
  EXPECT_EQ(git("config merge.rung.driver").out, test::rung_binary().string() + " merge-file %O %A %B %P\n");
  // A second run adds nothing.
  const test::RungRun again = rung("git setup");
  EXPECT_EQ(again.out.find("added"), std::string::npos);
  put("twincat/FB_Lamp.TcPOU",
      replaced(example("twincat/FB_Lamp.TcPOU"), "bLamp := FALSE;\r\ntonBlink", "bLamp := TRUE;\r\ntonBlink"));
  commit("lamp on");
  const test::CommandRun log = git("log -p -1 --format=%s -- twincat/FB_Lamp.TcPOU");
  ASSERT_EQ(log.exit_code, 0) << log.out;
  EXPECT_NE(
      log.out.find("@@ -22,5 +22,5 @@ METHOD PUBLIC Off\n VAR_INPUT\n END_VAR\n \n-bLamp := FALSE;\n+bLamp := TRUE;\n "
                   "tonBlink(IN := FALSE);\n"),

      std::string::npos)
      << log.out;
  EXPECT_EQ(log.out.find("CDATA"), std::string::npos);
}

TEST_F(VcsCommands, GitMergeWithTheDriverCleanAndConflicting) {
  commit_example();
  ASSERT_EQ(rung("git setup").exit_code, 0);
  commit("attributes");
  ASSERT_EQ(git("checkout -q -b other").exit_code, 0);
  // Theirs: a method added to the TwinCAT block, a POU appended to an ST file.
  put("twincat/FB_Lamp.TcPOU",
      replaced(example("twincat/FB_Lamp.TcPOU"), "  </POU>",
               crlf("    <Method Name=\"On\" Id=\"{6a1d3c52-0b7e-4d8e-9a55-2f0c6d9e1a03}\">\n"
                    "      <Declaration><![CDATA[METHOD PUBLIC On\n]]></Declaration>\n"
                    "      <Implementation>\n        <ST><![CDATA[bLamp := TRUE;]]></ST>\n      </Implementation>\n"
                    "    </Method>\n  </POU>")));
  put("src/E_ConveyorState.st", example("src/E_ConveyorState.st") + "\nTYPE E_Theirs : (T1, T2); END_TYPE\n");
  commit("theirs");
  ASSERT_EQ(git("checkout -q main").exit_code, 0);
  // Ours: the block's body changed, another POU appended at the same place.
  put("twincat/FB_Lamp.TcPOU",
      replaced(example("twincat/FB_Lamp.TcPOU"), "bLamp := NOT bLamp;", "bLamp := NOT bLamp AND bEnable;"));
  put("src/E_ConveyorState.st", example("src/E_ConveyorState.st") + "\nTYPE E_Ours : (O1, O2); END_TYPE\n");
  commit("ours");
  const test::CommandRun merge = git("merge -q --no-edit other");
  ASSERT_EQ(merge.exit_code, 0) << merge.out;
  const std::string lamp = get("twincat/FB_Lamp.TcPOU");
  EXPECT_NE(lamp.find("bLamp := NOT bLamp AND bEnable;"), std::string::npos);
  EXPECT_NE(lamp.find("<Method Name=\"On\""), std::string::npos);
  EXPECT_EQ(
      get("src/E_ConveyorState.st"),
      example("src/E_ConveyorState.st") + "\nTYPE E_Ours : (O1, O2); END_TYPE\n\nTYPE E_Theirs : (T1, T2); END_TYPE\n");
  const test::RungRun check = rung("parse twincat/FB_Lamp.TcPOU src/E_ConveyorState.st");
  EXPECT_EQ(check.exit_code, 0) << check.out << check.err;

  // Now a real conflict: both change the same line of the method.
  ASSERT_EQ(git("checkout -q other").exit_code, 0);
  put("twincat/FB_Lamp.TcPOU",
      replaced(get("twincat/FB_Lamp.TcPOU"), "tonBlink(IN := FALSE);", "tonBlink(IN := TRUE);"));
  commit("theirs 2");
  ASSERT_EQ(git("checkout -q main").exit_code, 0);
  put("twincat/FB_Lamp.TcPOU",
      replaced(get("twincat/FB_Lamp.TcPOU"), "tonBlink(IN := FALSE);", "tonBlink(IN := bEnable);"));
  commit("ours 2");
  const test::CommandRun conflict = git("merge -q --no-edit other");
  EXPECT_NE(conflict.exit_code, 0);
  EXPECT_EQ(git("status --porcelain").out, "UU twincat/FB_Lamp.TcPOU\n");
  EXPECT_NE(get("twincat/FB_Lamp.TcPOU")
                .find(crlf("<![CDATA[bLamp := FALSE;\n<<<<<<< ours\ntonBlink(IN := bEnable);\n=======\n"
                           "tonBlink(IN := TRUE);\n>>>>>>> theirs\n]]>")),
            std::string::npos)
      << get("twincat/FB_Lamp.TcPOU");
}

// A repository written with libgit2 alone (no git command): rung reads it the same way.
TEST_F(VcsCommands, RepositoryMadeWithLibgit2) {
  git_libgit2_init();
  git_repository* repo = nullptr;
  const fs::path folder = dir_ / "lg2";
  ASSERT_EQ(git_repository_init(&repo, folder.c_str(), 0), 0);
  git_signature* who = nullptr;
  ASSERT_EQ(git_signature_new(&who, "rung", "rung@example.com", 1767225600, 0), 0);
  git_oid parent{};
  bool has_parent = false;
  for (const char* text : {"PROGRAM P\nVAR n : INT; END_VAR\nn := n + 1;\nEND_PROGRAM\n",
                           "PROGRAM P\nVAR n : LINT; END_VAR\nn := n + 1;\nEND_PROGRAM\n"}) {
    test::write_file(folder / "P.st", text);
    git_index* index = nullptr;
    ASSERT_EQ(git_repository_index(&index, repo), 0);
    ASSERT_EQ(git_index_add_bypath(index, "P.st"), 0);
    ASSERT_EQ(git_index_write(index), 0);
    git_oid tree_id{};
    ASSERT_EQ(git_index_write_tree(&tree_id, index), 0);
    git_index_free(index);
    git_tree* tree = nullptr;
    ASSERT_EQ(git_tree_lookup(&tree, repo, &tree_id), 0);
    git_commit* parent_commit = nullptr;
    if (has_parent) {
      ASSERT_EQ(git_commit_lookup(&parent_commit, repo, &parent), 0);
    }
    const git_commit* parents[1] = {parent_commit};
    git_oid commit_id{};
    ASSERT_EQ(git_commit_create(&commit_id, repo, "HEAD", who, who, nullptr, "c", tree, has_parent ? 1 : 0, parents),
              0);
    git_tree_free(tree);
    if (parent_commit != nullptr) git_commit_free(parent_commit);
    parent = commit_id;
    has_parent = true;
  }
  git_signature_free(who);
  git_repository_free(repo);
  git_libgit2_shutdown();
  const test::RungRun r = test::run_rung_in(folder, "diff HEAD~1 HEAD --color never");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, "modified PROGRAM P (P.st)\n  ~ n: (retyped)\n    -VAR n : INT\n    +VAR n : LINT\n");
}

}  // namespace
}  // namespace rung
