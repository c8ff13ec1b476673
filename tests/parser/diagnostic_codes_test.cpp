// The registry and the docs agree: every code has a page, every page a code.
#include "parser/diagnostic_codes.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <set>

#include "tests/support/test_paths.hpp"

namespace rung {
namespace {

TEST(DiagnosticCodes, EveryCodeHasADocsPageAndViceVersa) {
  auto dir = test::source_dir() / "docs/diagnostics";
  std::set<std::string> pages;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    if (e.path().extension() == ".md" && e.path().stem() != "README") pages.insert(e.path().stem().string());
  }
  std::set<std::string> registered;
  for (const auto& info : all_diagnostic_codes()) {
    registered.insert(std::string(info.code));
    EXPECT_TRUE(pages.count(std::string(info.code))) << "no docs/diagnostics/" << info.code << ".md";
    std::string page = test::read_file(dir / (std::string(info.code) + ".md"));
    EXPECT_NE(page.find("# " + std::string(info.code)), std::string::npos) << info.code;
    EXPECT_NE(page.find(std::string(severity_name(info.default_severity))), std::string::npos) << info.code;
    EXPECT_FALSE(info.summary.empty());
  }
  for (const auto& p : pages) EXPECT_TRUE(registered.count(p)) << "docs page without code: " << p;
  std::string index = test::read_file(dir / "README.md");
  for (const auto& code : registered) EXPECT_NE(index.find("[" + code + "]"), std::string::npos) << code;
}

TEST(DiagnosticCodes, LookupIsCaseInsensitive) {
  ASSERT_NE(find_diagnostic_code("s003"), nullptr);
  EXPECT_EQ(find_diagnostic_code("S003")->title, "missing-end-keyword");
  EXPECT_EQ(find_diagnostic_code("X999"), nullptr);
}

}  // namespace
}  // namespace rung
