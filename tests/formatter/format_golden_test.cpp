// Golden tests of `rung fmt`'s engine: every folder tests/formatter/golden/<case>/ holds
// input.st, expected.st and optionally format.toml (a rung.toml text with a [format] table) and
// status.txt ("syntax_errors" when the input must be refused). The formatter must turn input.st
// into expected.st and leave expected.st as it is (idempotence). RUNG_UPDATE_GOLDEN=1 rewrites
// expected.st from what the formatter produces (then review the diff).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "checker/project/project_config.hpp"
#include "formatter/format.hpp"
#include "tests/support/test_paths.hpp"

namespace rung::format {
namespace {

namespace fs = std::filesystem;

fs::path golden_dir() {
  return test::source_dir() / "tests" / "formatter" / "golden";
}

std::vector<std::string> golden_cases() {
  std::vector<std::string> names;
  if (!fs::is_directory(golden_dir())) return names;
  for (const auto& entry : fs::directory_iterator(golden_dir()))
    if (entry.is_directory()) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

project::FormatSettings settings_of(const fs::path& folder) {
  if (!fs::is_regular_file(folder / "format.toml")) return {};
  project::LoadedConfig loaded = project::parse_project_config(test::read_file(folder / "format.toml"), folder);
  for (const Diagnostic& d : loaded.diagnostics)
    ADD_FAILURE() << folder / "format.toml"
                  << ": " << d.message;
  return loaded.config.format;
}

Status expected_status(const fs::path& folder) {
  if (!fs::is_regular_file(folder / "status.txt")) return Status::Formatted;
  std::string word = test::read_file(folder / "status.txt");
  word.erase(word.find_last_not_of(" \r\n") + 1);
  EXPECT_EQ(word, "syntax_errors") << folder / "status.txt";
  return Status::SyntaxErrors;
}

std::string status_name(Status status) {
  switch (status) {
    case Status::Formatted: return "Formatted";
    case Status::SyntaxErrors: return "SyntaxErrors";
    case Status::Unsafe: return "Unsafe";
  }
  return "?";
}

class FormatGolden : public ::testing::TestWithParam<std::string> {};

TEST_P(FormatGolden, FormatsInputToExpectedAndExpectedToItself) {
  const fs::path folder = golden_dir() / GetParam();
  ASSERT_TRUE(fs::is_regular_file(folder / "input.st")) << "missing " << folder / "input.st";
  const project::FormatSettings settings = settings_of(folder);
  const std::string input = test::read_file(folder / "input.st");
  const Status want = expected_status(folder);

  const FormatResult result = format_text(input, settings);
  ASSERT_EQ(status_name(result.status), status_name(want)) << result.message;
  if (want == Status::SyntaxErrors) {
    EXPECT_EQ(result.text, input) << "a file with syntax errors must come back unchanged";
    EXPECT_FALSE(result.changed);
    EXPECT_EQ(result.message.rfind("line ", 0), 0u) << result.message;
  }
  if (test::update_golden()) {
    test::write_file(folder / "expected.st", result.text);
    return;
  }
  ASSERT_TRUE(fs::is_regular_file(folder / "expected.st")) << "missing " << folder / "expected.st";
  const std::string expected = test::read_file(folder / "expected.st");
  EXPECT_EQ(result.text, expected);
  EXPECT_EQ(result.changed, expected != input);

  const FormatResult again = format_text(expected, settings);
  EXPECT_EQ(status_name(again.status), status_name(want)) << again.message;
  EXPECT_EQ(again.text, expected) << "formatting expected.st changes it: the formatter is not idempotent";
}

INSTANTIATE_TEST_SUITE_P(Golden, FormatGolden, ::testing::ValuesIn(golden_cases()),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

TEST(FormatGoldenCases, ThereAreCases) {
  EXPECT_GE(golden_cases().size(), 40u);
}

}  // namespace
}  // namespace rung::format
