// Cases of the naming lint rules (L001-L006, L060-L062) that the golden files do not show: the
// prefix patterns themselves, rung.toml keys that change or switch off a prefix, scope and type
// prefixes together, name resolution that a case-insensitive text search would get wrong, and
// which comments count as code.
#include <gtest/gtest.h>

#include "checker/check.hpp"
#include "checker/lint/lint.hpp"
#include "checker/lint/naming_patterns.hpp"

namespace rung::lint {
namespace {

struct Settings {
  std::map<std::string, std::string> naming = {};
  std::map<std::string, int64_t> thresholds = {};
};

// The messages of `code` in `text` (one file, CODESYS profile, the rule switched on), each with
// the text it points at: "'start' is BOOL: ... @start".
std::vector<std::string> findings_of(std::string_view code, const std::string& text, const Settings& settings = {}) {
  project::ProjectConfig config;
  config.lint.rules[std::string(code)] = "on";
  config.lint.naming = settings.naming;
  config.lint.thresholds = settings.thresholds;
  auto workspace = check::Workspace::from_texts({{"Main.st", text}}, config);
  std::vector<std::string> found;
  for (const Finding& finding : lint_source(*workspace, 0, config.lint).findings) {
    if (finding.diagnostic.code != code) continue;
    const TextRange range = finding.diagnostic.range;
    found.push_back(finding.diagnostic.message + " @" + text.substr(range.begin, range.end - range.begin));
  }
  return found;
}

// `text` with every fix of `code` applied.
std::string fixed_by(std::string_view code, const std::string& text) {
  project::ProjectConfig config;
  config.lint.rules[std::string(code)] = "on";
  auto workspace = check::Workspace::from_texts({{"Main.st", text}}, config);
  std::vector<TextEdit> edits;
  for (const Finding& finding : lint_source(*workspace, 0, config.lint).findings) {
    if (finding.diagnostic.code == code && finding.fix) {
      edits.insert(edits.end(), finding.fix->edits.begin(), finding.fix->edits.end());
    }
  }
  return apply_edits(text, edits);
}

using Strings = std::vector<std::string>;

TEST(NamingPatterns, APrefixStartsANewWord) {
  using naming::has_prefix;
  EXPECT_TRUE(has_prefix("bStart", "b"));
  EXPECT_TRUE(has_prefix("b_Start", "b"));
  EXPECT_TRUE(has_prefix("b2Hand", "b"));
  EXPECT_FALSE(has_prefix("bstart", "b"));
  EXPECT_FALSE(has_prefix("BStart", "b"));     // case-sensitive
  EXPECT_FALSE(has_prefix("b", "b"));          // nothing after the prefix
  EXPECT_TRUE(has_prefix("FB_motor", "FB_"));  // after '_' anything may follow
  EXPECT_FALSE(has_prefix("FBMotor", "FB_"));
  EXPECT_FALSE(has_prefix("FB_", "FB_"));
  EXPECT_TRUE(has_prefix("anything", ""));  // an empty pattern checks nothing
}

TEST(NamingPatterns, AlternativesAndChains) {
  using naming::alternatives;
  EXPECT_EQ(alternatives(" F_ | FC_ ||"), (std::vector<std::string_view>{"F_", "FC_"}));
  EXPECT_TRUE(naming::has_prefix("FC_Scale", "F_|FC_"));
  const std::string chain[] = {"p", "a", "by"};
  EXPECT_TRUE(naming::has_prefix_chain("pData", chain));
  EXPECT_TRUE(naming::has_prefix_chain("paData", chain));
  EXPECT_TRUE(naming::has_prefix_chain("pabyData", chain));
  EXPECT_FALSE(naming::has_prefix_chain("abyData", chain));  // the first level is required
  EXPECT_FALSE(naming::has_prefix_chain("pabData", chain));
  const std::string open_chain[] = {"a", "", "i"};  // an empty level ends the chain
  EXPECT_FALSE(naming::has_prefix_chain("aiValues", open_chain));
  EXPECT_EQ(naming::matched_prefix_length("g_bReady", "g_|gc_"), 2u);
  EXPECT_EQ(naming::matched_prefix_length("gbReady", "g_"), 0u);
  EXPECT_EQ(naming::suggested_name("start", "b|x"), "bStart");
  EXPECT_EQ(naming::suggested_name("Motor", "FB_"), "FB_Motor");
  EXPECT_EQ(naming::describe_pattern("F_|FC_"), "one of 'F_', 'FC_'");
}

constexpr const char* kCounter = R"(FUNCTION_BLOCK FB_Counter
VAR_INPUT
    start : BOOL;
    nLimit : INT;
    iStep : INT;
    count : INT;
    todShift : TIME_OF_DAY;
END_VAR
END_FUNCTION_BLOCK
)";

TEST(NamingRules, VariablePrefixFollowsTheSettings) {
  // Alternatives, a type switched off, and a short type name as key.
  const Settings settings{.naming = {{"INT", "n|i"}, {"BOOL", ""}, {"TOD", "tm"}}};
  EXPECT_EQ(findings_of("L001", kCounter, settings),
            (Strings{"'count' is INT: its name should start with one of 'n', 'i' (e.g. nCount) @count",
                     "'todShift' is TIME_OF_DAY: its name should start with 'tm' (e.g. tmTodShift) @todShift"}));
}

TEST(NamingRules, ScopePrefixComesBeforeTheTypePrefix) {
  const std::string text = R"(FUNCTION_BLOCK FB_Valve
VAR_INPUT
    in_bOpen : BOOL;
    bClose : BOOL;
    in_close : BOOL;
END_VAR
END_FUNCTION_BLOCK
)";
  const Settings settings{.naming = {{"input", "in_"}}};
  EXPECT_EQ(findings_of("L002", text, settings),
            (Strings{"input 'bClose' should start with 'in_' (e.g. in_bClose) @bClose"}));
  // L001 skips the scope prefix: in_bOpen has its b; in_close has none.
  EXPECT_EQ(findings_of("L001", text, settings),
            (Strings{"'in_close' is BOOL: its name should start with 'b' (e.g. in_bClose) @in_close"}));
}

