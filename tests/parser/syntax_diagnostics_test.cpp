// Golden tests of syntax diagnostics: every tests/parser/syntax_errors/NAME.st has NAME.expected
// with the diagnostics rung must report (`line:col severity[CODE]: message`, then `help:`).
// RUNG_UPDATE_GOLDEN=1 rewrites the expected files; review the diff before committing.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <filesystem>

#include "parser/document.hpp"
#include "tests/support/test_paths.hpp"

namespace rung {
namespace {

std::string render(const Document& doc) {
  std::string out;
  for (const auto& d : doc.diagnostics()) {
    FilePosition p = doc.position_of_file_offset(d.range.begin);
    out += fmt::format("{}:{} {}[{}]: {}\n", p.line, p.column, severity_name(d.severity), d.code, d.message);
    for (const auto& l : d.labels) {
      FilePosition lp = doc.position_of_file_offset(l.range.begin);
      out += fmt::format("  note {}:{}: {}\n", lp.line, lp.column, l.message);
    }
    if (!d.help.empty()) out += fmt::format("  help: {}\n", d.help);
  }
  return out;
}

std::vector<std::filesystem::path> cases() {
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::directory_iterator(test::source_dir() / "tests/parser/syntax_errors")) {
    if (e.path().extension() == ".st") files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

TEST(SyntaxDiagnostics, GoldenFiles) {
  auto files = cases();
  ASSERT_GE(files.size(), 10u);
  for (const auto& file : files) {
    SCOPED_TRACE(file.filename().string());
    std::string error;
    auto doc = Document::load(file, &error);
    ASSERT_TRUE(doc) << error;
    std::string actual = render(*doc);
    auto expected_path = std::filesystem::path(file).replace_extension(".expected");
    if (test::update_golden()) {
      test::write_file(expected_path, actual);
      continue;
    }
    ASSERT_TRUE(std::filesystem::exists(expected_path)) << "no golden file; run with RUNG_UPDATE_GOLDEN=1";
    EXPECT_EQ(actual, test::read_file(expected_path));
    // Every broken example must produce at least one error, and never a bare "ERROR".
    EXPECT_NE(actual.find("error["), std::string::npos);
    EXPECT_EQ(actual.find("ERROR"), std::string::npos);
  }
}

}  // namespace
}  // namespace rung
