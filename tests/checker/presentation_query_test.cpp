// The queries behind the editor's presentation features (checker/query): what each name of a
// file is (semantic highlighting), which lines fold, and the ranges "expand selection" goes
// through.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "checker/check.hpp"
#include "checker/query/folding.hpp"
#include "checker/query/name_classes.hpp"
#include "checker/query/selection.hpp"

namespace rung::check {
namespace {

using query::ClassifiedName;
using query::NameClass;
using Files = std::vector<std::pair<std::string, std::string>>;

std::unique_ptr<Workspace> load(const Files& files) { return Workspace::from_texts(files, project::ProjectConfig{}); }

std::string_view class_name(NameClass name_class) {
  switch (name_class) {
    case NameClass::Namespace: return "namespace";
    case NameClass::Program: return "program";
    case NameClass::FunctionBlock: return "fb";
    case NameClass::Interface: return "interface";
    case NameClass::Function: return "function";
    case NameClass::Method: return "method";
    case NameClass::Action: return "action";
    case NameClass::Property: return "property";
    case NameClass::Struct: return "struct";
    case NameClass::Enum: return "enum";
    case NameClass::Alias: return "alias";
    case NameClass::Input: return "input";
    case NameClass::Output: return "output";
    case NameClass::InOut: return "inout";
    case NameClass::Local: return "local";
    case NameClass::Global: return "global";
    case NameClass::Field: return "field";
    case NameClass::EnumValue: return "enumvalue";
  }
  return "?";
}

// "name:class+flags" for every classified name of `path`, in order; flags as letters:
// d declaration, c constant, i instance, l library, s static.
std::vector<std::string> describe(const Workspace& workspace, const std::string& path, TextRange range = {0, UINT32_MAX}) {
  const ProjectModel& model = workspace.model();
  const SourceId id = *model.find_source(path);
  const std::string_view text = model.source(id).document->file_text();
  std::vector<std::string> out;
  for (const ClassifiedName& name : query::classify_names(model, id, range)) {
    std::string item(text.substr(name.range.begin, name.range.end - name.range.begin));
    item += ":";
    item += class_name(name.name_class);
    const std::pair<uint16_t, char> flags[] = {{query::kNameDeclaration, 'd'},
                                               {query::kNameConstant, 'c'},
                                               {query::kNameInstance, 'i'},
                                               {query::kNameLibrary, 'l'},
                                               {query::kNameStatic, 's'}};
    std::string letters;
    for (const auto& [flag, letter] : flags) {
      if (name.flags & flag) letters += letter;
    }
    if (!letters.empty()) item += "+" + letters;
    out.push_back(item);
  }
  return out;
}

const Files kPlant = {
    {"GVL.st", "VAR_GLOBAL gSpeed : INT; END_VAR\nVAR_GLOBAL CONSTANT gMax : INT := 9; END_VAR\n"},
    {"Types.st", "TYPE E_Mode : (Idle, Run); END_TYPE\nTYPE ST_P : STRUCT x : REAL; END_STRUCT END_TYPE\n"},
    {"FB.st",
     "FUNCTION_BLOCK FB_Pump\n"
     "VAR_INPUT go : BOOL; END_VAR\n"
     "VAR_OUTPUT busy : BOOL; END_VAR\n"
     "VAR_IN_OUT p : ST_P; END_VAR\n"
     "VAR t : TON; m : E_Mode; END_VAR\n"
     "VAR_STAT n : INT; END_VAR\n"
     "VAR_EXTERNAL gSpeed : INT; END_VAR\n"
     "t(IN := go);\n"
     "busy := t.Q OR gSpeed > gMax;\n"
     "p.x := 1.0;\n"
     "m := E_Mode.Run;\n"
     "undeclared := THIS^.n;\n"
     "END_FUNCTION_BLOCK\n"},
};

TEST(NameClasses, EveryRoleOfAName) {
  const auto workspace = load(kPlant);
  EXPECT_EQ(describe(*workspace, "FB.st"),
            (std::vector<std::string>{
                "FB_Pump:fb+d", "go:input+d", "busy:output+d", "p:inout+d", "ST_P:struct", "t:local+di",
                "TON:fb+l", "m:local+d", "E_Mode:enum", "n:local+ds",
                "gSpeed:global",  // VAR_EXTERNAL: the global it stands for
                "t:local+i", "IN:input+l", "go:input", "busy:output", "t:local+i", "Q:output+l", "gSpeed:global",
                "gMax:global+c", "p:inout", "x:field", "m:local", "E_Mode:enum", "Run:enumvalue+c",
                // THIS is a keyword; the undeclared name has no class
                "n:local+s"}));
  EXPECT_EQ(describe(*workspace, "Types.st"), (std::vector<std::string>{"E_Mode:enum+d", "Idle:enumvalue+dc",
                                                                        "Run:enumvalue+dc", "ST_P:struct+d",
                                                                        "x:field+d"}));
  EXPECT_EQ(describe(*workspace, "GVL.st"), (std::vector<std::string>{"gSpeed:global+d", "gMax:global+dc"}));
}

TEST(NameClasses, OnlyNamesStartingInTheRange) {
  const auto workspace = load(kPlant);
  const std::string& text = kPlant[2].second;
  const uint32_t begin = static_cast<uint32_t>(text.find("busy := "));
  const uint32_t end = static_cast<uint32_t>(text.find("p.x"));
  EXPECT_EQ(describe(*workspace, "FB.st", {begin, end}),
            (std::vector<std::string>{"busy:output", "t:local+i", "Q:output+l", "gSpeed:global", "gMax:global+c"}));
}

TEST(NameClasses, StopsWhenCancelled) {
  std::string text = "PROGRAM P\nVAR x : INT; END_VAR\n";
  for (int i = 0; i < 1000; ++i) text += "x := x + 1;\n";
  text += "END_PROGRAM\n";
  const auto workspace = load({{"p.st", text}});
  const ProjectModel& model = workspace->model();
  const SourceId id = *model.find_source("p.st");
  int polls = 0;
  const auto names = query::classify_names(model, id, {0, UINT32_MAX}, [&polls] { return ++polls == 2; });
  EXPECT_EQ(polls, 2);
  EXPECT_LT(names.size(), 1000u);
  EXPECT_GE(names.size(), 256u);
  EXPECT_EQ(query::classify_names(model, id, {0, UINT32_MAX}).size(), 2u + 2000u);  // P, the declaration, the uses
}

TEST(NameClasses, MethodsPropertiesActionsFunctionsInterfaces) {
  const auto workspace = load({{"a.st",
                                "INTERFACE I_Run METHOD Go : BOOL END_METHOD END_INTERFACE\n"
                                "FUNCTION Twice : INT VAR_INPUT v : INT; END_VAR Twice := v * 2; END_FUNCTION\n"
                                "FUNCTION_BLOCK FB IMPLEMENTS I_Run\n"
                                "VAR r : I_Run; END_VAR\n"
                                "METHOD Go : BOOL Go := Level > Twice(1); END_METHOD\n"
                                "PROPERTY Level : INT GET Level := 1; END_GET END_PROPERTY\n"
                                "ACTION Tick: r.Go(); END_ACTION\n"
                                "END_FUNCTION_BLOCK\n"}});
  EXPECT_EQ(describe(*workspace, "a.st"),
            (std::vector<std::string>{"I_Run:interface+d", "Go:method+d", "Twice:function+d", "v:input+d",
                                      "Twice:function", "v:input", "FB:fb+d", "I_Run:interface", "r:local+di",
                                      "I_Run:interface", "Go:method+d", "Go:method", "Level:property",
                                      "Twice:function", "Level:property+d", "Level:property", "Tick:action+d",
                                      "r:local+i", "Go:method"}));
}

// Folds as "first-last" (1-based lines) with c for comments and r for regions.
std::vector<std::string> folds_of(const std::string& text) {
  const Document document = Document::from_bytes("a.st", text);
  std::vector<std::string> out;
  for (const query::Fold& fold : query::folding_ranges(document)) {
    std::string item = std::to_string(fold.first_line + 1) + "-" + std::to_string(fold.last_line + 1);
    if (fold.kind == query::FoldKind::Comment) item += "c";
    if (fold.kind == query::FoldKind::Region) item += "r";
    out.push_back(item);
  }
  return out;
}

TEST(Folding, BlocksStopBeforeTheirClosingKeyword) {
  EXPECT_EQ(folds_of("PROGRAM P\n"          // 1
                     "VAR\n"                // 2
                     "  x : INT;\n"         // 3
                     "END_VAR\n"            // 4
                     "WHILE x < 3 DO\n"     // 5
                     "  x := x + 1;\n"      // 6
                     "END_WHILE\n"          // 7
                     "IF x > 1 THEN x := 0; END_IF\n"  // 8: one line, no fold
                     "END_PROGRAM\n"),
            (std::vector<std::string>{"1-8", "2-3", "5-6"}));
}

TEST(Folding, IfBranchesCommentsAndRegions) {
  EXPECT_EQ(folds_of("PROGRAM P\n"       // 1
                     "VAR x : INT; END_VAR\n"  // 2
                     "{region \"r\"}\n"  // 3
                     "// a\n"            // 4
                     "// b\n"            // 5
                     "IF x = 1 THEN\n"   // 6
                     "  x := 2;\n"       // 7
                     "ELSE\n"            // 8
                     "  x := 3;\n"       // 9
                     "END_IF\n"          // 10
                     "{endregion}\n"     // 11
                     "(* one\n"          // 12
                     "   two *)\n"       // 13
                     "x := 1; // c\n"    // 14: a trailing comment starts no run
                     "// d\n"            // 15
                     "END_PROGRAM\n"),
            (std::vector<std::string>{"1-15", "3-11r", "4-5c", "6-7", "8-9", "12-13c"}));
}

TEST(Folding, BrokenAndUnparsedFilesGiveWhatTheTreeHas) {
  EXPECT_EQ(folds_of("PROGRAM P\nIF x THEN\n  x := 1;\n"), (std::vector<std::string>{"1-3", "2-3"}));
  EXPECT_TRUE(folds_of("").empty());
  EXPECT_TRUE(folds_of(std::string("\0\1\2", 3)).empty());
}

// The selection ranges at the '|' of `marked`, as the texts they select.
std::vector<std::string> selections(const std::string& marked) {
  const size_t cursor = marked.find('|');
  std::string text = marked;
  text.erase(cursor, 1);
  const Document document = Document::from_bytes("a.st", text);
  std::vector<std::string> out;
  for (const TextRange range : query::selection_ranges(document, static_cast<uint32_t>(cursor))) {
    out.push_back(text.substr(range.begin, range.end - range.begin));
  }
  return out;
}

TEST(Selection, FromTheNameOutToTheFile) {
  const std::string program = "PROGRAM P\nVAR a : INT; END_VAR\nIF a > 0 THEN\n  a := a + 1;\nEND_IF\nEND_PROGRAM\n";
  std::string marked = program;
  marked.insert(marked.find("a + 1") + 1, "|");  // right after the name: still on it
  EXPECT_EQ(selections(marked), (std::vector<std::string>{
                                    "a",
                                    "a + 1",
                                    "a := a + 1;",
                                    "IF a > 0 THEN\n  a := a + 1;\nEND_IF",  // its statement list is no larger
                                    program.substr(0, program.size() - 1),  // the PROGRAM
                                    program,                                // the file
                                }));
}

TEST(Selection, NothingOutsideTheParsedText) {
  EXPECT_TRUE(selections(std::string("\0\1|\2", 4)).empty());
  EXPECT_EQ(selections("|").size(), 1u);  // the empty file itself
}

}  // namespace
}  // namespace rung::check
