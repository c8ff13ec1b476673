// Suppression comments and the rung-lint attribute: which findings they hide and which they must
// leave. The findings come from two simple rules (L031 empty-statement, L035 self-assignment).
#include "checker/lint/suppression.hpp"

#include <gtest/gtest.h>

#include "checker/check.hpp"
#include "checker/lint/lint.hpp"

namespace rung::lint {
namespace {

// Only L031 and L035 run, so other rules cannot change what these tests see.
project::ProjectConfig two_rules() {
  project::ProjectConfig config;
  for (const Rule& rule : all_rules()) config.lint.rules[std::string(rule.code)] = "off";
  config.lint.rules["L031"] = "on";
  config.lint.rules["L035"] = "on";
  return config;
}

// "line:code" of every finding left after suppressions.
std::vector<std::string> findings_of(const std::string& text, const std::string& name = "test.st") {
  const project::ProjectConfig config = two_rules();
  auto workspace = check::Workspace::from_texts({{name, text}}, config);
  const FileFindings found = lint_source(*workspace, 0, config.lint);
  const Document& document = *workspace->model().source(0).document;
  std::vector<std::string> out;
  for (const Finding& finding : found.findings) {
    out.push_back(std::to_string(document.position_of_file_offset(finding.diagnostic.range.begin).line) + ":" +
                  finding.diagnostic.code);
  }
  return out;
}

using Lines = std::vector<std::string>;

TEST(LintSuppression, WithoutCommentsEverythingIsReported) {
  EXPECT_EQ(findings_of("PROGRAM P\nVAR x : INT; END_VAR\nx := x;\n;\nEND_PROGRAM\n"), (Lines{"3:L035", "4:L031"}));
}

TEST(LintSuppression, TrailingCommentCoversItsOwnLineOnly) {
  EXPECT_EQ(findings_of(R"(PROGRAM P
VAR x : INT; END_VAR
x := x; // rung-lint: ignore L035
x := x;
x := x; (* rung-lint: ignore self-assignment -- kept for the debugger *)
;       // rung-lint: ignore L035
END_PROGRAM
)"),
            (Lines{"4:L035", "6:L031"}));
}

TEST(LintSuppression, CommentAloneCoversTheNextCodeLine) {
  EXPECT_EQ(findings_of(R"(PROGRAM P
VAR x : INT; END_VAR
// rung-lint: ignore L035

(* a second comment between *)
x := x;
x := x;
   (* rung-lint: ignore L031, L035 *)
x := x; ;
END_PROGRAM
)"),
            (Lines{"7:L035"}));
}

TEST(LintSuppression, NoCodesMeansEveryRuleAndUnknownCodesMeanNone) {
  EXPECT_EQ(findings_of(R"(PROGRAM P
VAR x : INT; END_VAR
x := x; ; // rung-lint: ignore
x := x; ; // rung-lint: ignore L99
x := x; ; // rung-lint: ignore L031
x := x; ; // rung-lint: ignore
END_PROGRAM
)"),
            (Lines{"4:L035", "4:L031", "5:L035"}));
}

TEST(LintSuppression, IgnorePouCoversThePouItIsIn) {
  EXPECT_EQ(findings_of(R"(FUNCTION_BLOCK FB_A (* rung-lint: ignore-pou L035 *)
VAR x : INT; END_VAR
x := x;
;
METHOD M
x := x;
END_METHOD
END_FUNCTION_BLOCK
PROGRAM P
VAR x : INT; END_VAR
x := x;
END_PROGRAM
)"),
            (Lines{"4:L031", "11:L035"}));
}

TEST(LintSuppression, AttributeCoversThePouThatFollows) {
  EXPECT_EQ(findings_of(R"(PROGRAM P1
VAR x : INT; END_VAR
x := x;
END_PROGRAM
{attribute 'rung-lint' := 'ignore L035'}
PROGRAM P2
VAR x : INT; END_VAR
x := x;
;
END_PROGRAM
FUNCTION_BLOCK FB
VAR x : INT; END_VAR
x := x;
{attribute 'rung-lint' := 'ignore'}
METHOD M
x := x;
;
END_METHOD
END_FUNCTION_BLOCK
)"),
            (Lines{"3:L035", "9:L031", "13:L035"}));
}

TEST(LintSuppression, IgnorePouBeforeThePouAndIgnoreFileAnywhere) {
  EXPECT_EQ(findings_of(R"(// rung-lint: ignore-pou
PROGRAM P1
VAR x : INT; END_VAR
x := x;
END_PROGRAM
PROGRAM P2
VAR x : INT; END_VAR
x := x;
;
END_PROGRAM
)"),
            (Lines{"8:L035", "9:L031"}));
  EXPECT_EQ(findings_of(R"(PROGRAM P2
VAR x : INT; END_VAR
x := x;
;
END_PROGRAM
(* rung-lint: ignore-file L031 *)
)"),
            (Lines{"3:L035"}));
}

TEST(LintSuppression, TheMarkerInAStringOrAnUnknownDirectiveDoesNothing) {
  EXPECT_EQ(findings_of(R"(PROGRAM P
VAR x : INT; s : STRING; END_VAR
s := 'rung-lint: ignore-file'; x := x;
x := x; // rung-lint: silence L035
x := x; // rung-lint ignore L035
END_PROGRAM
)"),
            (Lines{"3:L035", "4:L035", "5:L035"}));
}

TEST(LintSuppression, WorksInTwinCatContainers) {
  const std::string pou = R"(<?xml version="1.0" encoding="utf-8"?>
<TcPlcObject Version="1.1.0.1">
  <POU Name="P" Id="{00000000-0000-0000-0000-000000000001}" SpecialFunc="None">
    <Declaration><![CDATA[PROGRAM P
VAR x : INT; END_VAR
]]></Declaration>
    <Implementation>
      <ST><![CDATA[x := x; // rung-lint: ignore L035
x := x;]]></ST>
    </Implementation>
  </POU>
</TcPlcObject>
)";
  // Line numbers are the container's own.
  EXPECT_EQ(findings_of(pou, "P.TcPOU"), (Lines{"9:L035"}));
}

TEST(LintSuppression, ReadsScopesInTreeCoordinates) {
  const std::string text = "PROGRAM P\nx := x; // rung-lint: ignore-file\nEND_PROGRAM\n";
  SyntaxTree tree = SyntaxTree::parse(text);
  const std::vector<Suppression> found = read_suppressions(tree.root());
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].scope.begin, 0u);
  EXPECT_EQ(found[0].scope.end, text.size());
  EXPECT_TRUE(found[0].codes.empty());
}

}  // namespace
}  // namespace rung::lint
