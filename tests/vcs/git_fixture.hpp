// A git repository made inside a test, driven with the git command (as a user would) and with
// rung. Header-only, for tests/vcs and tests/cli.
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "tests/support/rung_process.hpp"
#include "tests/support/test_paths.hpp"

namespace rung::test {

struct CommandRun {
  int exit_code = -1;
  std::string out;  // stdout and stderr together
};

// `text` with CRLF line ends (TwinCAT writes its files so).
inline std::string crlf(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c == '\n') out += '\r';
    out += c;
  }
  return out;
}

// Runs a shell command in `folder`, stdout and stderr captured together.
inline CommandRun run_shell_in(const std::filesystem::path& folder, const std::string& command) {
  const std::filesystem::path out = folder.parent_path() / (folder.filename().string() + ".out");
  const std::string full = "cd '" + folder.string() + "' && (" + command + ") >'" + out.string() + "' 2>&1";
  const int status = std::system(full.c_str());
  CommandRun run{WIFEXITED(status) ? WEXITSTATUS(status) : -1, read_file(out)};
  std::filesystem::remove(out);
  return run;
}

// The git command with an identity and settings of its own (no user or system config read).
inline std::string git_command() {
  return "env GIT_CONFIG_NOSYSTEM=1 HOME=/nonexistent-rung-test GIT_AUTHOR_NAME=rung GIT_AUTHOR_EMAIL=rung@example.com "
         "GIT_COMMITTER_NAME=rung GIT_COMMITTER_EMAIL=rung@example.com GIT_AUTHOR_DATE='2026-01-01T00:00:00Z' "
         "GIT_COMMITTER_DATE='2026-01-01T00:00:00Z' git";
}

class GitRepoTest : public TempFolderTest {
 protected:
  void SetUp() override {
    TempFolderTest::SetUp();
    repo_ = dir_ / "repo";
    std::filesystem::create_directories(repo_);
    ASSERT_EQ(git("init -q -b main").exit_code, 0);
  }

  CommandRun git(const std::string& args) const { return run_shell_in(repo_, git_command() + " " + args); }

  // Commits everything in the working tree; fails the test when git does.
  void commit(const std::string& message) const {
    const CommandRun add = git("add -A");
    ASSERT_EQ(add.exit_code, 0) << add.out;
    const CommandRun c = git("commit -q --allow-empty -m '" + message + "'");
    ASSERT_EQ(c.exit_code, 0) << c.out;
  }

  void put(const std::string& name, const std::string& text) const { write_file(repo_ / name, text); }
  std::string get(const std::string& name) const { return read_file(repo_ / name); }

  RungRun rung(const std::string& args) const { return run_rung_in(repo_, args); }

  // Compares `actual` with the golden file tests/vcs/golden/<name> (RUNG_UPDATE_GOLDEN=1 writes it).
  static void expect_golden(const std::string& name, const std::string& actual) {
    const std::filesystem::path path = source_dir() / "tests" / "vcs" / "golden" / name;
    if (update_golden()) {
      write_file(path, actual);
      return;
    }
    EXPECT_EQ(read_file(path), actual) << "golden file " << path << " (RUNG_UPDATE_GOLDEN=1 rewrites it)";
  }

  std::filesystem::path repo_;
};

}  // namespace rung::test
