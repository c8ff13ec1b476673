#include "parser/document.hpp"

#include <gtest/gtest.h>

#include <string>

#include "tests/support/test_paths.hpp"

namespace rung {
namespace {

bool has_code(const Document& doc, std::string_view code) {
  for (const auto& d : doc.diagnostics())
    if (d.code == code) return true;
  return false;
}

TEST(Document, PlainFileParsesClean) {
  Document doc = Document::from_bytes("a.st", "PROGRAM P\nVAR x : INT; END_VAR\nx := 1;\nEND_PROGRAM\n");
  ASSERT_NE(doc.tree(), nullptr);
  EXPECT_TRUE(doc.diagnostics().empty());
  EXPECT_EQ(doc.file_offset_of(5), 5u);
}

TEST(Document, Utf8BomIsDroppedAndPositionsCountCharacters) {
  Document doc = Document::from_bytes("a.st", "\xEF\xBB\xBFPROGRAM P\n(* \xC3\xA4\xC3\xB6 *) x := ;\nEND_PROGRAM\n");
  EXPECT_TRUE(doc.had_bom());
  ASSERT_FALSE(doc.diagnostics().empty());
  FilePosition p = doc.position_of_file_offset(doc.diagnostics()[0].range.begin);
  EXPECT_EQ(p.line, 2u);
  // "(* äö *) x := ;" — the missing expression is reported right after ':=' (column 14 counting
  // characters; it would be 16 counting bytes).
  EXPECT_EQ(p.column, 14u);
}

TEST(Document, Cp1252FileIsDecoded) {
  // OSCAT-style comment with a cp1252 'ä' (0xE4) and '€' (0x80).
  Document doc = Document::from_bytes("a.st", "(* Z\xE4hler \x80 *)\nPROGRAM P\nEND_PROGRAM\n");
  EXPECT_EQ(doc.encoding(), source::Encoding::Cp1252);
  EXPECT_NE(doc.file_text().find("Z\xC3\xA4hler \xE2\x82\xAC"), std::string_view::npos);
  EXPECT_FALSE(has_code(doc, "S001"));
}

TEST(Document, BinaryFileIsReportedNotParsed) {
  static const char kPng[] = "\x89PNG\r\n\x1a\n\0\0\0\rIHDR\0\0\0\x10\0\0\0\x10\x08\x06";
  std::string png(kPng, sizeof(kPng) - 1);
  Document doc = Document::from_bytes("image.st", png);
  EXPECT_EQ(doc.tree(), nullptr);
  ASSERT_EQ(doc.diagnostics().size(), 1u);
  EXPECT_EQ(doc.diagnostics()[0].code, "S009");
}

TEST(Document, TooLargeFileIsRefusedWithAClearMessage) {
  DocumentOptions options;
  options.max_bytes = 1000;
  Document doc = Document::from_bytes("big.st", std::string(2000, ' '), options);
  EXPECT_EQ(doc.tree(), nullptr);
  ASSERT_EQ(doc.diagnostics().size(), 1u);
  EXPECT_EQ(doc.diagnostics()[0].code, "S011");
}

TEST(Document, TwinCatDiagnosticsPointAtTheContainerLines) {
  std::string xml =
      "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n"
      "<TcPlcObject Version=\"1.1.0.1\">\n"
      "  <POU Name=\"FB_A\" Id=\"{1}\">\n"
      "    <Declaration><![CDATA[FUNCTION_BLOCK FB_A\n"
      "VAR\n"
      "  x : INT;\n"
      "END_VAR\n"
      "]]></Declaration>\n"
      "    <Implementation>\n"
      "      <ST><![CDATA[x := x + 1;\n"
      "x := ;]]></ST>\n"
      "    </Implementation>\n"
      "  </POU>\n"
      "</TcPlcObject>\n";
  Document doc = Document::from_bytes("FB_A.TcPOU", xml);
  ASSERT_NE(doc.container(), nullptr);
  ASSERT_NE(doc.tree(), nullptr);
  ASSERT_FALSE(doc.diagnostics().empty());
  FilePosition p = doc.position_of_file_offset(doc.diagnostics()[0].range.begin);
  EXPECT_EQ(p.line, 11u);   // "x := ;]]></ST>" is line 11 of the .TcPOU file
  EXPECT_EQ(p.column, 5u);  // right after ':=', where the expression is missing
  // And back: the file offset of "x := ;" maps to the same text in the parsed tree.
  uint32_t file_offset = static_cast<uint32_t>(xml.find("x := ;"));
  auto tree_offset = doc.tree_offset_of(file_offset);
  ASSERT_TRUE(tree_offset.has_value());
  EXPECT_EQ(doc.tree()->text().substr(*tree_offset, 6), "x := ;");
  EXPECT_FALSE(doc.tree_offset_of(static_cast<uint32_t>(xml.find("<Implementation>"))).has_value());
}

TEST(Document, ExampleProjectParsesClean) {
  for (const auto& entry : std::filesystem::recursive_directory_iterator(test::source_dir() / "examples/conveyor")) {
    if (!entry.is_regular_file() || entry.path().extension() == ".md") continue;
    std::string error;
    auto doc = Document::load(entry.path(), &error);
    ASSERT_TRUE(doc) << error;
    EXPECT_TRUE(doc->diagnostics().empty()) << entry.path() << ": " << doc->diagnostics()[0].message;
  }
}

}  // namespace
}  // namespace rung

