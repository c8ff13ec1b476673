#include "parser/containers/exp_reader.hpp"

#include <gtest/gtest.h>

#include "container_test_support.hpp"
#include "parser/source/line_index.hpp"

namespace rung::containers {
namespace {

using testing::decoded_data;
using testing::file_position_of;
using testing::LineColumn;

bool is_blank(std::string_view text) {
  return text.find_first_not_of(" \r\n") == std::string_view::npos;
}

// The virtual text of file line `line` (1-based).
std::string_view virtual_line(const ContainerDocument& doc, uint32_t line) {
  const source::LineIndex index(doc.virtual_text);
  return index.line_text(doc.virtual_text, line - 1);
}

TEST(ExpReader, KeepsLengthAndMapsOneToOne) {
  const std::string file = decoded_data("Project.EXP");
  const ContainerDocument doc = read_exp(file);
  EXPECT_EQ(doc.kind, ContainerKind::CodesysExp);
  EXPECT_TRUE(doc.issues.empty());
  EXPECT_EQ(doc.virtual_text.size(), file.size());
  ASSERT_EQ(doc.segments.size(), 1u);
  EXPECT_EQ(doc.segments[0].file_begin, 0u);
  EXPECT_EQ(doc.to_file_offset(1234), 1234u);
  EXPECT_EQ(doc.to_virtual_offset(1234), 1234u);
  // Line ends survive blanking, so every line keeps its number.
  EXPECT_EQ(source::LineIndex(doc.virtual_text).line_count(), source::LineIndex(file).line_count());
}

TEST(ExpReader, Cp1252CommentsAreDecodedBeforeReading) {
  const std::string file = decoded_data("Project.EXP");
  const ContainerDocument doc = read_exp(file);
  EXPECT_EQ(file_position_of(doc, file, "(* Z\xC3\xA4hler erh\xC3\xB6hen, Kosten in \xE2\x82\xAC *)"),
            (LineColumn{17, 17}));
  EXPECT_EQ(file_position_of(doc, file, "nCnt := nCnt + 1"), (LineColumn{25, 5}));
}

TEST(ExpReader, CodeAndMarkersStay) {
  const std::string file = decoded_data("Project.EXP");
  const ContainerDocument doc = read_exp(file);
  EXPECT_EQ(virtual_line(doc, 1), "(* @NESTEDCOMMENTS := 'Yes' *)");
  EXPECT_EQ(virtual_line(doc, 15), "FUNCTION_BLOCK FB_COUNT");
  EXPECT_EQ(virtual_line(doc, 22), "(* @END_DECLARATION := '0' *)");
  EXPECT_EQ(virtual_line(doc, 28), "ACTION RESET:");
  EXPECT_EQ(virtual_line(doc, 46), "FILENAME : ''");  // inside the @CONNECTIONS comment
  EXPECT_EQ(virtual_line(doc, 102), "END_FUNCTION");
}

TEST(ExpReader, GraphicalBodyIsBlankedButTheEndKeywordStays) {
  const std::string file = decoded_data("Project.EXP");
  const ContainerDocument doc = read_exp(file);
  EXPECT_EQ(virtual_line(doc, 56), "PROGRAM PLC_PRG");
  EXPECT_EQ(virtual_line(doc, 60), "(* @END_DECLARATION := '0' *)");
  for (uint32_t line = 61; line <= 78; ++line) EXPECT_TRUE(is_blank(virtual_line(doc, line))) << line;
  EXPECT_EQ(virtual_line(doc, 61), std::string(9, ' '));  // "_FBD_BODY" became 9 spaces
  EXPECT_EQ(virtual_line(doc, 65), std::string(9, ' '));  // "'Zählen'": 9 bytes in UTF-8
  EXPECT_EQ(virtual_line(doc, 79), "END_PROGRAM");
}

TEST(ExpReader, VisualisationAndLibraryAreBlanked) {
  const std::string file = decoded_data("Project.EXP");
  const ContainerDocument doc = read_exp(file);
  EXPECT_EQ(virtual_line(doc, 83), "(* @OBJECTFLAGS := '0, 8' *)");  // the header stays
  for (uint32_t line = 84; line <= 89; ++line) EXPECT_TRUE(is_blank(virtual_line(doc, line))) << line;
  // The "END_PROGRAM" inside the visualisation text did not end anything.
  EXPECT_EQ(virtual_line(doc, 95), "FUNCTION F_LD : BOOL");
  for (uint32_t line = 104; line <= 111; ++line) EXPECT_TRUE(is_blank(virtual_line(doc, line))) << line;
  EXPECT_EQ(virtual_line(doc, 111), std::string(11, ' '));  // "END_LIBRARY"
  EXPECT_EQ(virtual_line(doc, 112), "");
}

TEST(ExpReader, ObjectsWithKindPathAndNestedCommentsFlag) {
  const std::string file = decoded_data("Project.EXP");
  const ContainerDocument doc = read_exp(file);
  ASSERT_EQ(doc.objects.size(), 8u);
  const auto line_of = [&](const ContainerObject& o) {
    return source::LineIndex(file).position_of(o.file_offset).line + 1;
  };

  EXPECT_EQ(doc.objects[0].kind, "TYPE");
  EXPECT_EQ(doc.objects[0].name, "ST_AXIS");
  EXPECT_EQ(doc.objects[0].path, "/Motion");
  EXPECT_TRUE(doc.objects[0].nested_comments);
  EXPECT_EQ(line_of(doc.objects[0]), 4u);

  EXPECT_EQ(doc.objects[1].kind, "FUNCTION_BLOCK");
  EXPECT_EQ(doc.objects[1].name, "FB_COUNT");
  EXPECT_EQ(doc.objects[1].path, "/Basic/Math");
  EXPECT_FALSE(doc.objects[1].nested_comments);
  EXPECT_EQ(doc.objects[1].language, "ST");
  EXPECT_EQ(line_of(doc.objects[1]), 15u);

  EXPECT_EQ(doc.objects[2].kind, "ACTION");
  EXPECT_EQ(doc.objects[2].name, "FB_COUNT.RESET");
  EXPECT_EQ(doc.objects[2].path, "/Basic/Math");  // inherited from its POU
  EXPECT_FALSE(doc.objects[2].nested_comments);
  EXPECT_EQ(doc.objects[2].language, "ST");

  EXPECT_EQ(doc.objects[3].kind, "GVL");
  EXPECT_EQ(doc.objects[3].name, "Globale_Variablen");  // both VAR_GLOBAL blocks: one list
  EXPECT_EQ(doc.objects[3].path, "");
  EXPECT_TRUE(doc.objects[3].nested_comments);

  EXPECT_EQ(doc.objects[4].kind, "PROGRAM");
  EXPECT_EQ(doc.objects[4].name, "PLC_PRG");
  EXPECT_EQ(doc.objects[4].language, "FBD");
  EXPECT_EQ(doc.objects[4].note, "FBD body is graphical; blanked");

  EXPECT_EQ(doc.objects[5].kind, "VISUALISATION");
  EXPECT_EQ(doc.objects[5].name, "PLC_VISU");
  EXPECT_EQ(doc.objects[5].note, "VISUALISATION section is not PLC code; blanked");

  EXPECT_EQ(doc.objects[6].kind, "FUNCTION");
  EXPECT_EQ(doc.objects[6].name, "F_LD");
  EXPECT_EQ(doc.objects[6].language, "IL");

  EXPECT_EQ(doc.objects[7].kind, "LIBRARY");
  EXPECT_EQ(doc.objects[7].name, "Standard.lib");
  EXPECT_EQ(line_of(doc.objects[7]), 104u);
}

TEST(ExpReader, NestedCommentsOffMeansTheFirstCloseEndsTheComment) {
  // With nesting on, "(* (* x *)" would still be open and hide END_FUNCTION_BLOCK.
  const std::string text =
      "(* @NESTEDCOMMENTS := 'No' *)\n"
      "FUNCTION_BLOCK A\n"
      "(* @END_DECLARATION := '0' *)\n"
      "(* (* x *)\n"
      "END_FUNCTION_BLOCK\n"
      "VISUALISATION V _VISU_TYPES : 1\n"
      "END_VISUALISATION\n";
  const ContainerDocument doc = read_exp(text);
  ASSERT_EQ(doc.objects.size(), 2u);
  EXPECT_EQ(doc.objects[0].note, "");
  EXPECT_EQ(doc.objects[1].kind, "VISUALISATION");
  EXPECT_EQ(doc.virtual_text.find("VISUALISATION"), std::string::npos);

  std::string nested = text;
  nested.replace(nested.find("'No'"), 4, "'Yes'");
  const ContainerDocument doc_nested = read_exp(nested);
  // Nesting on: the comment swallows the rest, so the FB never ends and
  // the visualisation stays (the parser reports the unclosed comment).
  ASSERT_EQ(doc_nested.objects.size(), 1u);
  EXPECT_EQ(doc_nested.objects[0].note, "ends without END_FUNCTION_BLOCK");
}

TEST(ExpReader, MissingEndIsNotedAndTheNextObjectStillFound) {
  const std::string text =
      "(* @NESTEDCOMMENTS := 'Yes' *)\n"
      "PROGRAM A\n"
      "(* @END_DECLARATION := '0' *)\n"
      "x := 1;\n"
      "(* @NESTEDCOMMENTS := 'Yes' *)\n"
      "(* @PATH := '\\/F' *)\n"
      "PROGRAM B\n"
      "(* @END_DECLARATION := '0' *)\n"
      "_LD_BODY\n"
      "_NETWORKS : 0\n";
  const ContainerDocument doc = read_exp(text);
  ASSERT_EQ(doc.objects.size(), 2u);
  EXPECT_EQ(doc.objects[0].note, "has no END_PROGRAM before the next object");
  EXPECT_EQ(doc.objects[1].name, "B");
  EXPECT_EQ(doc.objects[1].path, "/F");
  EXPECT_EQ(doc.objects[1].language, "LD");
  EXPECT_EQ(doc.objects[1].note, "LD body is graphical; blanked; ends without END_PROGRAM");
  EXPECT_EQ(doc.virtual_text.find("_NETWORKS"), std::string::npos);
}

TEST(ExpReader, UnderscoreSectionsAreNotCode) {
  const std::string text =
      "_ALARMCONFIG\n"
      "_ALARMGROUP 'x'\n"
      "_END_ALARMCONFIG\n"
      "(* @NESTEDCOMMENTS := 'Yes' *)\n"
      "PROGRAM P\n"
      "(* @END_DECLARATION := '0' *)\n"
      "x := 'END_PROGRAM';\n"
      "END_PROGRAM\n"
      "_WORKSPACE\n"
      "whatever\n";
  const ContainerDocument doc = read_exp(text);
  ASSERT_EQ(doc.objects.size(), 3u);
  EXPECT_EQ(doc.objects[0].kind, "_ALARMCONFIG");
  EXPECT_EQ(doc.objects[1].kind, "PROGRAM");
  EXPECT_EQ(doc.objects[2].kind, "_WORKSPACE");
  EXPECT_EQ(doc.objects[2].note, "_WORKSPACE section is not PLC code; blanked; section runs to the end of the file");
  const std::string expected_tail = "END_PROGRAM\n          \n        \n";
  EXPECT_TRUE(doc.virtual_text.ends_with(expected_tail)) << doc.virtual_text;
  EXPECT_TRUE(doc.virtual_text.starts_with("            \n               \n                \n(*"));
}

TEST(ExpReader, EmptyAndOddInputs) {
  EXPECT_EQ(read_exp("").virtual_text, "");
  EXPECT_TRUE(read_exp("").objects.empty());
  EXPECT_EQ(read_exp("\r\n\r\n").virtual_text, "\r\n\r\n");
  const ContainerDocument lone = read_exp("PROGRAM");
  ASSERT_EQ(lone.objects.size(), 1u);
  EXPECT_EQ(lone.objects[0].name, "");
  EXPECT_EQ(lone.objects[0].note, "ends without END_PROGRAM");
}

// A library export's layout: blank lines first, a plain comment between the markers and
// the header, tab-separated "ACTION\tName:" blocks after END_FUNCTION_BLOCK, runs of blank
// lines between objects, an indented header, CRLF.
TEST(ExpReader, ActionsAfterTheBlockAndCommentsBeforeTheHeader) {
  const std::string file = decoded_data("FB_Client.EXP");
  const ContainerDocument doc = read_exp(file);
  EXPECT_EQ(doc.virtual_text, file);
  ASSERT_EQ(doc.objects.size(), 4u);
  EXPECT_EQ(doc.objects[0].kind, "FUNCTION_BLOCK");
  EXPECT_EQ(doc.objects[0].name, "FB_Client");
  EXPECT_EQ(doc.objects[0].path, "/Net/Client");
  EXPECT_EQ(doc.objects[0].language, "ST");
  EXPECT_EQ(doc.objects[1].kind, "ACTION");
  EXPECT_EQ(doc.objects[1].name, "FB_Client.AC_Close");
  EXPECT_EQ(doc.objects[1].path, "/Net/Client");
  EXPECT_EQ(doc.objects[2].name, "FB_Client.AC_Open");
  EXPECT_EQ(doc.objects[3].name, "FB_Random");
  for (const ContainerObject& object : doc.objects) EXPECT_EQ(object.note, "") << object.name;
  EXPECT_EQ(file_position_of(doc, file, "wState := 2#0111"), (LineColumn{34, 1}));
}

}  // namespace
}  // namespace rung::containers