TEST(NamingRules, PouPrefixOfMembersIsJudgedWhereTheSignatureIs) {
  const std::string text = R"(INTERFACE I_Drive
METHOD Enable : BOOL
END_METHOD
END_INTERFACE
FUNCTION_BLOCK FB_Drive IMPLEMENTS I_Drive
END_FUNCTION_BLOCK
METHOD Enable : BOOL
Enable := TRUE;
END_METHOD
METHOD Disable : BOOL
Disable := TRUE;
END_METHOD
FUNCTION F_Scale : INT
F_Scale := 0;
END_FUNCTION
)";
  const Settings settings{.naming = {{"METHOD", "M_"}, {"FUNCTION", "FC_"}}};
  EXPECT_EQ(findings_of("L003", text, settings),
            (Strings{"method 'I_Drive.Enable' should start with 'M_' (e.g. M_Enable) @Enable",
                     "method 'FB_Drive.Disable' should start with 'M_' (e.g. M_Disable) @Disable",
                     "function 'F_Scale' should start with 'FC_' (e.g. FC_F_Scale) @F_Scale"}));
}

TEST(NamingRules, MinimumNameLengthIsAThreshold) {
  const std::string text = "PROGRAM PRG_Main\nVAR\n    iAge : INT;\n    rSpeed : REAL;\nEND_VAR\nEND_PROGRAM\n";
  const Settings settings{.thresholds = {{"min_name_length", 5}}};
  EXPECT_EQ(findings_of("L005", text, settings), (Strings{"variable 'iAge' is shorter than 5 characters @iAge"}));
}

TEST(NamingRules, CaseIsComparedWithTheDeclarationTheNameResolvesTo) {
  // The local `speed` hides the global `Speed`: its uses are spelled right. `SPEED` in the
  // function refers to the global.
  const std::string text = R"(VAR_GLOBAL
    Speed : INT;
END_VAR
FUNCTION_BLOCK FB_Local
VAR
    speed : INT;
END_VAR
speed := 1;
END_FUNCTION_BLOCK
FUNCTION F_Global : INT
F_Global := SPEED;
END_FUNCTION
)";
  EXPECT_EQ(findings_of("L006", text), (Strings{"'SPEED' is declared as 'Speed' @SPEED"}));
  const std::string fixed = fixed_by("L006", text);
  EXPECT_NE(fixed.find("F_Global := Speed;"), std::string::npos) << fixed;
  EXPECT_NE(fixed.find("speed := 1;"), std::string::npos) << fixed;
}

TEST(NamingRules, CaseIsComparedWithADeclarationInAnotherFile) {
  // Main.st spells the global one way everywhere; only GVL.st shows the declared spelling. A
  // name spelled like every declaration of it (bRun) is fine.
  project::ProjectConfig config;
  auto workspace = check::Workspace::from_texts(
      {{"GVL.st", "VAR_GLOBAL\n    gCount : INT;\n    bRun : BOOL;\nEND_VAR\n"},
       {"Main.st", "PROGRAM PRG_Main\nIF bRun THEN\n    gcount := gcount + 1;\nEND_IF\nEND_PROGRAM\n"}},
      config);
  Strings found;
  for (const FileFindings& file : lint_all(*workspace, config.lint, 1)) {
    for (const Finding& finding : file.findings) {
      if (finding.diagnostic.code == "L006") found.push_back(file.path + ": " + finding.diagnostic.message);
    }
  }
  EXPECT_EQ(found, (Strings{"Main.st: 'gcount' is declared as 'gCount'", "Main.st: 'gcount' is declared as 'gCount'"}));
}

TEST(NamingRules, CommentedOutCodeNeedsCodeThatParses) {
  const std::string text = R"((* Demo of the comment rules. *)
PROGRAM PRG_Main
VAR
    iSpeed : INT;
END_VAR
// Set the motor on

// motor on

// 0 = off; 1 = on

// done;

// Usage: fbMotor(bStart := TRUE);

// x := speed of the belt;

// a OR b;

// iSpeed := 10

// nOld : INT;

// fbOld : FB_Motor;

// iSpeed := 10;
iSpeed := 0;
END_PROGRAM
)";
  // Prose (even IL-like word pairs or bare expressions), a label before code, a statement without
  // ';', an FB instance declaration: not code. `nOld : INT;` and the assignment are.
  EXPECT_EQ(findings_of("L062", text), (Strings{"commented-out code: 'nOld : INT;' @// nOld : INT;",
                                                "commented-out code: 'iSpeed := 10;' @// iSpeed := 10;"}));
  // Lines on consecutive lines are one text: prose among them makes it all prose.
  const std::string run =
      "// Main.\nPROGRAM PRG_Main\nVAR i : INT; END_VAR\n// Set the counter\n// i := 1;\n"
      "//IF i > 0 THEN\n//  i := 0;\n//END_IF\ni := 2;\nEND_PROGRAM\n";
  EXPECT_TRUE(findings_of("L062", run).empty());
}

TEST(NamingRules, TodoWordsAreWholeWords) {
  const std::string text =
      "// Main program.\nPROGRAM PRG_Main\n(* todos, fixmed, XXXL *)\n// ToDo later\nEND_PROGRAM\n";
  EXPECT_EQ(findings_of("L061", text), (Strings{"TODO comment: 'ToDo later' @ToDo"}));
}

}  // namespace
}  // namespace rung::lint
