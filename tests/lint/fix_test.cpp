// Applying fixes to one file (`rung lint --fix`): whole fixes only, the file's encoding and line
// ends kept, and never on a file that has (or would get) syntax errors.
#include <gtest/gtest.h>

#include "checker/lint/apply_fixes.hpp"

namespace rung::lint {
namespace {

// A finding of `code` whose fix replaces each [begin, end) of `edits` (FILE offsets of `text`).
Finding finding_with_fix(std::string_view text, std::vector<std::pair<std::string, std::string>> edits) {
  Finding finding;
  finding.diagnostic.code = "L035";
  Fix fix;
  fix.description = "remove it";
  for (auto& [old_text, replacement] : edits) {
    const auto at = static_cast<uint32_t>(text.find(old_text));
    fix.edits.push_back({{at, at + static_cast<uint32_t>(old_text.size())}, replacement});
  }
  finding.fix = fix;
  return finding;
}

TEST(LintFix, KeepsCp1252AndCrlf) {
  const std::string bytes =
      "PROGRAM P\r\nVAR x : INT; END_VAR (* Z\xE4hler *)\r\nx := x;\r\nx := 1;\r\nEND_PROGRAM\r\n";
  const Document document = Document::from_bytes("P.st", bytes);
  ASSERT_EQ(document.encoding(), source::Encoding::Cp1252);
  const FixedFile fixed = fix_file(document, {finding_with_fix(document.file_text(), {{"x := x;\r\n", ""}})});
  ASSERT_EQ(fixed.outcome, FixedFile::Outcome::Changed) << fixed.problem;
  EXPECT_EQ(fixed.applied, 1u);
  EXPECT_EQ(fixed.bytes, "PROGRAM P\r\nVAR x : INT; END_VAR (* Z\xE4hler *)\r\nx := 1;\r\nEND_PROGRAM\r\n");
}

TEST(LintFix, KeepsAUtf8Bom) {
  const std::string bytes = "\xEF\xBB\xBFPROGRAM P\nVAR x : INT; END_VAR\nx := x;\nEND_PROGRAM\n";
  const Document document = Document::from_bytes("P.st", bytes);
  const FixedFile fixed = fix_file(document, {finding_with_fix(document.file_text(), {{"x := x;\n", ""}})});
  ASSERT_EQ(fixed.outcome, FixedFile::Outcome::Changed) << fixed.problem;
  EXPECT_EQ(fixed.bytes, "\xEF\xBB\xBFPROGRAM P\nVAR x : INT; END_VAR\nEND_PROGRAM\n");
}

TEST(LintFix, AFixThatTouchesAnAppliedOneWaitsWhole) {
  const std::string text = "PROGRAM P\nVAR x : INT; y : INT; END_VAR\nx := x;\ny := y;\nEND_PROGRAM\n";
  const Document document = Document::from_bytes("P.st", text);
  // The second fix edits two places; one of them overlaps the first fix, so neither is applied.
  const FixedFile fixed = fix_file(document, {finding_with_fix(text, {{"x := x;", "x := 1;"}}),
                                              finding_with_fix(text, {{"y := y;", ""}, {"x := x", "x := 2"}})});
  ASSERT_EQ(fixed.outcome, FixedFile::Outcome::Changed) << fixed.problem;
  EXPECT_EQ(fixed.applied, 1u);
  EXPECT_EQ(fixed.deferred, 1u);
  EXPECT_EQ(fixed.bytes, "PROGRAM P\nVAR x : INT; y : INT; END_VAR\nx := 1;\ny := y;\nEND_PROGRAM\n");
}

TEST(LintFix, NeverTouchesAFileWithSyntaxErrors) {
  const std::string text = "PROGRAM P\nVAR x : INT; END_VAR\nx := x;\nIF x THEN\nEND_PROGRAM\n";
  const Document document = Document::from_bytes("P.st", text);
  const FixedFile fixed = fix_file(document, {finding_with_fix(text, {{"x := x;\n", ""}})});
  EXPECT_EQ(fixed.outcome, FixedFile::Outcome::NotFixed);
  EXPECT_NE(fixed.problem.find("not fixed"), std::string::npos) << fixed.problem;
  EXPECT_TRUE(fixed.bytes.empty());
}

TEST(LintFix, RefusesFixesThatWouldBreakTheSyntax) {
  const std::string text = "PROGRAM P\nVAR x : INT; END_VAR\nIF x > 0 THEN\nx := x;\nEND_IF\nEND_PROGRAM\n";
  const Document document = Document::from_bytes("P.st", text);
  const FixedFile fixed = fix_file(document, {finding_with_fix(text, {{"END_IF\n", ""}})});
  EXPECT_EQ(fixed.outcome, FixedFile::Outcome::NotFixed);
  EXPECT_NE(fixed.problem.find("internal error"), std::string::npos) << fixed.problem;
}

TEST(LintFix, NoFixesNoChange) {
  const std::string text = "PROGRAM P\nEND_PROGRAM\n";
  const Document document = Document::from_bytes("P.st", text);
  Finding plain;
  plain.diagnostic.code = "L060";
  EXPECT_EQ(fix_file(document, {plain}).outcome, FixedFile::Outcome::Unchanged);
}

}  // namespace
}  // namespace rung::lint
