#include "parser/containers/twincat_reader.hpp"

#include <gtest/gtest.h>

#include "container_test_support.hpp"

namespace rung::containers {
namespace {

using testing::decoded_data;
using testing::file_position_of;
using testing::LineColumn;

TEST(TwinCatReader, FunctionBlockVirtualTextIsWhatTheGrammarExpects) {
  const std::string file = decoded_data("FB_Motor.TcPOU");
  const ContainerDocument doc = read_twincat(file);
  EXPECT_EQ(doc.kind, ContainerKind::TwinCat);
  EXPECT_TRUE(doc.issues.empty());
  const std::string expected =
      "FUNCTION_BLOCK FB_Motor\r\n"
      "VAR_INPUT\r\n"
      "    bEnable : BOOL; // Freigabe f\xC3\xBCr den Motor\r\n"
      "END_VAR\r\n"
      "VAR_OUTPUT\r\n"
      "    bRunning : BOOL;\r\n"
      "END_VAR\r\n"
      "VAR\r\n"
      "    nState : INT;\r\n"
      "    fSpeed : LREAL;\r\n"
      "END_VAR\r\n"
      "\n"
      "IF bEnable THEN\r\n"
      "    nState := 1;\r\n"
      "END_IF\r\n"
      "bRunning := nState = 1;\n"
      "METHOD M_Start : BOOL\r\n"
      "VAR_INPUT\r\n"
      "    fTarget : LREAL;\r\n"
      "END_VAR\r\n"
      "\n"
      "fSpeed := fTarget;\r\n"
      "M_Start := TRUE;\n"
      "PROPERTY P_Speed : LREAL\n"
      "GET\n"
      "VAR\r\n"
      "END_VAR\r\n"
      "\n"
      "P_Speed := fSpeed;\n"
      "SET\n"
      "VAR\r\n"
      "END_VAR\r\n"
      "\n"
      "fSpeed := P_Speed;\n"
      "ACTION A_Reset:\n"
      "nState := 0;\r\n"
      "fSpeed := 0;\n"
      "TRANSITION T_Done:\n"
      "nState = 2";
  EXPECT_EQ(doc.virtual_text, expected);
}

TEST(TwinCatReader, PositionsMapToTheContainerLines) {
  const std::string file = decoded_data("FB_Motor.TcPOU");
  const ContainerDocument doc = read_twincat(file);
  // The BOM is gone after decoding; line numbers are the file's own.
  EXPECT_EQ(file_position_of(doc, file, "FUNCTION_BLOCK FB_Motor"), (LineColumn{4, 27}));
  EXPECT_EQ(file_position_of(doc, file, "bEnable : BOOL"), (LineColumn{6, 5}));
  EXPECT_EQ(file_position_of(doc, file, "// Freigabe"), (LineColumn{6, 21}));
  EXPECT_EQ(file_position_of(doc, file, "IF bEnable"), (LineColumn{17, 20}));
  EXPECT_EQ(file_position_of(doc, file, "nState := 1"), (LineColumn{18, 5}));
  EXPECT_EQ(file_position_of(doc, file, "METHOD M_Start"), (LineColumn{24, 29}));
  EXPECT_EQ(file_position_of(doc, file, "M_Start := TRUE"), (LineColumn{31, 1}));
  EXPECT_EQ(file_position_of(doc, file, "P_Speed := fSpeed"), (LineColumn{41, 24}));
  EXPECT_EQ(file_position_of(doc, file, "fSpeed := P_Speed"), (LineColumn{49, 24}));
  EXPECT_EQ(file_position_of(doc, file, "fSpeed := 0"), (LineColumn{56, 1}));
  EXPECT_EQ(file_position_of(doc, file, "nState = 2"), (LineColumn{61, 22}));
}

TEST(TwinCatReader, SegmentsCarryRoles) {
  const std::string file = decoded_data("FB_Motor.TcPOU");
  const ContainerDocument doc = read_twincat(file);
  const auto role_at = [&](std::string_view needle) {
    const Segment* s = doc.segment_at(static_cast<uint32_t>(doc.virtual_text.find(needle)));
    return s ? s->role : std::string("<none>");
  };
  EXPECT_EQ(role_at("VAR_OUTPUT"), "declaration");
  EXPECT_EQ(role_at("IF bEnable"), "implementation");
  EXPECT_EQ(role_at("METHOD"), "method M_Start/declaration");
  EXPECT_EQ(role_at("fSpeed := fTarget"), "method M_Start/implementation");
  EXPECT_EQ(role_at("PROPERTY"), "property P_Speed/declaration");
  EXPECT_EQ(role_at("GET\n"), "property P_Speed/get");
  EXPECT_EQ(role_at("P_Speed := fSpeed"), "property P_Speed/get/implementation");
  EXPECT_EQ(role_at("SET\n"), "property P_Speed/set");
  EXPECT_EQ(role_at("ACTION A_Reset"), "action A_Reset");
  EXPECT_EQ(role_at("TRANSITION T_Done"), "transition T_Done");
  EXPECT_EQ(role_at("nState = 2"), "transition T_Done");
  for (const Segment& s : doc.segments) EXPECT_EQ(s.object_name, "FB_Motor");
}

TEST(TwinCatReader, SyntheticTextMapsToTheFollowingRealText) {
  const std::string file = decoded_data("FB_Motor.TcPOU");
  const ContainerDocument doc = read_twincat(file);
  const auto get = static_cast<uint32_t>(doc.virtual_text.find("GET\n"));
  const Segment* s = doc.segment_at(get);
  ASSERT_NE(s, nullptr);
  EXPECT_FALSE(s->file_begin.has_value());
  // "GET\n" is followed by the getter's declaration "VAR": a diagnostic on the
  // synthetic line lands there.
  const auto mapped = doc.to_file_offset(get);
  ASSERT_TRUE(mapped.has_value());
  EXPECT_EQ(std::string_view(file).substr(*mapped, 3), "VAR");
  EXPECT_EQ(*mapped, *doc.to_file_offset(get + 4));
}

TEST(TwinCatReader, FileOffsetsMapBackToVirtual) {
  const std::string file = decoded_data("FB_Motor.TcPOU");
  const ContainerDocument doc = read_twincat(file);
  const auto in_file = static_cast<uint32_t>(file.find("M_Start := TRUE"));
  const auto in_virtual = doc.to_virtual_offset(in_file);
  ASSERT_TRUE(in_virtual.has_value());
  EXPECT_EQ(*in_virtual, doc.virtual_text.find("M_Start := TRUE"));
  EXPECT_EQ(doc.to_virtual_offset(static_cast<uint32_t>(file.find("<Method"))), std::nullopt);
  EXPECT_EQ(doc.to_virtual_offset(static_cast<uint32_t>(file.find("LineIds"))), std::nullopt);
  // Every real byte round-trips.
  for (const Segment& s : doc.segments) {
    if (!s.file_begin) continue;
    for (uint32_t k = 0; k < s.length; ++k) {
      ASSERT_EQ(doc.to_virtual_offset(*s.file_begin + k), s.virtual_begin + k);
      ASSERT_EQ(doc.to_file_offset(s.virtual_begin + k), *s.file_begin + k);
    }
  }
}

TEST(TwinCatReader, ObjectsAreListed) {
  const std::string file = decoded_data("FB_Motor.TcPOU");
  const ContainerDocument doc = read_twincat(file);
  ASSERT_EQ(doc.objects.size(), 5u);
  EXPECT_EQ(doc.objects[0].name, "FB_Motor");
  EXPECT_EQ(doc.objects[0].kind, "POU");
  EXPECT_EQ(doc.objects[0].language, "ST");
  EXPECT_EQ(std::string_view(file).substr(doc.objects[0].file_offset, 15), "<POU Name=\"FB_M");
  EXPECT_EQ(doc.objects[1].name, "FB_Motor.M_Start");
  EXPECT_EQ(doc.objects[1].kind, "METHOD");
  EXPECT_EQ(doc.objects[2].name, "FB_Motor.P_Speed");
  EXPECT_EQ(doc.objects[2].kind, "PROPERTY");
  EXPECT_EQ(doc.objects[2].language, "ST");
  EXPECT_EQ(doc.objects[3].name, "FB_Motor.A_Reset");
  EXPECT_EQ(doc.objects[3].kind, "ACTION");
  EXPECT_EQ(doc.objects[4].name, "FB_Motor.T_Done");
  EXPECT_EQ(doc.objects[4].kind, "TRANSITION");
}

TEST(TwinCatReader, Dut) {
  const std::string file = decoded_data("ST_Axis.TcDUT");
  const ContainerDocument doc = read_twincat(file);
  EXPECT_TRUE(doc.issues.empty());
  EXPECT_EQ(doc.virtual_text,
            "TYPE ST_Axis :\r\nSTRUCT\r\n    fPosition : LREAL; (* mm *)\r\n    bHomed    : BOOL;\r\n"
            "END_STRUCT\r\nEND_TYPE\r\n");
  ASSERT_EQ(doc.segments.size(), 1u);
  EXPECT_EQ(doc.segments[0].role, "declaration");
  EXPECT_EQ(file_position_of(doc, file, "(* mm *)"), (LineColumn{6, 24}));
  ASSERT_EQ(doc.objects.size(), 1u);
  EXPECT_EQ(doc.objects[0].kind, "DUT");
  EXPECT_EQ(doc.objects[0].name, "ST_Axis");
  EXPECT_EQ(doc.objects[0].language, "");
}

TEST(TwinCatReader, GvlWithPragmas) {
  const std::string file = decoded_data("GVL_IO.TcGVL");
  const ContainerDocument doc = read_twincat(file);
  EXPECT_TRUE(doc.virtual_text.starts_with("{attribute 'qualified_only'}\r\n{attribute 'linkalways'}\r\nVAR_GLOBAL"));
  EXPECT_EQ(file_position_of(doc, file, "{attribute 'qualified_only'}"), (LineColumn{4, 27}));
  EXPECT_EQ(file_position_of(doc, file, "nCount : UDINT"), (LineColumn{9, 5}));
  ASSERT_EQ(doc.objects.size(), 1u);
  EXPECT_EQ(doc.objects[0].kind, "GVL");
  EXPECT_EQ(doc.objects[0].name, "GVL_IO");
}

TEST(TwinCatReader, InterfaceWithMethodAndProperty) {
  const std::string file = decoded_data("I_Drive.TcIO");
  const ContainerDocument doc = read_twincat(file);
  EXPECT_TRUE(doc.issues.empty());
  EXPECT_EQ(doc.virtual_text,
            "INTERFACE I_Drive EXTENDS __SYSTEM.IQueryInterface\r\n"
            "\n"
            "METHOD M_Move : BOOL\r\nVAR_INPUT\r\n    fDistance : LREAL;\r\nEND_VAR\r\n"
            "\n"
            "PROPERTY P_Ready : BOOL\n"
            "GET\n");
  EXPECT_EQ(file_position_of(doc, file, "fDistance"), (LineColumn{9, 5}));
  ASSERT_EQ(doc.objects.size(), 3u);
  EXPECT_EQ(doc.objects[0].kind, "ITF");
  EXPECT_EQ(doc.objects[1].name, "I_Drive.M_Move");
  EXPECT_EQ(doc.objects[2].name, "I_Drive.P_Ready");
}

TEST(TwinCatReader, EscapedTextIsUnescapedAndMappedPiecewise) {
  const std::string file = decoded_data("F_Max_escaped.TcPOU");
  const ContainerDocument doc = read_twincat(file);
  EXPECT_TRUE(doc.issues.empty());
  EXPECT_EQ(doc.virtual_text,
            "FUNCTION F_Max : INT\r\nVAR_INPUT\r\n    a, b : INT;\r\nEND_VAR\r\n"
            "\n"
            "IF a > b THEN F_Max := a; ELSE F_Max := b; END_IF\r\n"
            "s := '\xE2\x82\xAC'; // a&b");
  // Text after an entity still lands on the right column: "b THEN" follows "&gt; ".
  EXPECT_EQ(file_position_of(doc, file, "b THEN"), (LineColumn{10, 21}));
  EXPECT_EQ(file_position_of(doc, file, "F_Max := b"), (LineColumn{10, 45}));
  EXPECT_EQ(file_position_of(doc, file, "// a"), (LineColumn{11, 28}));
  // The '>' itself maps to the '&' of "&gt;".
  const auto gt = doc.to_file_offset(static_cast<uint32_t>(doc.virtual_text.find('>')));
  ASSERT_TRUE(gt.has_value());
  EXPECT_EQ(std::string_view(file).substr(*gt, 4), "&gt;");
  EXPECT_EQ(doc.to_virtual_offset(*gt), doc.virtual_text.find('>'));
}

TEST(TwinCatReader, GraphicalImplementationIsSkippedWithANote) {
  const std::string file = decoded_data("P_Ladder.TcPOU");
  const ContainerDocument doc = read_twincat(file);
  EXPECT_TRUE(doc.issues.empty());
  EXPECT_EQ(doc.virtual_text,
            "PROGRAM P_Ladder\r\nVAR\r\n    bIn, bOut : BOOL;\r\nEND_VAR\r\n\nACTION A_Text:\nbOut := bIn;");
  ASSERT_EQ(doc.objects.size(), 2u);
  EXPECT_EQ(doc.objects[0].language, "NWL");
  EXPECT_EQ(doc.objects[0].note, "NWL implementation is graphical; not read as text");
  EXPECT_EQ(doc.objects[1].language, "ST");
  EXPECT_EQ(doc.objects[1].note, "");
}

TEST(TwinCatReader, TruncatedFileReportsWhereAndKeepsWhatItCould) {
  const std::string file = decoded_data("FB_Truncated.TcPOU");
  const ContainerDocument doc = read_twincat(file);
  ASSERT_EQ(doc.issues.size(), 1u);
  EXPECT_EQ(doc.issues[0].message.rfind("malformed XML at line 31: ", 0), 0u) << doc.issues[0].message;
  // The declaration and body before the damage are still there, at their positions.
  EXPECT_TRUE(doc.virtual_text.starts_with("FUNCTION_BLOCK FB_Motor\r\n"));
  EXPECT_EQ(file_position_of(doc, file, "nState := 1"), (LineColumn{18, 5}));
}

TEST(TwinCatReader, MalformedXmlNamesTheCause) {
  const std::string text = "<?xml version=\"1.0\"?>\n<TcPlcObject>\n  <POU Name=\"X\">\n</TcPlcObject>";
  const ContainerDocument doc = read_twincat(text);
  ASSERT_EQ(doc.issues.size(), 1u);
  EXPECT_EQ(doc.issues[0].message, "malformed XML at line 4: Start-end tags mismatch");
  EXPECT_EQ(doc.issues[0].offset, text.find("/TcPlcObject>") + 1);
}

TEST(TwinCatReader, GarbageDoesNotCrash) {
  for (const std::string text : {"", "<", "<<<>>>", "<![CDATA[", "\x01\x02<TcPlcObject", "<a><![CDATA[x]]></b>"}) {
    const ContainerDocument doc = read_twincat(text);
    EXPECT_FALSE(doc.issues.empty()) << text;
    EXPECT_EQ(doc.virtual_text, "");
  }
}

TEST(TwinCatReader, UnknownRootIsReported) {
  const std::string file = decoded_data("UnknownRoot.TcPOU");
  const ContainerDocument doc = read_twincat(file);
  ASSERT_EQ(doc.issues.size(), 1u);
  EXPECT_EQ(doc.issues[0].message, "not a TwinCAT PLC object: the root element is <Project>, not <TcPlcObject>");
  EXPECT_EQ(doc.issues[0].offset, file.find("<Project"));
  EXPECT_EQ(doc.virtual_text, "");
}

TEST(TwinCatReader, TaskObjectIsListedWithoutCode) {
  const std::string file = decoded_data("PlcTask.TcTTO");
  const ContainerDocument doc = read_twincat(file);
  EXPECT_TRUE(doc.issues.empty());
  EXPECT_EQ(doc.virtual_text, "");
  ASSERT_EQ(doc.objects.size(), 1u);
  EXPECT_EQ(doc.objects[0].kind, "Task");
  EXPECT_EQ(doc.objects[0].name, "PlcTask");
  EXPECT_EQ(doc.objects[0].note, "TwinCAT <Task> object holds no PLC source; skipped");
}

TEST(TwinCatReader, EmptyCdataAddsNothing) {
  const std::string text =
      "<TcPlcObject><POU Name=\"P\"><Declaration><![CDATA[PROGRAM P]]></Declaration>"
      "<Implementation><ST><![CDATA[]]></ST></Implementation>"
      "<Method Name=\"M\"><Declaration><![CDATA[METHOD M]]></Declaration></Method></POU></TcPlcObject>";
  const ContainerDocument doc = read_twincat(text);
  EXPECT_TRUE(doc.issues.empty());
  EXPECT_EQ(doc.virtual_text, "PROGRAM P\nMETHOD M");
  EXPECT_EQ(doc.objects[0].language, "ST");
}

// An SFC program as XAE writes it (BOM, CRLF, <LineIds>): the chart is skipped; step
// actions and transitions with code become objects of the virtual text; an empty or
// graphical action gets no header, since there is nothing in it to parse.
TEST(TwinCatReader, SfcProgramKeepsActionsAndTransitionsWithCode) {
  const std::string file = decoded_data("P_Sequence.TcPOU");
  const ContainerDocument doc = read_twincat(file);
  EXPECT_TRUE(doc.issues.empty());
  EXPECT_EQ(doc.virtual_text,
            "PROGRAM P_Sequence\r\nVAR\r\n\tbGo : BOOL;\r\n\tnCycles : UDINT;\r\nEND_VAR\r\n"
            "\nACTION Run_active:\nnCycles := nCycles + 1;"
            "\nTRANSITION Trans0:\nbGo"
            "\nTRANSITION Trans1:\nnCycles >= 3");
  ASSERT_EQ(doc.objects.size(), 6u);
  EXPECT_EQ(doc.objects[0].language, "SFC");
  EXPECT_EQ(doc.objects[1].name, "P_Sequence.Idle_entry");
  EXPECT_EQ(doc.objects[1].language, "ST");
  EXPECT_EQ(doc.objects[1].note, "empty; not in the virtual text");
  EXPECT_EQ(doc.objects[2].note, "");
  EXPECT_EQ(doc.objects[3].name, "P_Sequence.Lamp");
  EXPECT_EQ(doc.objects[3].language, "NWL");
  EXPECT_EQ(doc.objects[3].note, "NWL implementation is graphical; not read as text");
  EXPECT_EQ(doc.objects[5].kind, "TRANSITION");
  EXPECT_EQ(file_position_of(doc, file, "nCycles := nCycles"), (LineColumn{28, 22}));
  EXPECT_EQ(file_position_of(doc, file, "nCycles >= 3"), (LineColumn{45, 22}));
}

// Interface properties as XAE 4026 writes them: accessors with an empty CDATA
// declaration, or no child at all; methods with a declaration only.
TEST(TwinCatReader, InterfacePropertiesWithEmptyAccessors) {
  const std::string file = decoded_data("I_Parent.TcIO");
  const ContainerDocument doc = read_twincat(file);
  EXPECT_TRUE(doc.issues.empty());
  EXPECT_EQ(doc.virtual_text,
            "(* Parent of children.\n   (* nested *)\n*)\nINTERFACE I_Parent EXTENDS I_Base, Lib.I_Dispatcher\n"
            "METHOD ChildAt : I_Child\nVAR_INPUT\n\tnIndex : UDINT;\nEND_VAR\n"
            "{attribute 'monitoring' := 'call'}\nPROPERTY FINAL Policy : Lib.I_Policy\nGET\nSET\n"
            "PROPERTY Count : UDINT\nGET\n");
  ASSERT_EQ(doc.objects.size(), 4u);
  EXPECT_EQ(doc.objects[0].kind, "ITF");
  EXPECT_EQ(doc.objects[1].kind, "METHOD");
  EXPECT_EQ(doc.objects[2].name, "I_Parent.Policy");
  EXPECT_EQ(file_position_of(doc, file, "PROPERTY Count"), (LineColumn{19, 29}));
}

}  // namespace
}  // namespace rung::containers

namespace rung::containers {
namespace {

// The XML loader is shared: a raw '<' inside an attribute value (which pugixml accepts) is
// reported for TwinCAT files as for PLCopen ones, and the ST is still read.
TEST(TwinCatReader, LessThanInAnAttributeValueIsReported) {
  const std::string text =
      "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n"
      "<TcPlcObject Version=\"1.1.0.1\" ProductVersion=\"<hidden>\">\n"
      "  <POU Name=\"P\"><Declaration><![CDATA[PROGRAM P]]></Declaration></POU>\n"
      "</TcPlcObject>\n";
  const ContainerDocument doc = read_twincat(text);
  ASSERT_EQ(doc.issues.size(), 1u);
  EXPECT_EQ(doc.issues[0].message, "malformed XML at line 2: '<' inside an attribute value");
  EXPECT_EQ(doc.issues[0].offset, text.find("<hidden>"));
  EXPECT_EQ(doc.virtual_text, "PROGRAM P");
}

}  // namespace
}  // namespace rung::containers
