// Completion (checker/query/completion, cursor_context, call_site): what the editor offers at a
// position, in finished and in half-typed code. Positions are written as a snippet of the file
// with '|' where the cursor stands.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "checker/query/call_site.hpp"
#include "checker/query/completion.hpp"
#include "tests/support/marked_project.hpp"

namespace rung::check {
namespace {

using testing::MarkedProject;
using Files = MarkedProject::Files;

// Each candidate as the editor would list it: "name" for declarations, "name:=" for parameters
// (name=> for outputs), "#KEYWORD", "$SNIPPET", "E.v" for a qualified value.
std::vector<std::string> offered(const MarkedProject& project, const std::string& path, const std::string& marked) {
  const query::Completion completion =
      query::complete_at(project.workspace(), project.id(path), project.at(path, marked));
  std::vector<std::string> out;
  for (const query::CompletionCandidate& candidate : completion.candidates) {
    switch (candidate.kind) {
      case query::CandidateKind::Symbol:
        out.push_back(candidate.qualifier.empty() ? std::string(candidate.symbol->name)
                                                  : std::string(candidate.qualifier) + "." + std::string(candidate.symbol->name));
        break;
      case query::CandidateKind::Parameter:
        out.push_back(std::string(candidate.symbol->name) +
                      (candidate.symbol->section == ast::VarSection::Output ? "=>" : ":="));
        break;
      case query::CandidateKind::Keyword:
      case query::CandidateKind::ElementaryType: out.push_back("#" + std::string(candidate.word)); break;
      case query::CandidateKind::LibraryNamespace: out.push_back(std::string(candidate.word)); break;
      case query::CandidateKind::Snippet: out.push_back("$" + std::string(candidate.word)); break;
    }
  }
  return out;
}

bool has(const std::vector<std::string>& list, const std::string& item) {
  return std::find(list.begin(), list.end(), item) != list.end();
}

size_t index_of(const std::vector<std::string>& list, const std::string& item) {
  return static_cast<size_t>(std::find(list.begin(), list.end(), item) - list.begin());
}

const char* const kTypes =
    "TYPE E_Color : (Red, Green, Blue); END_TYPE\n"
    "TYPE ST_Point : STRUCT x : INT; y : INT; END_STRUCT END_TYPE\n";

const char* const kGlobals =
    "{attribute 'qualified_only'}\n"
    "VAR_GLOBAL\n"
    "  gHidden : INT;\n"
    "END_VAR\n";

TEST(QueryCompletion, MembersAfterADotInUnfinishedCode) {
  const MarkedProject project(Files{{"types.st", kTypes},
                                    {"main.st",
                                     "PROGRAM Main\n"
                                     "VAR\n"
                                     "  fbTimer : TON;\n"
                                     "  pt : ST_Point;\n"
                                     "END_VAR\n"
                                     "fbTimer.\n"
                                     "pt.\n"
                                     "END_PROGRAM\n"}});
  EXPECT_EQ(offered(project, "main.st", "fbTimer.|\n"), (std::vector<std::string>{"IN", "PT", "Q", "ET"}));
  EXPECT_EQ(offered(project, "main.st", "pt.|\n"), (std::vector<std::string>{"x", "y"}));
}

TEST(QueryCompletion, BodyOffersLocalsFirstThenGlobalsFunctionsAndKeywords) {
  const MarkedProject project(Files{{"types.st", kTypes},
                                    {"gvl.st", "VAR_GLOBAL gSpeed : INT; END_VAR\n"},
                                    {"GVL_Hidden.st", kGlobals},
                                    {"main.st",
                                     "FUNCTION Clamp : INT\nVAR_INPUT v : INT; END_VAR\nClamp := v;\nEND_FUNCTION\n"
                                     "PROGRAM Main\n"
                                     "VAR\n"
                                     "  counter : INT;\n"
                                     "  fbTimer : TON;\n"
                                     "END_VAR\n"
                                     "counter := 1;\n"
                                     "\n"
                                     "END_PROGRAM\n"}});
  const std::vector<std::string> list = offered(project, "main.st", "counter := 1;\n|");
  ASSERT_TRUE(has(list, "counter"));
  EXPECT_EQ(index_of(list, "counter"), 0u);  // locals first
  EXPECT_TRUE(has(list, "fbTimer"));
  EXPECT_TRUE(has(list, "gSpeed"));
  EXPECT_TRUE(has(list, "Clamp"));
  EXPECT_TRUE(has(list, "LIMIT"));    // a library function
  EXPECT_TRUE(has(list, "E_Color"));  // for E_Color.Red
  EXPECT_TRUE(has(list, "#IF"));
  EXPECT_TRUE(has(list, "$IF"));
  EXPECT_TRUE(has(list, "#END_PROGRAM"));
  EXPECT_FALSE(has(list, "gHidden"));     // qualified_only: only as GVL_Hidden.gHidden
  EXPECT_TRUE(has(list, "GVL_Hidden"));
  EXPECT_FALSE(has(list, "TON"));       // a block type is no value
  EXPECT_FALSE(has(list, "ST_Point"));  // nor a structure type
  EXPECT_LT(index_of(list, "gSpeed"), index_of(list, "Clamp"));
  EXPECT_LT(index_of(list, "Clamp"), index_of(list, "LIMIT"));
}

TEST(QueryCompletion, QualifiedOnlyListsAndEnumerationsAfterTheirName) {
  const MarkedProject project(Files{{"types.st", kTypes},
                                    {"GVL_Hidden.st", kGlobals},
                                    {"main.st",
                                     "PROGRAM Main\nVAR c : E_Color; END_VAR\n"
                                     "GVL_Hidden.\n"
                                     "c := E_Color.\n"
                                     "c := E_Color#\n"
                                     "END_PROGRAM\n"}});
  EXPECT_EQ(offered(project, "main.st", "GVL_Hidden.|"), (std::vector<std::string>{"gHidden"}));
  EXPECT_EQ(offered(project, "main.st", "E_Color.|"), (std::vector<std::string>{"Red", "Green", "Blue"}));
  EXPECT_EQ(offered(project, "main.st", "E_Color#|"), (std::vector<std::string>{"Red", "Green", "Blue"}));
}

TEST(QueryCompletion, TypePositionsOfferTypesOnly) {
  const MarkedProject project(Files{{"types.st", kTypes},
                                    {"blocks.st",
                                     "INTERFACE I_Run\nEND_INTERFACE\n"
                                     "FUNCTION_BLOCK FB_Base\nEND_FUNCTION_BLOCK\n"
                                     "FUNCTION_BLOCK FB_Derived EXTENDS FB_Motor\nEND_FUNCTION_BLOCK\n"},
                                    {"main.st",
                                     "FUNCTION_BLOCK FB_Motor EXTENDS \n"
                                     "VAR\n"
                                     "  speed : \n"
                                     "  list : ARRAY[1..3] OF \n"
                                     "END_VAR\n"
                                     "END_FUNCTION_BLOCK\n"
                                     "FUNCTION_BLOCK FB_Pump IMPLEMENTS \nEND_FUNCTION_BLOCK\n"}});
  const std::vector<std::string> types = offered(project, "main.st", "speed : |");
  EXPECT_TRUE(has(types, "#INT"));
  EXPECT_TRUE(has(types, "ST_Point"));
  EXPECT_TRUE(has(types, "E_Color"));
  EXPECT_TRUE(has(types, "TON"));
  EXPECT_TRUE(has(types, "#ARRAY"));
  EXPECT_FALSE(has(types, "speed"));
  EXPECT_FALSE(has(types, "LIMIT"));  // a function is no type
  EXPECT_FALSE(has(types, "#IF"));
  EXPECT_TRUE(has(offered(project, "main.st", "OF |"), "ST_Point"));
  const std::vector<std::string> bases = offered(project, "main.st", "EXTENDS |");
  EXPECT_TRUE(has(bases, "FB_Base"));
  EXPECT_FALSE(has(bases, "FB_Motor"));   // a block cannot extend itself
  EXPECT_FALSE(has(bases, "FB_Derived"));  // nor one that extends it (a cycle)
  EXPECT_FALSE(has(bases, "I_Run"));
  EXPECT_FALSE(has(bases, "#INT"));
  const std::vector<std::string> interfaces = offered(project, "main.st", "IMPLEMENTS |");
  EXPECT_EQ(interfaces, (std::vector<std::string>{"I_Run"}));
}

TEST(QueryCompletion, NamedParametersInsideACall) {
  const MarkedProject project(Files{{"main.st",
                                     "PROGRAM Main\n"
                                     "VAR fbTimer : TON; x : INT; END_VAR\n"
                                     "fbTimer(\n"
                                     "fbTimer(IN := TRUE, \n"
                                     "x := LIMIT(\n"
                                     "END_PROGRAM\n"}});
  const std::vector<std::string> first = offered(project, "main.st", "fbTimer(|\n");
  EXPECT_EQ(std::vector<std::string>(first.begin(), first.begin() + 4),
            (std::vector<std::string>{"IN:=", "PT:=", "Q=>", "ET=>"}));
  EXPECT_EQ(first.size(), 4u);  // a function block takes formal arguments only
  const std::vector<std::string> rest = offered(project, "main.st", "IN := TRUE, |");
  EXPECT_EQ(std::vector<std::string>(rest.begin(), rest.begin() + 3), (std::vector<std::string>{"PT:=", "Q=>", "ET=>"}));
  EXPECT_FALSE(has(rest, "IN:="));
  const std::vector<std::string> limit = offered(project, "main.st", "LIMIT(|");
  EXPECT_EQ(std::vector<std::string>(limit.begin(), limit.begin() + 3), (std::vector<std::string>{"MN:=", "IN:=", "MX:="}));
  EXPECT_TRUE(has(limit, "x"));  // a function's arguments may be given by position
}

TEST(QueryCompletion, ExpectedEnumerationValuesComeFirst) {
  const MarkedProject project(Files{{"types.st", kTypes},
                                    {"main.st",
                                     "PROGRAM Main\nVAR c : E_Color; n : INT; END_VAR\n"
                                     "c := \n"
                                     "END_PROGRAM\n"}});
  const std::vector<std::string> list = offered(project, "main.st", "c := |");
  ASSERT_GE(list.size(), 3u);
  EXPECT_EQ(std::vector<std::string>(list.begin(), list.begin() + 3),
            (std::vector<std::string>{"E_Color.Red", "E_Color.Green", "E_Color.Blue"}));
  EXPECT_TRUE(has(list, "#TRUE"));
}

TEST(QueryCompletion, KeywordsThatContinueOrCloseTheStatement) {
  const MarkedProject project(Files{{"main.st",
                                     "PROGRAM Main\nVAR x : BOOL; i : INT; END_VAR\n"
                                     "IF x \n"
                                     "IF x THEN\n"
                                     "  i := 1;\n"
                                     "  \n"
                                     "FOR i := 1 \n"
                                     "END_PROGRAM\n"}});
  const std::vector<std::string> condition = offered(project, "main.st", "IF x |\n");
  EXPECT_EQ(condition.front(), "#THEN");
  EXPECT_TRUE(has(condition, "#AND"));
  EXPECT_FALSE(has(condition, "x"));
  const std::vector<std::string> inside = offered(project, "main.st", "  i := 1;\n  |");
  EXPECT_TRUE(has(inside, "#END_IF"));
  EXPECT_TRUE(has(inside, "#ELSIF"));
  EXPECT_TRUE(has(inside, "i"));
  EXPECT_TRUE(has(offered(project, "main.st", "FOR i := 1 |"), "#TO"));
}

TEST(QueryCompletion, DeclarationsAndTopLevel) {
  const MarkedProject project(Files{{"main.st",
                                     "\n"
                                     "FUNCTION_BLOCK FB_A\n"
                                     "VAR_INPUT\n"
                                     "  a : INT;\n"
                                     "  \n"
                                     "END_VAR\n"
                                     "\n"
                                     "END_FUNCTION_BLOCK\n"
                                     "// a comment here\n"}});
  const std::vector<std::string> top = offered(project, "main.st", "|\nFUNCTION_BLOCK FB_A");
  EXPECT_TRUE(has(top, "#PROGRAM"));
  EXPECT_TRUE(has(top, "$FUNCTION_BLOCK"));
  EXPECT_FALSE(has(top, "#IF"));
  EXPECT_EQ(offered(project, "main.st", "  a : INT;\n  |"), (std::vector<std::string>{"#END_VAR"}));
  const std::vector<std::string> header = offered(project, "main.st", "END_VAR\n|\nEND_FUNCTION_BLOCK");
  EXPECT_TRUE(has(header, "#VAR_OUTPUT"));
  EXPECT_TRUE(has(header, "$METHOD"));
  EXPECT_TRUE(has(header, "#END_FUNCTION_BLOCK"));
  EXPECT_TRUE(has(header, "a"));  // the body may begin here
  EXPECT_TRUE(offered(project, "main.st", "// a comm|ent").empty());
}

TEST(QueryCompletion, ThisAndMethodScope) {
  const MarkedProject project(Files{{"main.st",
                                     "FUNCTION_BLOCK FB_Base\nVAR_INPUT b : INT; END_VAR\nVAR hidden : INT; END_VAR\n"
                                     "END_FUNCTION_BLOCK\n"
                                     "FUNCTION_BLOCK FB_A EXTENDS FB_Base\n"
                                     "VAR own : INT; END_VAR\n"
                                     "METHOD Run\n"
                                     "VAR local : INT; END_VAR\n"
                                     "THIS^.\n"
                                     "\n"
                                     "END_METHOD\n"
                                     "END_FUNCTION_BLOCK\n"}});
  const std::vector<std::string> self = offered(project, "main.st", "THIS^.|");
  EXPECT_TRUE(has(self, "own"));
  EXPECT_TRUE(has(self, "Run"));
  EXPECT_TRUE(has(self, "b"));
  const std::vector<std::string> body = offered(project, "main.st", "THIS^.\n|");
  EXPECT_EQ(body.front(), "local");
  EXPECT_TRUE(has(body, "own"));
  EXPECT_LT(index_of(body, "local"), index_of(body, "own"));
  EXPECT_TRUE(has(body, "#THIS"));
}

TEST(QueryCompletion, PrefixFiltersAndTheWordIsReplaced) {
  const MarkedProject project(Files{{"main.st",
                                     "PROGRAM Main\nVAR counter : INT; other : INT; END_VAR\n"
                                     "cou := 1;\n"
                                     "END_PROGRAM\n"}});
  const query::Completion completion =
      query::complete_at(project.workspace(), project.id("main.st"), project.at("main.st", "co|u :="));
  EXPECT_EQ(completion.prefix, "co");
  EXPECT_EQ(completion.word.begin, project.at("main.st", "|cou :="));
  EXPECT_EQ(completion.word.end, project.at("main.st", "cou| :="));
  ASSERT_FALSE(completion.candidates.empty());
  EXPECT_EQ(completion.candidates.front().name(), "counter");
  for (const auto& candidate : completion.candidates) EXPECT_TRUE(query::matches_prefix(candidate.name(), "co"));
  EXPECT_TRUE(query::matches_prefix("fbTimer", "tim"));
  EXPECT_FALSE(query::matches_prefix("fbTimer", "timx"));
  EXPECT_TRUE(query::matches_prefix("MAX_VALUE", "mv"));
  EXPECT_FALSE(query::matches_prefix("fbTimer", "imer"));  // not where a part begins
}

// Within a group, names that start with the typed letters come first, then the looser matches:
// a client that keeps the server's order (Neovim's omnifunc) shows LIMIT before ADD_LTIME.
TEST(QueryCompletion, NamesStartingWithTheTypedLettersComeFirstInTheirGroup) {
  const MarkedProject project(Files{{"main.st",
                                     "PROGRAM Main\nVAR bLimitHit : BOOL; LimitLow : INT; END_VAR\n"
                                     "LimitLow := LIM;\n"
                                     "END_PROGRAM\n"}});
  const std::vector<std::string> names = offered(project, "main.st", "LimitLow := LIM|;");
  const auto position = [&](const std::string& name) {
    return std::find(names.begin(), names.end(), name) - names.begin();
  };
  ASSERT_LT(position("LIMIT"), static_cast<std::ptrdiff_t>(names.size()));
  ASSERT_LT(position("ADD_LTIME"), static_cast<std::ptrdiff_t>(names.size()));
  EXPECT_LT(position("LIMIT"), position("ADD_LTIME"));
  // The same in the POU's own names, which still come before every library function.
  EXPECT_LT(position("LimitLow"), position("bLimitHit"));
  EXPECT_LT(position("bLimitHit"), position("LIMIT"));
}

TEST(QueryCompletion, InsideATwinCatContainer) {
  const std::string pou =
      "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n"
      "<TcPlcObject Version=\"1.1.0.1\">\n"
      "  <POU Name=\"FB_Valve\" Id=\"{1}\">\n"
      "    <Declaration><![CDATA[FUNCTION_BLOCK FB_Valve\n"
      "VAR\n"
      "  fbDelay : TON;\n"
      "END_VAR\n"
      "]]></Declaration>\n"
      "    <Implementation>\n"
      "      <ST><![CDATA[fbDelay.]]></ST>\n"
      "    </Implementation>\n"
      "  </POU>\n"
      "</TcPlcObject>\n";
  const MarkedProject project(Files{{"FB_Valve.TcPOU", pou}}, project::Profile::Twincat);
  EXPECT_EQ(offered(project, "FB_Valve.TcPOU", "fbDelay.|]]"), (std::vector<std::string>{"IN", "PT", "Q", "ET"}));
  EXPECT_TRUE(offered(project, "FB_Valve.TcPOU", "<POU Na|me").empty());  // XML markup
}

TEST(QueryCallSite, ActiveParameterByPositionNameAndExtensibleInputs) {
  const MarkedProject project(Files{{"main.st",
                                     "PROGRAM Main\nVAR fbTimer : TON; x : INT; END_VAR\n"
                                     "x := LIMIT(0, x, 5);\n"
                                     "x := MAX(1, 2, 3, 4);\n"
                                     "fbTimer(IN := TRUE, PT := T#1S);\n"
                                     "END_PROGRAM\n"}});
  auto active = [&](const std::string& marked) -> std::string {
    const auto site = query::call_site_at(project.workspace(), project.id("main.st"), project.at("main.st", marked));
    if (!site) return "none";
    return std::string(site->callee->name) + ":" + (site->active ? std::string(site->active->name) : "-");
  };
  EXPECT_EQ(active("LIMIT(|0"), "LIMIT:MN");
  EXPECT_EQ(active("LIMIT(0, |x"), "LIMIT:IN");
  EXPECT_EQ(active("LIMIT(0, x, 5|)"), "LIMIT:MX");
  EXPECT_EQ(active("MAX(1, 2, 3, |4"), "MAX:IN2");  // extensible
  EXPECT_EQ(active("PT := T#1|S"), "TON:PT");
  EXPECT_EQ(active("fbTimer(IN := TR|UE"), "TON:IN");
  EXPECT_EQ(active("fbTimer(IN := TRUE,| PT"), "TON:PT");  // after a formal argument: the next input not named
  EXPECT_EQ(active("x := LIM|IT"), "none");
  EXPECT_EQ(query::call_parameters(project.model().find_global("TON")).size(), 4u);
}

}  // namespace
}  // namespace rung::check
