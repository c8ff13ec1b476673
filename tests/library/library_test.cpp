// The shipped libraries (library/): the ST that the checker reads for the signatures of the
// standard functions and function blocks and the runner compiles where a POU has a body
// (docs/library.md).
//
// These tests pin (a) that every file parses without a diagnostic, (b) the interfaces of the key
// blocks as the seed manuals give them, (c) that no name is declared twice across the libraries,
// (d) that every declaration carries a doc comment with a `source:` reference, and (e) that a
// block's internal state is hidden.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "parser/ast.hpp"
#include "parser/document.hpp"
#include "parser/file_walk.hpp"
#include "tests/support/test_paths.hpp"

namespace rung {
namespace {

namespace fs = std::filesystem;

std::string upper(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

fs::path library_root() { return rung::test::source_dir() / "library"; }

std::string library_relative(const fs::path& path) { return fs::relative(path, library_root()).generic_string(); }

// One parameter as declared: its name, type text and the attribute pragmas written before it.
struct Param {
  std::string name;
  std::string type;
  std::vector<std::string> attributes;  // the pragma text, e.g. "attribute 'rung.extensible'"
};

struct Declaration {
  std::string name;
  std::string kind;  // "FUNCTION", "FUNCTION_BLOCK", "TYPE"
  std::string file;
  std::string return_type;
  std::vector<Param> inputs, outputs, in_outs;
};

// The attribute pragmas directly before a declaration inside its VAR block.
std::vector<std::string> attributes_before(SyntaxNode decl) {
  std::vector<std::string> out;
  for (SyntaxNode prev = decl.prev_sibling(); prev && prev.kind() == "pragma"; prev = prev.prev_sibling()) {
    out.insert(out.begin(), std::string(prev.text()));
  }
  return out;
}

// The node that sits at file level for a declaration (a TYPE's outline node is its inner type).
SyntaxNode top_level(SyntaxNode node) {
  while (node.parent() && node.parent().kind() != "source_file") node = node.parent();
  return node;
}

// The comment lines directly above a top-level node: pragmas between them are skipped, and a blank
// line ends the block (so a file's introduction does not count for its first declaration).
std::string doc_comment(SyntaxNode node) {
  std::string doc;
  SyntaxNode cur = node;
  for (SyntaxNode prev = node.prev_sibling(); prev; prev = prev.prev_sibling()) {
    std::string_view gap = cur.source().substr(prev.end(), cur.begin() - prev.end());
    if (std::count(gap.begin(), gap.end(), '\n') > 1) break;
    if (prev.kind() == "comment") {
      doc.insert(0, std::string(prev.text()) + "\n");
    } else if (prev.kind() != "pragma") {
      break;
    }
    cur = prev;
  }
  return doc;
}

struct Library {
  std::vector<fs::path> files;
  std::vector<std::string> parse_problems;  // "file: message"
  std::vector<Declaration> declarations;
  std::vector<std::string> undocumented;  // declarations without a `source:` doc comment
};

const Library& library() {
  static const Library loaded = [] {
    Library lib;
    WalkResult walk = collect_source_files({library_root()});
    lib.files = walk.files;
    for (const std::string& error : walk.errors) lib.parse_problems.push_back(error);
    for (const fs::path& path : walk.files) {
      std::string error;
      std::optional<Document> doc = Document::load(path, &error);
      std::string file = library_relative(path);
      if (!doc) {
        lib.parse_problems.push_back(fmt::format("{}: {}", file, error));
        continue;
      }
      for (const Diagnostic& d : doc->diagnostics()) {
        FilePosition at = doc->position_of_file_offset(d.range.begin);
        lib.parse_problems.push_back(file + ":" + std::to_string(at.line) + ": " + d.message);
      }
      if (!doc->tree()) continue;
      ast::Outline outline = ast::outline(doc->tree()->root());
      auto check_doc = [&](SyntaxNode node, const std::string& name) {
        std::string comment = doc_comment(top_level(node));
        if (comment.find("source:") == std::string::npos) lib.undocumented.push_back(fmt::format("{}: {}", file, name));
      };
      for (const ast::Pou& pou : outline.pous) {
        Declaration d;
        d.name = std::string(pou.name());
        d.file = file;
        d.kind = pou.kind() == ast::PouKind::Function        ? "FUNCTION"
                 : pou.kind() == ast::PouKind::FunctionBlock ? "FUNCTION_BLOCK"
                                                             : std::string(ast::pou_kind_name(pou.kind()));
        if (pou.return_type()) d.return_type = std::string(pou.return_type().text());
        for (const ast::VarBlock& block : pou.var_blocks()) {
          std::vector<Param>* target = block.section() == ast::VarSection::Input    ? &d.inputs
                                       : block.section() == ast::VarSection::Output ? &d.outputs
                                       : block.section() == ast::VarSection::InOut  ? &d.in_outs
                                                                                    : nullptr;
          if (!target) continue;
          for (const ast::VarDeclaration& decl : block.declarations()) {
            for (SyntaxNode name : decl.names()) {
              target->push_back({std::string(name.text()), std::string(decl.type().text()),
                                 attributes_before(decl.node())});
            }
          }
        }
        check_doc(pou.node(), d.name);
        lib.declarations.push_back(std::move(d));
      }
      for (const ast::TypeDeclaration& type : outline.types) {
        Declaration d;
        d.name = std::string(type.name());
        d.kind = "TYPE";
        d.file = file;
        check_doc(type.node(), d.name);
        lib.declarations.push_back(std::move(d));
      }
    }
    return lib;
  }();
  return loaded;
}

const Declaration* find(std::string_view name) {
  for (const Declaration& d : library().declarations) {
    if (upper(d.name) == upper(name)) return &d;
  }
  return nullptr;
}

std::string render(const std::vector<Param>& params) {
  std::string out;
  for (const Param& p : params) {
    if (!out.empty()) out += "; ";
    out += p.name + " : " + p.type;
  }
  return out;
}

bool has_attribute(const Param& param, std::string_view needle) {
  return std::any_of(param.attributes.begin(), param.attributes.end(),
                     [&](const std::string& a) { return a.find(needle) != std::string::npos; });
}

TEST(Library, FilesExist) {
  EXPECT_GE(library().files.size(), 40u) << "library/ is missing or nearly empty";
  EXPECT_GE(library().declarations.size(), 600u);
}

// (a) Every file parses with zero diagnostics.
TEST(Library, EveryFileParsesCleanly) {
  std::string all;
  for (const std::string& problem : library().parse_problems) all += problem + "\n";
  EXPECT_TRUE(library().parse_problems.empty()) << all;
}

// (b) The interfaces of key blocks, as the seed manuals give them ("; "-separated "name : type").
struct Expected {
  const char* name;
  const char* kind;
  const char* return_type;  // functions only
  const char* inputs;
  const char* outputs;
  const char* in_outs = "";
};

const Expected kExpected[] = {
    // IEC / CODESYS Standard function blocks (000b.md, 002.md ch.4, 003.md §24)
    {"TON", "FUNCTION_BLOCK", "", "IN : BOOL; PT : TIME", "Q : BOOL; ET : TIME"},
    {"TOF", "FUNCTION_BLOCK", "", "IN : BOOL; PT : TIME", "Q : BOOL; ET : TIME"},
    {"TP", "FUNCTION_BLOCK", "", "IN : BOOL; PT : TIME", "Q : BOOL; ET : TIME"},
    {"RTC", "FUNCTION_BLOCK", "", "EN : BOOL; PDT : DT", "Q : BOOL; CDT : DT"},
    {"CTU", "FUNCTION_BLOCK", "", "CU : BOOL; RESET : BOOL; PV : INT", "Q : BOOL; CV : INT"},
    {"CTD", "FUNCTION_BLOCK", "", "CD : BOOL; LOAD : BOOL; PV : INT", "Q : BOOL; CV : INT"},
    {"CTUD", "FUNCTION_BLOCK", "", "CU : BOOL; CD : BOOL; RESET : BOOL; LOAD : BOOL; PV : INT",
     "QU : BOOL; QD : BOOL; CV : INT"},
    {"R_TRIG", "FUNCTION_BLOCK", "", "CLK : BOOL", "Q : BOOL"},
    {"F_TRIG", "FUNCTION_BLOCK", "", "CLK : BOOL", "Q : BOOL"},
    {"SR", "FUNCTION_BLOCK", "", "SET1 : BOOL; RESET : BOOL", "Q1 : BOOL"},
    {"RS", "FUNCTION_BLOCK", "", "SET : BOOL; RESET1 : BOOL", "Q1 : BOOL"},
    {"SEMA", "FUNCTION_BLOCK", "", "CLAIM : BOOL; RELEASE : BOOL", "BUSY : BOOL"},
    // IEC functions
    {"LIMIT", "FUNCTION", "T", "MN : T; IN : T; MX : T", ""},
    {"SEL", "FUNCTION", "T", "G : BOOL; IN0 : T; IN1 : T", ""},
    {"MUX", "FUNCTION", "T", "K : I; IN0 : T; IN1 : T", ""},
    {"MAX", "FUNCTION", "T", "IN1 : T; IN2 : T", ""},
    {"ADD", "FUNCTION", "T", "IN1 : T; IN2 : T", ""},
    {"SUB", "FUNCTION", "T", "IN1 : T; IN2 : T", ""},
    {"SHL", "FUNCTION", "T", "IN : T; N : I", ""},
    {"EXPT", "FUNCTION", "T", "IN1 : T; IN2 : N", ""},
    {"SQRT", "FUNCTION", "T", "IN : T", ""},
    {"GT", "FUNCTION", "BOOL", "IN1 : T; IN2 : T", ""},
    {"NE", "FUNCTION", "BOOL", "IN1 : T; IN2 : T", ""},
    {"CONCAT", "FUNCTION", "T", "IN1 : T; IN2 : T", ""},
    {"LEN", "FUNCTION", "INT", "IN : T", ""},
    {"LEFT", "FUNCTION", "T", "IN : T; L : I", ""},
    {"MID", "FUNCTION", "T", "IN : T; L : I; P : I", ""},
    {"INSERT", "FUNCTION", "T", "IN1 : T; IN2 : T; P : I", ""},
    {"DELETE", "FUNCTION", "T", "IN1 : T; L : I; P : I", ""},
    {"REPLACE", "FUNCTION", "T", "IN1 : T; IN2 : T; L : I; P : I", ""},
    {"FIND", "FUNCTION", "INT", "IN1 : T; IN2 : T", ""},
    {"REAL_TO_INT", "FUNCTION", "INT", "IN : REAL", ""},
    {"DT_TO_TOD", "FUNCTION", "TOD", "IN : DT", ""},
    {"TRUNC", "FUNCTION", "DINT", "IN : T", ""},
    {"TRUNC_INT", "FUNCTION", "INT", "IN : T", ""},
    {"SUB_TOD_TOD", "FUNCTION", "TIME", "IN1 : TOD; IN2 : TOD", ""},
    {"MUL_TIME", "FUNCTION", "TIME", "IN1 : TIME; IN2 : N", ""},
    // CODESYS Standard64
    {"LTON", "FUNCTION_BLOCK", "", "IN : BOOL; PT : LTIME", "Q : BOOL; ET : LTIME"},
    // CODESYS Util (002.md §4.3)
    {"BCD_TO_INT", "FUNCTION", "INT", "B : BYTE", ""},
    {"INT_TO_BCD", "FUNCTION", "BYTE", "I : INT", ""},
    {"EXTRACT", "FUNCTION", "BOOL", "X : DWORD; N : BYTE", ""},
    {"PUTBIT", "FUNCTION", "DWORD", "X : DWORD; N : BYTE; B : BOOL", ""},
    {"PACK", "FUNCTION", "BYTE",
     "B0 : BOOL; B1 : BOOL; B2 : BOOL; B3 : BOOL; B4 : BOOL; B5 : BOOL; B6 : BOOL; B7 : BOOL", ""},
    {"UNPACK", "FUNCTION_BLOCK", "", "B : BYTE",
     "B0 : BOOL; B1 : BOOL; B2 : BOOL; B3 : BOOL; B4 : BOOL; B5 : BOOL; B6 : BOOL; B7 : BOOL"},
    {"DERIVATIVE", "FUNCTION_BLOCK", "", "IN : REAL; TM : DWORD; RESET : BOOL", "OUT : REAL"},
    {"INTEGRAL", "FUNCTION_BLOCK", "", "IN : REAL; TM : DWORD; RESET : BOOL", "OUT : REAL"},
    {"LIN_TRAFO", "FUNCTION_BLOCK", "", "IN : REAL; IN_MIN : REAL; IN_MAX : REAL; OUT_MIN : REAL; OUT_MAX : REAL",
     "OUT : REAL; ERROR : BOOL"},
    {"STATISTICS_INT", "FUNCTION_BLOCK", "", "IN : INT; RESET : BOOL", "MN : INT; MX : INT; AVG : INT"},
    {"VARIANCE", "FUNCTION_BLOCK", "", "IN : REAL; RESET : BOOL", "OUT : REAL"},
    {"PD", "FUNCTION_BLOCK", "",
     "ACTUAL : REAL; SET_POINT : REAL; KP : REAL; TV : REAL; Y_MANUAL : REAL; Y_OFFSET : REAL; Y_MIN : REAL; "
     "Y_MAX : REAL; MANUAL : BOOL; RESET : BOOL",
     "Y : REAL; LIMITS_ACTIVE : BOOL"},
    {"PID", "FUNCTION_BLOCK", "",
     "ACTUAL : REAL; SET_POINT : REAL; KP : REAL; TN : REAL; TV : REAL; Y_MANUAL : REAL; Y_OFFSET : REAL; "
     "Y_MIN : REAL; Y_MAX : REAL; MANUAL : BOOL; RESET : BOOL",
     "Y : REAL; LIMITS_ACTIVE : BOOL; OVERFLOW : BOOL"},
    {"PID_FIXCYCLE", "FUNCTION_BLOCK", "",
     "ACTUAL : REAL; SET_POINT : REAL; KP : REAL; TN : REAL; TV : REAL; Y_MANUAL : REAL; Y_OFFSET : REAL; "
     "Y_MIN : REAL; Y_MAX : REAL; MANUAL : BOOL; RESET : BOOL; CYCLE : REAL",
     "Y : REAL; LIMITS_ACTIVE : BOOL; OVERFLOW : BOOL"},
    {"BLINK", "FUNCTION_BLOCK", "", "ENABLE : BOOL; TIMELOW : TIME; TIMEHIGH : TIME", "OUT : BOOL"},
    {"FREQ_MEASURE", "FUNCTION_BLOCK", "", "IN : BOOL; PERIODS : INT; RESET : BOOL", "OUT : REAL; VALID : BOOL"},
    {"GEN", "FUNCTION_BLOCK", "",
     "MODE : GEN_MODE; BASE : BOOL; PERIOD : TIME; CYCLES : INT; AMPLITUDE : INT; RESET : BOOL", "OUT : INT"},
    {"CHARCURVE", "FUNCTION_BLOCK", "", "IN : INT; N : BYTE; P : ARRAY[0..10] OF POINT", "OUT : INT; ERR : BYTE"},
    {"RAMP_INT", "FUNCTION_BLOCK", "", "IN : INT; ASCEND : INT; DESCEND : INT; TIMEBASE : TIME; RESET : BOOL",
     "OUT : INT"},
    {"RAMP_REAL", "FUNCTION_BLOCK", "", "IN : REAL; ASCEND : REAL; DESCEND : REAL; TIMEBASE : TIME; RESET : BOOL",
     "OUT : REAL"},
    {"HYSTERESIS", "FUNCTION_BLOCK", "", "IN : INT; HIGH : INT; LOW : INT", "OUT : BOOL"},
    {"LIMITALARM", "FUNCTION_BLOCK", "", "IN : INT; HIGH : INT; LOW : INT", "O : BOOL; U : BOOL; IL : BOOL"},
    // OpenPCS firmware blocks (003.md §24)
    {"GetTime", "FUNCTION", "TIME", "IN1 : TIME", ""},
    {"ETRC", "FUNCTION_BLOCK", "", "IN : BOOL", "Q : BOOL; EVC : USINT; ERT : TIME; CCV : UDINT; ERROR : USINT"},
    {"GetTaskInfo", "FUNCTION_BLOCK", "", "",
     "Count : DWORD; LastCT : TIME; AverageCT : TIME; MinCT : TIME; MaxCT : TIME; State : DWORD"},
    {"GetDateStruct", "FUNCTION_BLOCK", "", "IN : DATE", "", "DATESTRUCT_INOUT : DateStruct"},
};

TEST(Library, KeyInterfacesMatchTheManuals) {
  for (const Expected& e : kExpected) {
    SCOPED_TRACE(e.name);
    const Declaration* d = find(e.name);
    ASSERT_NE(d, nullptr) << e.name << " is not declared";
    EXPECT_EQ(d->kind, e.kind);
    if (std::string_view(e.kind) == "FUNCTION") {
      EXPECT_EQ(d->return_type, e.return_type);
    }
    EXPECT_EQ(render(d->inputs), e.inputs);
    EXPECT_EQ(render(d->outputs), e.outputs);
    EXPECT_EQ(render(d->in_outs), e.in_outs);
  }
}

// The extensible inputs carry the pragma on the input that repeats.
TEST(Library, ExtensibleInputsAreMarked) {
  const std::map<std::string, std::string> extensible = {
      {"ADD", "IN2"}, {"MUL", "IN2"}, {"AND", "IN2"}, {"OR", "IN2"},  {"XOR", "IN2"},    {"MAX", "IN2"},
      {"MIN", "IN2"}, {"MUX", "IN1"}, {"GT", "IN2"},  {"GE", "IN2"},  {"EQ", "IN2"},     {"LE", "IN2"},
      {"LT", "IN2"},  {"CONCAT", "IN2"}};
  for (const auto& [name, input] : extensible) {
    SCOPED_TRACE(name);
    const Declaration* d = find(name);
    ASSERT_NE(d, nullptr);
    ASSERT_FALSE(d->inputs.empty());
    EXPECT_EQ(d->inputs.back().name, input);
    EXPECT_TRUE(has_attribute(d->inputs.back(), "'rung.extensible'"));
  }
  // Fixed-arity functions are not extensible.
  for (const char* name : {"SUB", "DIV", "MOD", "NE", "SEL", "LIMIT", "TON", "CTU"}) {
    const Declaration* d = find(name);
    ASSERT_NE(d, nullptr) << name;
    for (const Param& p : d->inputs) EXPECT_FALSE(has_attribute(p, "rung.extensible")) << name << "." << p.name;
  }
}

// Where CODESYS differs from IEC, the difference is written down as a pragma.
TEST(Library, CodesysDifferencesAreRecorded) {
  const Declaration* ctu = find("CTU");
  ASSERT_NE(ctu, nullptr);
  EXPECT_TRUE(has_attribute(ctu->inputs[1], "'rung.alias' := 'R'"));
  EXPECT_TRUE(has_attribute(ctu->inputs[2], "'rung.codesys_type' := 'WORD'"));
  EXPECT_TRUE(has_attribute(ctu->outputs[1], "'rung.codesys_type' := 'WORD'"));
  const Declaration* left = find("LEFT");
  ASSERT_NE(left, nullptr);
  EXPECT_TRUE(has_attribute(left->inputs[0], "'rung.alias' := 'STR'"));
  EXPECT_TRUE(has_attribute(left->inputs[1], "'rung.alias' := 'SIZE'"));
}

// The conversion matrix is complete: <A>_TO_<B> for every ordered pair of elementary types.
TEST(Library, ConversionMatrixIsComplete) {
  const char* types[] = {"BOOL", "BYTE", "WORD",  "DWORD", "LWORD", "SINT", "USINT", "INT",
                         "UINT", "DINT", "UDINT", "LINT",  "ULINT", "REAL", "LREAL", "TIME",
                         "LTIME", "DATE", "TOD",  "DT",    "STRING", "WSTRING"};
  for (const char* from : types) {
    for (const char* to : types) {
      if (std::string_view(from) == to) continue;
      std::string name = std::string(from) + "_TO_" + to;
      const Declaration* d = find(name);
      ASSERT_NE(d, nullptr) << name;
      EXPECT_EQ(d->return_type, to) << name;
      EXPECT_EQ(render(d->inputs), std::string("IN : ") + from) << name;
    }
    EXPECT_NE(find(std::string("TO_") + from), nullptr) << "TO_" << from;
  }
}

// (c) No name is declared twice across the libraries (names are case-insensitive).
TEST(Library, NoNameIsDeclaredTwice) {
  std::map<std::string, std::string> seen;  // upper-case name -> file
  std::string duplicates;
  for (const Declaration& d : library().declarations) {
    auto [it, inserted] = seen.emplace(upper(d.name), d.file);
    if (!inserted) duplicates += d.name + " in " + d.file + " and " + it->second + "\n";
  }
  EXPECT_TRUE(duplicates.empty()) << duplicates;
}

// (d) Every declaration has a doc comment directly above it with a `source:` reference.
TEST(Library, EveryDeclarationIsDocumented) {
  std::string all;
  for (const std::string& u : library().undocumented) all += u + "\n";
  EXPECT_TRUE(library().undocumented.empty()) << all;
}

// A block's own state (plain VAR) is an implementation detail: every such variable of a library
// FUNCTION_BLOCK is marked {attribute 'hide'}, so reports, hovers and watch lists show only its
// interface. (Blocks that ST expresses have bodies; the others stay declarations, see
// docs/library.md.)
TEST(Library, BlockStateIsHidden) {
  for (const fs::path& path : library().files) {
    std::string error;
    std::optional<Document> doc = Document::load(path, &error);
    ASSERT_TRUE(doc && doc->tree()) << path;
    for (const ast::Pou& pou : ast::outline(doc->tree()->root()).pous) {
      if (pou.kind() != ast::PouKind::FunctionBlock) continue;
      for (const ast::VarBlock& block : pou.var_blocks()) {
        if (block.section() != ast::VarSection::Var) continue;
        for (const ast::VarDeclaration& decl : block.declarations()) {
          const std::vector<std::string> attributes = attributes_before(decl.node());
          const bool hidden = std::any_of(attributes.begin(), attributes.end(),
                                          [](const std::string& a) { return a.find("'hide'") != std::string::npos; });
          EXPECT_TRUE(hidden) << library_relative(path) << ": " << pou.name() << " shows its state variable "
                              << (decl.names().empty() ? std::string() : std::string(decl.names().front().text()));
        }
      }
    }
  }
}

}  // namespace
}  // namespace rung
