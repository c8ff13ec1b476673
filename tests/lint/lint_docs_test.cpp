// docs/commands/lint.md lists every rule with its real defaults: the table is checked against the
// rule registry, so a rule added or changed without its row fails here.
#include <gtest/gtest.h>

#include <map>
#include <sstream>

#include "checker/lint/lint_rule.hpp"
#include "parser/diagnostic_codes.hpp"
#include "tests/support/test_paths.hpp"

namespace rung::lint {
namespace {

// The cells of a Markdown table row, trimmed: "| a | b |" -> {"a", "b"}.
std::vector<std::string> cells(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream row(line.substr(1));
  for (std::string cell; std::getline(row, cell, '|');) {
    const size_t begin = cell.find_first_not_of(' ');
    const size_t end = cell.find_last_not_of(' ');
    out.push_back(begin == std::string::npos ? "" : cell.substr(begin, end - begin + 1));
  }
  return out;
}

TEST(LintDocs, RuleTableListsEveryRuleWithItsDefaults) {
  const std::string page = test::read_file(test::source_dir() / "docs" / "commands" / "lint.md");
  ASSERT_FALSE(page.empty());
  std::map<std::string, std::vector<std::string>> rows;  // code -> cells
  std::stringstream lines(page);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("| [L", 0) != 0) continue;
    std::vector<std::string> row = cells(line);
    ASSERT_GE(row.size(), 5u) << line;
    const std::string code = row[0].substr(1, row[0].find(']') - 1);
    EXPECT_EQ(row[0], "[" + code + "](../diagnostics/" + code + ".md)") << line;
    EXPECT_TRUE(rows.emplace(code, row).second) << code << " has two rows";
  }
  for (const Rule& rule : all_rules()) {
    const std::string code(rule.code);
    auto found = rows.find(code);
    ASSERT_NE(found, rows.end()) << code << " is missing from the table in docs/commands/lint.md";
    const std::vector<std::string>& row = found->second;
    const DiagnosticCodeInfo* info = find_diagnostic_code(rule.code);
    ASSERT_NE(info, nullptr);
    EXPECT_EQ(row[1], rule.name) << code;
    EXPECT_EQ(row[2], severity_name(info->default_severity)) << code;
    EXPECT_EQ(row[3], rule.enabled_by_default ? "on" : "off") << code;
    EXPECT_EQ(row[4], rule.has_fix ? "yes" : "no") << code;
    rows.erase(found);
  }
  for (const auto& [code, row] : rows) ADD_FAILURE() << code << " is in the table but is not a rule";
}

}  // namespace
}  // namespace rung::lint
