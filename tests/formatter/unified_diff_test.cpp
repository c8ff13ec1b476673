// Line diffs and unified diff text, checked against exact expected output and against the
// system's `diff -u`.
#include "formatter/unified_diff.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <random>

#include "tests/support/test_paths.hpp"

namespace rung::format {
namespace {

std::string numbered(int from, int to) {
  std::string out;
  for (int i = from; i <= to; ++i) out += "line " + std::to_string(i) + "\n";
  return out;
}

TEST(SplitLines, KeepsLineEndsAndALastLineWithoutOne) {
  EXPECT_EQ(split_lines(""), std::vector<std::string_view>{});
  EXPECT_EQ(split_lines("a\r\nb\n\nc"), (std::vector<std::string_view>{"a\r\n", "b\n", "\n", "c"}));
  EXPECT_EQ(split_lines("a\n"), std::vector<std::string_view>{"a\n"});
}

TEST(DiffLines, EqualTextsHaveNoChanges) {
  auto lines = split_lines("a\nb\nc\n");
  EXPECT_TRUE(diff_lines(lines, lines).empty());
  EXPECT_TRUE(diff_lines({}, {}).empty());
}

TEST(DiffLines, ReplacementInsertionAndDeletion) {
  auto before = split_lines("a\nb\nc\nd\ne\n");
  auto after = split_lines("a\nB\nc\nd\nx\ny\ne\n");
  EXPECT_EQ(diff_lines(before, after), (std::vector<LineChange>{{1, 1, 1, 1}, {4, 0, 4, 2}}));
  EXPECT_EQ(diff_lines(after, before), (std::vector<LineChange>{{1, 1, 1, 1}, {4, 2, 4, 0}}));
  EXPECT_EQ(diff_lines({}, split_lines("x\n")), (std::vector<LineChange>{{0, 0, 0, 1}}));
  EXPECT_EQ(diff_lines(split_lines("x\n"), {}), (std::vector<LineChange>{{0, 1, 0, 0}}));
}

TEST(DiffLines, FindsTheShortestScript) {
  // The classic example of Myers' paper: ABCABBA -> CBABAC needs 5 edits (LCS of 4).
  auto chars = [](std::string_view s) {
    std::vector<std::string_view> out;
    for (size_t i = 0; i < s.size(); ++i) out.push_back(s.substr(i, 1));
    return out;
  };
  const auto a = chars("ABCABBA");
  const auto b = chars("CBABAC");
  size_t edits = 0;
  for (const LineChange& c : diff_lines(a, b)) edits += c.before_count + c.after_count;
  EXPECT_EQ(edits, 5u);
}

TEST(DiffLines, LineEndsCount) {
  EXPECT_EQ(diff_lines(split_lines("a\r\nb\r\n"), split_lines("a\nb\r\n")), (std::vector<LineChange>{{0, 1, 0, 1}}));
}

TEST(DiffLines, ALargeRewriteIsFast) {
  // Every line changed: D = N + M. Linear space keeps this at a few MB.
  std::string before, after;
  for (int i = 0; i < 20000; ++i) {
    before += "x" + std::to_string(i) + "\n";
    after += "y" + std::to_string(i) + "\n";
  }
  const auto changes = diff_lines(split_lines(before), split_lines(after));
  ASSERT_EQ(changes.size(), 1u);
  EXPECT_EQ(changes[0], (LineChange{0, 20000, 0, 20000}));
}

TEST(UnifiedDiff, EqualTextsGiveNothing) {
  EXPECT_EQ(unified_diff("a\n", "a\n", "a/x", "b/x"), "");
}

TEST(UnifiedDiff, OneHunkWithThreeLinesOfContext) {
  std::string before = numbered(1, 10);
  std::string after = before;
  after.replace(after.find("line 5\n"), 7, "LINE 5\n");
  EXPECT_EQ(unified_diff(before, after, "a/main.st", "b/main.st"),
            "--- a/main.st\n"
            "+++ b/main.st\n"
            "@@ -2,7 +2,7 @@\n"
            " line 2\n"
            " line 3\n"
            " line 4\n"
            "-line 5\n"
            "+LINE 5\n"
            " line 6\n"
            " line 7\n"
            " line 8\n");
}

TEST(UnifiedDiff, ChangesFarApartMakeTwoHunksAndNearOnesOne) {
  const std::string before = numbered(1, 20);
  std::string far = before;
  far.replace(far.find("line 2\n"), 7, "");
  far.replace(far.find("line 18\n"), 8, "line 18\nnew\n");
  EXPECT_EQ(unified_diff(before, far, "a/f", "b/f"),
            "--- a/f\n+++ b/f\n"
            "@@ -1,5 +1,4 @@\n line 1\n-line 2\n line 3\n line 4\n line 5\n"
            "@@ -16,5 +15,6 @@\n line 16\n line 17\n line 18\n+new\n line 19\n line 20\n");

  // Six unchanged lines between two changes: their contexts meet, one hunk.
  std::string near = before;
  near.replace(near.find("line 3\n"), 7, "three\n");
  near.replace(near.find("line 10\n"), 8, "ten\n");
  EXPECT_EQ(unified_diff(before, near, "a/f", "b/f"),
            "--- a/f\n+++ b/f\n"
            "@@ -1,13 +1,13 @@\n line 1\n line 2\n-line 3\n+three\n line 4\n line 5\n line 6\n line 7\n"
            " line 8\n line 9\n-line 10\n+ten\n line 11\n line 12\n line 13\n");
}

TEST(UnifiedDiff, NoNewlineAtEndOfFile) {
  EXPECT_EQ(unified_diff("a\nb", "a\nb\n", "a/f", "b/f"),
            "--- a/f\n+++ b/f\n@@ -1,2 +1,2 @@\n a\n-b\n\\ No newline at end of file\n+b\n");
  EXPECT_EQ(unified_diff("a\nb", "A\nb", "a/f", "b/f"),
            "--- a/f\n+++ b/f\n@@ -1,2 +1,2 @@\n-a\n+A\n b\n\\ No newline at end of file\n");
}

TEST(UnifiedDiff, EmptyRangesNameTheLineBefore) {
  EXPECT_EQ(unified_diff("", "x\n", "a/f", "b/f"), "--- a/f\n+++ b/f\n@@ -0,0 +1 @@\n+x\n");
  EXPECT_EQ(unified_diff("x\n", "", "a/f", "b/f"), "--- a/f\n+++ b/f\n@@ -1 +0,0 @@\n-x\n");
  EXPECT_EQ(unified_diff("a\nb\n", "a\nnew\nb\n", "a/f", "b/f"), "--- a/f\n+++ b/f\n@@ -1,2 +1,3 @@\n a\n+new\n b\n");
}

TEST(UnifiedDiff, CrLfLinesArePrintedAsTheyAre) {
  EXPECT_EQ(unified_diff("a\r\nb\r\n", "a\r\nB\r\n", "a/f", "b/f"),
            "--- a/f\n+++ b/f\n@@ -1,2 +1,2 @@\n a\r\n-b\r\n+B\r\n");
}

// The system's diff as the peer: same hunks, same numbers, same text.
class SystemDiff : public ::testing::Test {
 protected:
  void SetUp() override {
    if (std::system("diff --version >/dev/null 2>&1") != 0) GTEST_SKIP() << "no diff on this system";
    dir_ = std::filesystem::temp_directory_path() / ("rung_unified_diff_" + std::to_string(getpid()));
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override {
    if (!dir_.empty()) std::filesystem::remove_all(dir_);
  }

  std::string system_diff(const std::string& before, const std::string& after) {
    test::write_file(dir_ / "before", before);
    test::write_file(dir_ / "after", after);
    const std::string command = "diff -u --label a/f --label b/f '" + (dir_ / "before").string() + "' '" +
                                (dir_ / "after").string() + "' > '" + (dir_ / "out").string() + "'";
    const int status = std::system(command.c_str());
    EXPECT_NE(status, -1);
    return test::read_file(dir_ / "out");
  }

  std::filesystem::path dir_;
};

TEST_F(SystemDiff, RandomEditsGiveTheSameOutput) {
  // Unique lines, edited by deleting, inserting and replacing (no moves): the common lines are
  // then the same for every shortest script, so both programs must print the same diff.
  std::mt19937 random(4);
  int fresh = 0;
  for (int round = 0; round < 40; ++round) {
    std::vector<std::string> before;
    const int size = 1 + static_cast<int>(random() % 60);
    for (int i = 0; i < size; ++i) before.push_back("old " + std::to_string(i) + "\n");
    std::vector<std::string> after;
    for (const std::string& line : before) {
      switch (random() % 8) {
        case 0: break;                                                            // deleted
        case 1: after.push_back("new " + std::to_string(fresh++) + "\n"); break;  // replaced
        case 2:
          after.push_back("new " + std::to_string(fresh++) + "\n");  // inserted before
          after.push_back(line);
          break;
        default: after.push_back(line);
      }
    }
    if (random() % 3 == 0) after.push_back("new " + std::to_string(fresh++) + "\n");
    std::string a, b;
    for (const auto& l : before) a += l;
    for (const auto& l : after) b += l;
    if (random() % 4 == 0 && !a.empty()) a.pop_back();  // no newline at the end
    if (random() % 4 == 0 && !b.empty()) b.pop_back();
    EXPECT_EQ(unified_diff(a, b, "a/f", "b/f"), system_diff(a, b)) << "round " << round;
  }
}

TEST_F(SystemDiff, FormatterShapedChange) {
  const std::string before =
      "PROGRAM Main\nVAR\n  x:INT;\n  longer_name:BOOL;\nEND_VAR\nif x>1 then\n  x:=0;\nend_if\nEND_PROGRAM";
  const std::string after =
      "PROGRAM Main\nVAR\n\tx           : INT;\n\tlonger_name : BOOL;\nEND_VAR\nIF x > 1 THEN\n\tx := 0;\nEND_IF\n"
      "END_PROGRAM\n";
  EXPECT_EQ(unified_diff(before, after, "a/f", "b/f"), system_diff(before, after));
}

}  // namespace
}  // namespace rung::format
