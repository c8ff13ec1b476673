// Range formatting of a whole file of any kind (the language server's range and on-type
// formatting): only lines touching the range change, in plain files and inside containers.
#include "formatter/file_range_format.hpp"

#include <gtest/gtest.h>

namespace rung::format {
namespace {

using containers::ContainerKind;

project::FormatSettings spaces() {
  project::FormatSettings settings;
  settings.use_tabs = false;
  settings.indent_width = 2;
  return settings;
}

TextRange line_range(std::string_view text, std::string_view line) {
  const uint32_t at = static_cast<uint32_t>(text.find(line));
  return {at, at + static_cast<uint32_t>(line.size())};
}

const std::string kPlain =
    "PROGRAM P\n"
    "VAR x : INT; END_VAR\n"
    "x:=x+1;\n"
    "if x>1 then\n"
    "x:=0;\n"
    "end_if\n"
    "END_PROGRAM\n";

TEST(FileRangeFormat, PlainFileTakesOnlyTheRangesLines) {
  const FileFormatResult r = format_file_range(ContainerKind::None, kPlain, line_range(kPlain, "x:=0;"), spaces());
  ASSERT_EQ(r.result.status, Status::Formatted);
  EXPECT_EQ(r.result.text,
            "PROGRAM P\n"
            "VAR x : INT; END_VAR\n"
            "x:=x+1;\n"
            "if x>1 then\n"
            "  x := 0;\n"
            "end_if\n"
            "END_PROGRAM\n");
}

TEST(FileRangeFormat, SyntaxErrorsLeaveTheFile) {
  const std::string broken = "PROGRAM P\nx:=x+;\nEND_PROGRAM\n";
  const FileFormatResult r = format_file_range(ContainerKind::None, broken, line_range(broken, "x:=x+;"), spaces());
  EXPECT_EQ(r.result.status, Status::SyntaxErrors);
  EXPECT_EQ(r.result.text, broken);
}

std::string crlf(std::string_view text) {
  std::string out;
  for (char c : text) {
    if (c == '\n') out += '\r';
    out += c;
  }
  return out;
}

std::string tc_pou(std::string_view body) {
  return crlf(
      "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n"
      "<TcPlcObject Version=\"1.1.0.1\" ProductVersion=\"3.1.4024.12\">\n"
      "  <POU Name=\"P\" Id=\"{5b1c0e52-0000-4000-8000-000000000002}\" SpecialFunc=\"None\">\n"
      "    <Declaration><![CDATA[PROGRAM P\nVAR\n\tx : INT;\nEND_VAR\n]]></Declaration>\n"
      "    <Implementation>\n"
      "      <ST><![CDATA[" +
      std::string(body) +
      "]]></ST>\n"
      "    </Implementation>\n"
      "  </POU>\n"
      "</TcPlcObject>\n");
}

TEST(FileRangeFormat, ContainerPiecesKeepTheirMarkup) {
  const std::string file = tc_pou("x:=x+1;\nx:=2;");
  const FileFormatResult r =
      format_file_range(ContainerKind::TwinCat, file, line_range(file, "x:=2;"), project::FormatSettings{});
  ASSERT_EQ(r.result.status, Status::Formatted) << r.result.message;
  EXPECT_EQ(r.result.text, tc_pou("x:=x+1;\nx := 2;"));
}

TEST(FileRangeFormat, PieceFormatterAddsTheProjectsCommentRule) {
  project::FormatSettings settings;
  // One comment when comments nest; when they do not (OpenPCS), the first *) ends it and the
  // rest is a syntax error.
  const std::string text = "PROGRAM P\n(* a (* b *) x := 1; *)\nEND_PROGRAM\n";
  EXPECT_EQ(piece_formatter(settings)(text, {}).status, Status::Formatted);
  EXPECT_EQ(piece_formatter(settings, {.flat_comments = true})(text, {}).status, Status::SyntaxErrors);
  EXPECT_EQ(piece_formatter(settings)(text, {.flat_comments = true}).status, Status::SyntaxErrors);
}

}  // namespace
}  // namespace rung::format
