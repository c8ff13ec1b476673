// Range formatting: only the changed lines that touch the range are taken.
#include "formatter/range_format.hpp"

#include <gtest/gtest.h>

#include "formatter/format.hpp"

namespace rung::format {
namespace {

const std::string kBefore = "a\nb\nc\nd\ne\nf\n";
const std::string kAfter = "A\nb\nC\nd\nnew\ne\nF\n";  // changes at lines 0, 2, an insertion before 4, 5

TEST(TakeChangedLines, OnlyChangesTouchingTheRange) {
  EXPECT_EQ(take_changed_lines(kBefore, kAfter, 2, 2).text, "a\nb\nC\nd\ne\nf\n");
  EXPECT_EQ(take_changed_lines(kBefore, kAfter, 2, 2).first_line, 2u);
  EXPECT_EQ(take_changed_lines(kBefore, kAfter, 0, 2).text, "A\nb\nC\nd\ne\nf\n");
  EXPECT_EQ(take_changed_lines(kBefore, kAfter, 0, 5).text, kAfter);
}

TEST(TakeChangedLines, AnInsertionBelongsToTheLineAfterIt) {
  EXPECT_EQ(take_changed_lines(kBefore, kAfter, 4, 4).text, "a\nb\nc\nd\nnew\ne\nf\n");
  EXPECT_EQ(take_changed_lines(kBefore, kAfter, 3, 3).text, kBefore);  // "d" itself is unchanged
}

TEST(TakeChangedLines, NothingInRangeLeavesTheText) {
  const TakenLines taken = take_changed_lines(kBefore, kAfter, 1, 1);
  EXPECT_EQ(taken.text, kBefore);
  EXPECT_FALSE(taken.first_line.has_value());
}

TEST(TakeChangedLines, AChangeSpanningTheRangeEdgeIsTakenWhole) {
  // Two lines joined into one: a single change; a range on either line takes it.
  EXPECT_EQ(take_changed_lines("x\nIF a\nTHEN\ny\n", "x\nIF a THEN\ny\n", 2, 2).text, "x\nIF a THEN\ny\n");
}

TEST(TakeChangedLines, LinesRewrittenOneForOneAreTakenOneByOne) {
  EXPECT_EQ(take_changed_lines("a\nb\nc\n", "A\nB\nC\n", 1, 1).text, "a\nB\nc\n");
  EXPECT_EQ(take_changed_lines("a\nb\nc\n", "A\nB\nC\n", 1, 1).first_line, 1u);
}

TEST(TakeChangedLines, KeepsALastLineWithoutLineEnd) {
  EXPECT_EQ(take_changed_lines("a\nb", "A\nB", 0, 0).text, "A\nb");
  EXPECT_EQ(take_changed_lines("a\nb", "A\nB", 1, 1).text, "a\nB");
}

// With the real engine (these wait for the formatter engine of issue 4: until then format_text
// returns its input unchanged and the expectations on changed text fail).
project::FormatSettings upper_keywords() {
  project::FormatSettings s;
  s.keyword_case = project::KeywordCase::Upper;
  return s;
}

const std::string kProgram =
    "PROGRAM Main\nVAR\n\tx : INT;\nEND_VAR\nif x > 1 then\n\tx := 0;\nend_if\nif x < 0 then\n\tx := 1;\nend_if\n"
    "END_PROGRAM\n";

// Bytes before `begin` and from `end` on (of the input) are unchanged in `out`; what replaced the
// lines between is a piece of the whole text's formatting. Returns that middle part.
std::string middle_of(const std::string& out, size_t begin, size_t end) {
  EXPECT_EQ(out.substr(0, begin), kProgram.substr(0, begin));
  const std::string tail = kProgram.substr(end);
  EXPECT_GE(out.size(), begin + tail.size());
  EXPECT_EQ(out.substr(out.size() - tail.size()), tail);
  const std::string middle = out.substr(begin, out.size() - tail.size() - begin);
  EXPECT_NE(format_text(kProgram, upper_keywords()).text.find(middle), std::string::npos) << middle;
  return middle;
}

TEST(FormatRangeEngine, KeywordCaseChangesOnlyTheLinesInRange) {
  const size_t begin = kProgram.find("if x > 1");
  const size_t end = kProgram.find("if x < 0");  // whole lines 5 to 7
  const FormatResult out = format_range(kProgram, {uint32_t(begin), uint32_t(end)}, upper_keywords());
  ASSERT_EQ(out.status, Status::Formatted) << out.message;
  EXPECT_TRUE(out.changed);
  const std::string middle = middle_of(out.text, begin, end);
  EXPECT_NE(middle.find("IF x > 1 THEN"), std::string::npos) << middle;
  EXPECT_NE(middle.find("END_IF"), std::string::npos) << middle;
}

TEST(FormatRangeEngine, ACursorFormatsItsLine) {
  const size_t line = kProgram.find("end_if\nif x < 0");
  const FormatResult out =
      format_range(kProgram, {uint32_t(line + 2), uint32_t(line + 2)}, upper_keywords());  // inside "end_if"
  ASSERT_EQ(out.status, Status::Formatted) << out.message;
  EXPECT_TRUE(out.changed);
  EXPECT_NE(middle_of(out.text, line, line + 7).find("END_IF"), std::string::npos);
}

TEST(FormatRangeEngine, SyntaxErrorsAreReported) {
  const std::string broken = "PROGRAM Main\nVAR\n\tx : INT;\nEND_VAR\nx := (1 + ;\nEND_PROGRAM\n";
  const FormatResult out = format_range(broken, {0, 5}, upper_keywords());
  EXPECT_EQ(out.status, Status::SyntaxErrors);
  EXPECT_EQ(out.text, broken);
  EXPECT_FALSE(out.changed);
  EXPECT_EQ(out.message.rfind("line 5", 0), 0u) << out.message;
}

TEST(FormatRange, AFormattedTextStaysAsItIs) {
  // Holds with the placeholder engine and the real one: a text already in the layout of the
  // settings comes back unchanged whatever the range.
  const std::string formatted = "PROGRAM Main\nEND_PROGRAM\n";
  const FormatResult out = format_range(formatted, {0, static_cast<uint32_t>(formatted.size())}, upper_keywords());
  EXPECT_EQ(out.status, Status::Formatted);
  EXPECT_FALSE(out.changed);
  EXPECT_EQ(out.text, formatted);
}

}  // namespace
}  // namespace rung::format
