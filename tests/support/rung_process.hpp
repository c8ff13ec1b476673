// Running the real rung binary from a test, in a temporary folder of its own: what a user or a
// CI job does. Header-only (tests/support has no library).
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "tests/support/test_paths.hpp"

namespace rung::test {

struct RungRun {
  int exit_code = -1;
  std::string out;
  std::string err;
};

// Runs `rung ARGS` with `folder` as the current folder and `input` on standard input.
inline RungRun run_rung_in(const std::filesystem::path& folder, const std::string& args,
                           const std::string& input = "") {
  const std::filesystem::path in = folder / ".rung-stdin", out = folder / ".rung-stdout", err = folder / ".rung-stderr";
  write_file(in, input);
  const std::string command = "cd '" + folder.string() + "' && '" + rung_binary().string() + "' " + args + " <'" +
                              in.string() + "' >'" + out.string() + "' 2>'" + err.string() + "'";
  const int status = std::system(command.c_str());
  RungRun run{WIFEXITED(status) ? WEXITSTATUS(status) : -1, read_file(out), read_file(err)};
  std::filesystem::remove(in);
  std::filesystem::remove(out);
  std::filesystem::remove(err);
  return run;
}

// A test with an empty temporary folder of its own, removed afterwards.
class TempFolderTest : public ::testing::Test {
 protected:
  void SetUp() override {
    static int counter = 0;
    dir_ = std::filesystem::temp_directory_path() /
           ("rung_test_" + std::to_string(getpid()) + "_" + std::to_string(counter++));
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  void write(const std::string& name, const std::string& bytes) const { write_file(dir_ / name, bytes); }
  std::string read(const std::string& name) const { return read_file(dir_ / name); }

  std::filesystem::path dir_;
};

}  // namespace rung::test
