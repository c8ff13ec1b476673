// The symbol questions the language server asks (checker/query/outline, symbol_search): the
// outline of a file and the search over every declaration of a project.
#include <gtest/gtest.h>

#include <algorithm>

#include "checker/query/outline.hpp"
#include "checker/query/symbol_search.hpp"
#include "tests/support/marked_project.hpp"

namespace rung::check {
namespace {

using query::OutlineItem;
using query::OutlineKind;
using testing::MarkedProject;

// The outline as indented lines "name kind detail", checking on the way that every name lies
// inside its item's range and every child inside its parent's.
void render(const std::vector<OutlineItem>& items, const TextRange* parent, int depth, std::vector<std::string>& out) {
  for (const OutlineItem& item : items) {
    EXPECT_FALSE(item.name.empty());
    EXPECT_LE(item.range.begin, item.selection.begin) << item.name;
    EXPECT_GE(item.range.end, item.selection.end) << item.name;
    if (parent) {
      EXPECT_LE(parent->begin, item.range.begin) << item.name;
      EXPECT_GE(parent->end, item.range.end) << item.name;
    }
    std::string line(static_cast<size_t>(depth) * 2, ' ');
    line += item.name + " " + std::to_string(static_cast<int>(item.kind));
    if (!item.detail.empty()) line += " " + item.detail;
    out.push_back(line);
    render(item.children, &item.range, depth + 1, out);
  }
}

std::vector<std::string> outline_of(const MarkedProject& project, const std::string& path) {
  std::vector<std::string> lines;
  render(query::document_outline(project.model(), project.id(path)), nullptr, 0, lines);
  return lines;
}

std::string k(OutlineKind kind) {
  return " " + std::to_string(static_cast<int>(kind));
}

TEST(Outline, PouWithBlocksMembersAndTheirDetails) {
  const MarkedProject project({{"Motor.st",
                                "FUNCTION_BLOCK FB_Motor EXTENDS FB_Base IMPLEMENTS I_A, I_B\n"
                                "VAR_INPUT bOn : BOOL; END_VAR\n"
                                "VAR CONSTANT RETAIN cMax : INT := 5; END_VAR\n"
                                "VAR a, b : ARRAY[1..2] (* of *)\n    OF   INT; END_VAR\n"
                                "METHOD Start : BOOL\nVAR_INPUT n : INT; END_VAR\nEND_METHOD\n"
                                "PROPERTY Speed : REAL\nGET\nEND_GET\nSET\nEND_SET\nEND_PROPERTY\n"
                                "ACTION Reset:\nEND_ACTION\n"
                                "END_FUNCTION_BLOCK\n"}});
  EXPECT_EQ(outline_of(project, "Motor.st"),
            (std::vector<std::string>{
                "FB_Motor" + k(OutlineKind::FunctionBlock) + " EXTENDS FB_Base IMPLEMENTS I_A, I_B",
                "  VAR_INPUT" + k(OutlineKind::VarBlock),
                "    bOn" + k(OutlineKind::Variable) + " BOOL",
                "  VAR" + k(OutlineKind::VarBlock) + " CONSTANT RETAIN",
                "    cMax" + k(OutlineKind::Constant) + " INT",
                "  VAR" + k(OutlineKind::VarBlock),
                "    a" + k(OutlineKind::Variable) + " ARRAY[1..2] OF INT",
                "    b" + k(OutlineKind::Variable) + " ARRAY[1..2] OF INT",
                "  Start" + k(OutlineKind::Method) + " BOOL",
                "    VAR_INPUT" + k(OutlineKind::VarBlock),
                "      n" + k(OutlineKind::Variable) + " INT",
                "  Speed" + k(OutlineKind::Property) + " REAL",
                "    GET" + k(OutlineKind::Accessor),
                "    SET" + k(OutlineKind::Accessor),
                "  Reset" + k(OutlineKind::Action),
            }));
}

TEST(Outline, TypesGlobalListsAndAProgramsOwnGlobals) {
  const MarkedProject project(
      {{"Types.st",
        "TYPE\n"
        "  ST_P : STRUCT x : INT; END_STRUCT;\n"
        "  E_M : (Idle := 0, Run) DINT;\n"
        "  T_N : UINT;\n"
        "END_TYPE\n"
        "TYPE U_W : UNION w : WORD; b : BYTE; END_UNION END_TYPE\n"},
       {"GVL_Main.st",
        "VAR_GLOBAL g1 : INT; END_VAR\n"
        "VAR_GLOBAL CONSTANT g2 : INT := 1; END_VAR\n"},
       {"Prg.st", "PROGRAM P\nVAR_GLOBAL pg : INT; END_VAR\nVAR x : INT; END_VAR\nEND_PROGRAM\n"}});
  EXPECT_EQ(outline_of(project, "Types.st"), (std::vector<std::string>{
                                                 "ST_P" + k(OutlineKind::Struct),
                                                 "  x" + k(OutlineKind::Field) + " INT",
                                                 "E_M" + k(OutlineKind::Enum) + " DINT",
                                                 "  Idle" + k(OutlineKind::EnumValue) + " 0",
                                                 "  Run" + k(OutlineKind::EnumValue),
                                                 "T_N" + k(OutlineKind::Alias) + " UINT",
                                                 "U_W" + k(OutlineKind::Union),
                                                 "  w" + k(OutlineKind::Field) + " WORD",
                                                 "  b" + k(OutlineKind::Field) + " BYTE",
                                             }));
  EXPECT_EQ(outline_of(project, "GVL_Main.st"), (std::vector<std::string>{
                                                    "GVL_Main" + k(OutlineKind::GlobalList),
                                                    "  VAR_GLOBAL" + k(OutlineKind::VarBlock),
                                                    "    g1" + k(OutlineKind::Variable) + " INT",
                                                    "  VAR_GLOBAL" + k(OutlineKind::VarBlock) + " CONSTANT",
                                                    "    g2" + k(OutlineKind::Constant) + " INT",
                                                }));
  // A PROGRAM's VAR_GLOBAL is shown where it is written, not as a list of its own.
  EXPECT_EQ(outline_of(project, "Prg.st"), (std::vector<std::string>{
                                               "P" + k(OutlineKind::Program),
                                               "  VAR_GLOBAL" + k(OutlineKind::VarBlock),
                                               "    pg" + k(OutlineKind::Variable) + " INT",
                                               "  VAR" + k(OutlineKind::VarBlock),
                                               "    x" + k(OutlineKind::Variable) + " INT",
                                           }));
}

TEST(Outline, SfcAndConfigurations) {
  const MarkedProject project({{"Sfc.st",
                                "PROGRAM P\nVAR go : BOOL; END_VAR\n"
                                "INITIAL_STEP S1: A(N); END_STEP\n"
                                "TRANSITION FROM S1 TO (S2, S3) := go; END_TRANSITION\n"
                                "STEP S2: END_STEP\nSTEP S3: END_STEP\n"
                                "TRANSITION T_Back FROM (S2, S3) TO S1 := NOT go; END_TRANSITION\n"
                                "ACTION A: go := FALSE; END_ACTION\n"
                                "END_PROGRAM\n"},
                               {"Config.st",
                                "CONFIGURATION C\nVAR_GLOBAL g : INT; END_VAR\n"
                                "RESOURCE R ON CPU\nTASK T(INTERVAL := T#5ms);\nPROGRAM I WITH T : P;\nEND_RESOURCE\n"
                                "END_CONFIGURATION\n"}});
  EXPECT_EQ(outline_of(project, "Sfc.st"), (std::vector<std::string>{
                                               "P" + k(OutlineKind::Program),
                                               "  VAR" + k(OutlineKind::VarBlock),
                                               "    go" + k(OutlineKind::Variable) + " BOOL",
                                               "  S1" + k(OutlineKind::Step) + " INITIAL_STEP",
                                               "  S1 -> S2, S3" + k(OutlineKind::Transition) + " go",
                                               "  S2" + k(OutlineKind::Step),
                                               "  S3" + k(OutlineKind::Step),
                                               "  T_Back" + k(OutlineKind::Transition) + " NOT go",
                                               "  A" + k(OutlineKind::Action),
                                           }));
  EXPECT_EQ(outline_of(project, "Config.st"), (std::vector<std::string>{
                                                  "C" + k(OutlineKind::Configuration),
                                                  "  VAR_GLOBAL" + k(OutlineKind::VarBlock),
                                                  "    g" + k(OutlineKind::Variable) + " INT",
                                                  "  R" + k(OutlineKind::Resource) + " ON CPU",
                                                  "    T" + k(OutlineKind::Task) + " (INTERVAL := T#5ms)",
                                                  "    I" + k(OutlineKind::ProgramInstance) + " WITH T : P",
                                              }));
}

TEST(Outline, SnippetsBrokenAndEmptyFiles) {
  const MarkedProject project(
      {{"Snippet.st", "VAR n : INT; END_VAR\nn := n + 1;\n"},
       {"Broken.st", "FUNCTION_BLOCK\nVAR_INPUT x : ; END_VAR\nMETHOD : \nEND_FUNCTION_BLOCK\n"},
       {"Empty.st", ""},
       {"Binary.st", std::string("\0\1\2\3FUNCTION", 12)}});
  EXPECT_EQ(outline_of(project, "Snippet.st"), (std::vector<std::string>{
                                                   "VAR" + k(OutlineKind::VarBlock),
                                                   "  n" + k(OutlineKind::Variable) + " INT",
                                               }));
  EXPECT_FALSE(outline_of(project, "Broken.st").empty());  // named "(no name)" where a name is missing
  EXPECT_TRUE(outline_of(project, "Empty.st").empty());
  outline_of(project, "Binary.st");  // no crash
  EXPECT_TRUE(query::document_outline(project.model(), 100000).empty());
}

TEST(Outline, TwinCatNamesOnlyInTheXmlSelectTheNameAttribute) {
  const std::string text =
      "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n"
      "<TcPlcObject Version=\"1.1.0.1\">\n"
      "  <POU Name=\"FB_A\" Id=\"{1}\">\n"
      "    <Declaration><![CDATA[FUNCTION_BLOCK FB_A\nVAR n : INT; END_VAR\n]]></Declaration>\n"
      "    <Implementation><ST><![CDATA[n := 1;]]></ST></Implementation>\n"
      "    <Action Name=\"A_Go\" Id=\"{2}\">\n"
      "      <Implementation><ST><![CDATA[n := 2;]]></ST></Implementation>\n"
      "    </Action>\n"
      "  </POU>\n"
      "</TcPlcObject>\n";
  const MarkedProject project({{"FB_A.TcPOU", text}});
  const auto outline = query::document_outline(project.model(), project.id("FB_A.TcPOU"));
  ASSERT_EQ(outline.size(), 1u);
  EXPECT_EQ(outline[0].selection.begin, project.at("FB_A.TcPOU", "FUNCTION_BLOCK |FB_A"));
  const OutlineItem& action = outline[0].children.back();
  EXPECT_EQ(action.name, "A_Go");
  EXPECT_EQ(action.selection.begin, project.at("FB_A.TcPOU", "Action Name=\"|A_Go"));
  EXPECT_EQ(action.selection.end - action.selection.begin, 4u);
}

TEST(Outline, CutText) {
  EXPECT_EQ(query::cut_text("abc", 3), "abc");
  EXPECT_EQ(query::cut_text("abcdef", 3), "abc...");
  EXPECT_EQ(query::cut_text("ab\xC3\xA4", 3), "ab...");  // never half a UTF-8 character
}

TEST(SymbolSearch, ScoresRankExactPrefixPartScattered) {
  const auto exact = query::match_score("fb_motor", "FB_Motor");
  const auto prefix = query::match_score("fb_mo", "FB_Motor");
  const auto part = query::match_score("motor", "FB_Motor");
  const auto inner = query::match_score("otor", "FB_Motor");
  const auto scattered = query::match_score("fbm", "FB_Motor");
  ASSERT_TRUE(exact && prefix && part && inner && scattered);
  EXPECT_GT(*exact, *prefix);
  EXPECT_GT(*prefix, *part);
  EXPECT_GT(*part, *inner);  // a part at a word start counts more
  EXPECT_GT(*inner, *scattered);
  EXPECT_GT(*query::match_score("fbm", "FB_Motor"), *query::match_score("fbm", "FB_xxxxxxxxxMotor"));
  EXPECT_FALSE(query::match_score("mf", "FB_Motor"));  // order matters
  EXPECT_FALSE(query::match_score("FB_Motors", "FB_Motor"));
  EXPECT_EQ(query::match_score("", "anything"), 0);
}

const MarkedProject::Files kSearch = {
    {"Motor.st",
     "FUNCTION_BLOCK FB_Motor\n"
     "METHOD Start : BOOL\nEND_METHOD\n"
     "PROPERTY Speed : INT\nGET\nEND_GET\nEND_PROPERTY\n"
     "ACTION Stop:\nEND_ACTION\n"
     "END_FUNCTION_BLOCK\n"
     "{attribute 'hide'}\nFUNCTION_BLOCK FB_Hidden\nEND_FUNCTION_BLOCK\n"
     "FUNCTION_BLOCK TONX\nEND_FUNCTION_BLOCK\n"},
    {"Types.st", "TYPE E_State : (Starting, Running); END_TYPE\n"},
    {"GVL.st", "VAR_GLOBAL gStartCount : INT; END_VAR\n"},
    {"Snippet.st", "VAR s : INT; END_VAR\ns := 1;\n"},
};

std::vector<std::string> found(const std::vector<query::SymbolMatch>& matches) {
  std::vector<std::string> out;
  for (const auto& match : matches)
    out.push_back(match.name + (match.container.empty() ? "" : " in " + match.container));
  return out;
}

TEST(SymbolSearch, FindsPousMembersEnumValuesAndGlobals) {
  const MarkedProject project(kSearch);
  const query::SymbolSearch options;
  EXPECT_EQ(
      found(query::search_symbols(project.model(), "start", options)),
      (std::vector<std::string>{"FB_Motor.Start in FB_Motor", "E_State.Starting in E_State", "gStartCount in GVL"}));
  EXPECT_EQ(found(query::search_symbols(project.model(), "fbm.spe", options)),
            (std::vector<std::string>{"FB_Motor.Speed in FB_Motor"}));
  EXPECT_TRUE(query::search_symbols(project.model(), "FB_Hidden", options).empty());  // {attribute 'hide'}
  for (const auto& match : query::search_symbols(project.model(), "GET", options)) {  // accessors are not listed
    EXPECT_NE(match.symbol->owner ? match.symbol->owner->kind : SymbolKind::Program, SymbolKind::Property);
  }
}

TEST(SymbolSearch, ProjectBeforeLibraryAndTheLimit) {
  const MarkedProject project(kSearch);
  const auto ton = query::search_symbols(project.model(), "TON", {});
  ASSERT_GE(ton.size(), 3u);
  EXPECT_EQ(ton[0].name, "TONX");  // the project's, though the library's TON is exact
  EXPECT_FALSE(ton[0].library);
  EXPECT_EQ(ton[1].name, "TON");
  EXPECT_TRUE(ton[1].library);
  // Scattered letters (gStartCount) come after every name that contains TON, the library's too.
  const auto scattered = std::find_if(ton.begin(), ton.end(), [](const auto& m) { return m.name == "gStartCount"; });
  ASSERT_NE(scattered, ton.end());
  EXPECT_TRUE(std::all_of(ton.begin(), scattered,
                          [](const auto& m) { return upper_name(m.name).find("TON") != std::string::npos; }));
  query::SymbolSearch three;
  three.limit = 3;
  EXPECT_EQ(query::search_symbols(project.model(), "", three).size(), 3u);
}

TEST(SymbolSearch, SkipAndCancel) {
  const MarkedProject project(kSearch);
  const SourceId gvl = project.id("GVL.st");
  query::SymbolSearch skip_gvl;
  skip_gvl.skip = [&](SourceId id) { return id == gvl; };
  EXPECT_TRUE(query::search_symbols(project.model(), "gStartCount", skip_gvl).empty());
  query::SymbolSearch cancelled;
  cancelled.cancelled = [] { return true; };
  EXPECT_TRUE(query::search_symbols(project.model(), "FB_Motor", cancelled).empty());
}

}  // namespace
}  // namespace rung::check
