// E209: recursion through calls and instances that contain themselves (all four manuals forbid
// both), and the CODESYS/TwinCAT exception for methods.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "checker/check.hpp"

namespace rung::check {
namespace {

struct Found {
  std::string code;
  uint32_t line;
  std::string message;
};

std::vector<Found> check(const std::vector<std::pair<std::string, std::string>>& files,
                         project::Profile profile = project::Profile::Codesys) {
  project::ProjectConfig config;
  config.profile = profile;
  auto workspace = Workspace::from_texts(files, config);
  std::vector<Found> found;
  for (const auto& file : workspace->check_all(1)) {
    const Document& document = *workspace->model().source(file.source).document;
    for (const auto& d : file.diagnostics) {
      found.push_back({d.code, document.position_of_file_offset(d.range.begin).line, d.message});
    }
  }
  return found;
}

TEST(Recursion, FunctionCallingItself) {
  auto found = check({{"F.st",
                       "FUNCTION Fact : DINT\nVAR_INPUT n : DINT; END_VAR\n"
                       "IF n <= 1 THEN Fact := 1; ELSE Fact := n * Fact(n - 1); END_IF\nEND_FUNCTION\n"}});
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].code, "E209");
  EXPECT_EQ(found[0].line, 3u);
  EXPECT_EQ(found[0].message, "'Fact' calls itself: recursion is not allowed");
}

TEST(Recursion, IndirectAcrossFilesIsReportedAtEachCallOfTheCycle) {
  auto found = check({{"A.st", "FUNCTION A : INT\nA := B();\nEND_FUNCTION\n"},
                      {"B.st", "FUNCTION B : INT\nB := A();\nEND_FUNCTION\n"}});
  ASSERT_EQ(found.size(), 2u);
  EXPECT_EQ(found[0].message, "recursive call: A calls B calls A");
  EXPECT_EQ(found[1].message, "recursive call: B calls A calls B");
}

TEST(Recursion, FunctionBlockInstanceCallsAndProgramsAreFollowed) {
  auto found = check({{"P.st",
                       "FUNCTION_BLOCK FB_A\nVAR_INPUT x : INT; END_VAR\nPRG();\nEND_FUNCTION_BLOCK\n"
                       "PROGRAM PRG\nVAR a : FB_A; END_VAR\na(x := 1);\nEND_PROGRAM\n"}});
  ASSERT_EQ(found.size(), 2u);
  EXPECT_EQ(found[0].code, "E209");
  EXPECT_EQ(found[1].code, "E209");
}

TEST(Recursion, InstanceContainingItselfDirectlyOrThroughArrays) {
  auto found =
      check({{"FB.st",
              "FUNCTION_BLOCK FB_Self\nVAR inner : FB_Self; p : POINTER TO FB_Self; END_VAR\nEND_FUNCTION_BLOCK\n"
              "FUNCTION_BLOCK FB_X\nVAR y : ARRAY[1..2] OF FB_Y; END_VAR\nEND_FUNCTION_BLOCK\n"
              "FUNCTION_BLOCK FB_Y\nVAR x : FB_X; r : REFERENCE TO FB_Y; END_VAR\nEND_FUNCTION_BLOCK\n"}});
  ASSERT_EQ(found.size(), 3u);
  EXPECT_EQ(found[0].message, "'FB_Self' contains an instance of itself");
  EXPECT_EQ(found[1].message, "'FB_X' contains an instance of itself (FB_X contains FB_Y contains FB_X)");
  EXPECT_EQ(found[2].line, 8u);  // FB_Y contains FB_X
}

TEST(Recursion, NoCycleNoDiagnostic) {
  EXPECT_TRUE(check({{"P.st",
                      "FUNCTION Twice : INT\nVAR_INPUT v : INT; END_VAR\nTwice := v * 2;\nEND_FUNCTION\n"
                      "FUNCTION_BLOCK FB_T\nVAR t : TON; END_VAR\nt(IN := TRUE, PT := T#1s);\nEND_FUNCTION_BLOCK\n"
                      "PROGRAM PRG\nVAR f : FB_T; i : INT; END_VAR\nf(); i := Twice(Twice(3));\nEND_PROGRAM\n"}})
                  .empty());
}

TEST(Recursion, RecursiveMethodsAreCodesysAndTwincatBehaviour) {
  const std::string text =
      "FUNCTION_BLOCK FB_Tree\nVAR_INPUT depth : INT; END_VAR\n"
      "METHOD Walk : INT\nVAR_INPUT n : INT; END_VAR\nIF n > 0 THEN Walk := Walk(n - 1); END_IF\nEND_METHOD\n"
      "END_FUNCTION_BLOCK\n";
  EXPECT_TRUE(check({{"T.st", text}}, project::Profile::Codesys).empty());
  EXPECT_TRUE(check({{"T.st", text}}, project::Profile::Twincat).empty());
  auto strict = check({{"T.st", text}}, project::Profile::Iec);
  ASSERT_EQ(strict.size(), 1u);
  EXPECT_EQ(strict[0].code, "E209");
}

}  // namespace
}  // namespace rung::check