namespace rung {
namespace {

TEST(Document, ExpWithNestedCommentsOffParsesLikeCodesys) {
  // OSCAT-style object exported with nested comments off: "(* (* x *)" is ONE comment.
  std::string exp =
      "(* @NESTEDCOMMENTS := 'No' *)\r\n"
      "(* @PATH := '\\/lib' *)\r\n"
      "FUNCTION F_Add : INT\r\n"
      "VAR_INPUT a, b : INT; END_VAR\r\n"
      "(* @END_DECLARATION := '0' *)\r\n"
      "(* old code: (* F_Add := a - b; *)\r\n"
      "F_Add := a + b;\r\n"
      "END_FUNCTION\r\n";
  Document doc = Document::from_bytes("LIB.EXP", exp);
  ASSERT_NE(doc.container(), nullptr);
  EXPECT_TRUE(doc.diagnostics().empty()) << doc.diagnostics()[0].message;
  // The file text itself is untouched: only the parser's copy was adjusted.
  EXPECT_NE(doc.file_text().find("(* old code: (* F_Add"), std::string_view::npos);
}

}  // namespace
}  // namespace rung

namespace rung {
namespace {

TEST(Document, PlainFileWithFlatCommentsIsReadLikeMatiec) {
  // Beremiz/MATIEC do not nest comments: the first '*)' closes the comment.
  std::string text =
      "(* a commented-out call: (* old code **\n"
      "   foo(1);\n"
      "*)\n"
      "PROGRAM p\nVAR x : INT; END_VAR\nx := 1;\nEND_PROGRAM\n";
  Document doc = Document::from_bytes("plc.st", text);
  ASSERT_NE(doc.tree(), nullptr);
  EXPECT_TRUE(doc.diagnostics().empty()) << doc.diagnostics()[0].message;
  EXPECT_EQ(doc.tree()->root().named_child(1).kind(), "program_declaration");
  // A comment that stays open either way is still reported.
  Document broken = Document::from_bytes("b.st", "(* never closed\nPROGRAM p\nEND_PROGRAM\n");
  ASSERT_FALSE(broken.diagnostics().empty());
  EXPECT_EQ(broken.diagnostics()[0].code, "S005");
}

}  // namespace
}  // namespace rung

namespace rung {
namespace {

TEST(Document, UnknownXmlIsReportedOnceNotParsedAsSt) {
  Document doc = Document::from_bytes(
      "pom.xml",
      "<?xml version=\"1.0\"?>\n<!-- build -->\n<project xmlns=\"http://maven.apache.org/POM/4.0.0\">\n</project>\n");
  EXPECT_EQ(doc.tree(), nullptr);
  ASSERT_EQ(doc.diagnostics().size(), 1u);
  EXPECT_EQ(doc.diagnostics()[0].code, "S010");
  EXPECT_NE(doc.diagnostics()[0].message.find("<project>"), std::string::npos);
}

}  // namespace
}  // namespace rung

namespace rung {
namespace {

TEST(Document, ConditionalBranchesThatSplitAStatementParse) {
  std::string text =
      "PROGRAM P\nVAR a, b : BOOL; x : INT; END_VAR\n"
      "{IF defined (DEBUG)}\nIF a THEN\n{ELSE}\nIF b THEN\n{END_IF}\n    x := 1;\nEND_IF\nEND_PROGRAM\n";
  Document doc = Document::from_bytes("p.st", text);
  ASSERT_NE(doc.tree(), nullptr);
  EXPECT_TRUE(doc.diagnostics().empty()) << doc.diagnostics()[0].message;
  // Only the parser's copy changed: the file text still has both branches.
  EXPECT_NE(doc.file_text().find("IF b THEN"), std::string_view::npos);
  EXPECT_EQ(doc.tree()->text().find("IF b THEN"), std::string::npos);
}

TEST(Document, ConditionalBranchesAreLeftAloneWhenTheFileParses) {
  std::string text =
      "PROGRAM P\nVAR x : INT; END_VAR\n{IF defined (A)}\nx := 1;\n{ELSIF defined (B)}\nx := 2;\n{ELSE}\nx := 3;\n"
      "{END_IF}\nEND_PROGRAM\n";
  Document doc = Document::from_bytes("p.st", text);
  EXPECT_TRUE(doc.diagnostics().empty());
  EXPECT_EQ(doc.tree()->text(), text);
}

}  // namespace
}  // namespace rung
