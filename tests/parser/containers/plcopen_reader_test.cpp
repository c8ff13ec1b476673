#include "parser/containers/plcopen_reader.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "container_test_support.hpp"
#include "parser/containers/detect.hpp"
#include "parser/containers/read_container.hpp"
#include "parser/diagnostic_codes.hpp"
#include "parser/document.hpp"

namespace rung::containers {
namespace {

using testing::decoded_data;
using testing::file_position_of;
using testing::LineColumn;

constexpr const char* kDataFiles[] = {"Small_plcopen.xml", "Beremiz_plc.xml", "Codesys_export.xml",
                                      "Beremiz_quirks.xml", "Codesys_application.xml"};

const ContainerObject* find_object(const ContainerDocument& doc, std::string_view name) {
  const auto it =
      std::find_if(doc.objects.begin(), doc.objects.end(), [&](const ContainerObject& o) { return o.name == name; });
  return it == doc.objects.end() ? nullptr : &*it;
}

TEST(PlcOpenReader, SmallProjectVirtualTextIsWhatTheGrammarExpects) {
  const std::string file = decoded_data("Small_plcopen.xml");
  const ContainerDocument doc = read_plcopen(file);
  EXPECT_EQ(doc.kind, ContainerKind::PlcOpen);
  EXPECT_TRUE(doc.issues.empty());
  const std::string expected =
      "TYPE E_Mode : (Off := 0, Auto := 1); END_TYPE\n"
      "PROGRAM Blink\n"
      "VAR_INPUT\n"
      "  xOn : BOOL;\n"
      "END_VAR\n"
      "VAR CONSTANT\n"
      "  nMax : INT := 10;\n"
      "END_VAR\n"
      "VAR\n"
      "  nTick AT %MW4 : INT;\n"
      "END_VAR\n"
      "IF xOn AND nTick < nMax THEN\n"
      "  nTick := nTick + 1;\n"
      "END_IF;\n"
      "END_PROGRAM\n"
      "CONFIGURATION Cfg\n"
      "RESOURCE Res ON PLC\n"
      "  TASK Fast(INTERVAL := T#10ms, PRIORITY := 0);\n"
      "  PROGRAM blink1 WITH Fast : Blink;\n"
      "END_RESOURCE\n"
      "END_CONFIGURATION\n";
  EXPECT_EQ(doc.virtual_text, expected);
}

TEST(PlcOpenReader, BodiesMapToTheirXmlLines) {
  const std::string small = decoded_data("Small_plcopen.xml");
  const ContainerDocument small_doc = read_plcopen(small);
  EXPECT_EQ(file_position_of(small_doc, small, "IF xOn AND"), (LineColumn{48, 31}));
  EXPECT_EQ(file_position_of(small_doc, small, "nTick := nTick + 1"), (LineColumn{49, 3}));

  const std::string beremiz = decoded_data("Beremiz_plc.xml");
  const ContainerDocument beremiz_doc = read_plcopen(beremiz);
  EXPECT_EQ(file_position_of(beremiz_doc, beremiz, "IF nRaw < 0"), (LineColumn{131, 31}));
  EXPECT_EQ(file_position_of(beremiz_doc, beremiz, "JMPC ResetCnt"), (LineColumn{228, 1}));
  EXPECT_EQ(file_position_of(beremiz_doc, beremiz, "stPump.bRun := FALSE"), (LineColumn{193, 1}));
  EXPECT_EQ(file_position_of(beremiz_doc, beremiz, "nCount >= 10"), (LineColumn{318, 35}));

  const std::string codesys = decoded_data("Codesys_export.xml");
  const ContainerDocument codesys_doc = read_plcopen(codesys);
  EXPECT_EQ(file_position_of(codesys_doc, codesys, "nRuns := nRuns + 1"), (LineColumn{111, 2}));
  EXPECT_EQ(file_position_of(codesys_doc, codesys, "M_Reset := TRUE"), (LineColumn{145, 1}));
  EXPECT_EQ(file_position_of(codesys_doc, codesys, "nRuns := P_Runs"), (LineColumn{180, 65}));
  EXPECT_EQ(file_position_of(codesys_doc, codesys, "F_Limit := LIMIT"), (LineColumn{305, 65}));
}

TEST(PlcOpenReader, EscapedBodyTextMapsPieceByPiece) {
  const std::string file = decoded_data("Codesys_export.xml");
  const ContainerDocument doc = read_plcopen(file);
  // "&lt;" in the file is "<" in the virtual text, and maps back onto the entity.
  const auto less = doc.virtual_text.find("nRuns < 16#FFFFFFFF");
  ASSERT_NE(less, std::string::npos);
  const auto mapped = doc.to_file_offset(static_cast<uint32_t>(less + 6));
  ASSERT_TRUE(mapped.has_value());
  EXPECT_EQ(std::string_view(file).substr(*mapped, 4), "&lt;");
  EXPECT_EQ(file_position_of(doc, file, " 16#FFFFFFFF"), (LineColumn{110, 28}));
  // Attribute values are unescaped the same way.
  EXPECT_NE(doc.virtual_text.find("sLabel : STRING(80) := 'belt <1>';"), std::string::npos);
}

TEST(PlcOpenReader, DeclaredNamesMapToTheirAttributes) {
  const std::string file = decoded_data("Small_plcopen.xml");
  const ContainerDocument doc = read_plcopen(file);
  EXPECT_EQ(file_position_of(doc, file, "E_Mode"), (LineColumn{7, 23}));
  EXPECT_EQ(file_position_of(doc, file, "Blink"), (LineColumn{19, 18}));
  EXPECT_EQ(file_position_of(doc, file, "xOn"), (LineColumn{22, 29}));
  EXPECT_EQ(file_position_of(doc, file, "nMax"), (LineColumn{29, 29}));
  EXPECT_EQ(file_position_of(doc, file, "%MW4"), (LineColumn{39, 45}));
  EXPECT_EQ(file_position_of(doc, file, "blink1"), (LineColumn{61, 32}));
  // A diagnostic on the synthesized start of a declaration line lands on the variable's name.
  const auto line = doc.virtual_text.find("  nMax : INT");
  ASSERT_NE(line, std::string::npos);
  EXPECT_EQ(doc.to_file_offset(static_cast<uint32_t>(line)), doc.to_file_offset(static_cast<uint32_t>(line + 2)));
  // Keywords and punctuation are synthetic.
  const Segment* keyword = doc.segment_at(static_cast<uint32_t>(doc.virtual_text.find("VAR_INPUT")));
  ASSERT_NE(keyword, nullptr);
  EXPECT_FALSE(keyword->file_begin.has_value());

  const std::string codesys = decoded_data("Codesys_export.xml");
  const ContainerDocument codesys_doc = read_plcopen(codesys);
  EXPECT_EQ(file_position_of(codesys_doc, codesys, "xHard"), (LineColumn{128, 35}));
  EXPECT_EQ(file_position_of(codesys_doc, codesys, "FB_Base"), (LineColumn{91, 26}));
}

TEST(PlcOpenReader, EveryRealByteRoundTrips) {
  for (const char* name : kDataFiles) {
    SCOPED_TRACE(name);
    const std::string file = decoded_data(name);
    const ContainerDocument doc = read_plcopen(file);
    uint32_t expected_begin = 0;
    for (const Segment& s : doc.segments) {
      ASSERT_EQ(s.virtual_begin, expected_begin);
      expected_begin += s.length;
      if (!s.file_begin) continue;
      for (uint32_t k = 0; k < s.length; ++k) {
        ASSERT_EQ(doc.to_virtual_offset(*s.file_begin + k), s.virtual_begin + k);
        ASSERT_EQ(doc.to_file_offset(s.virtual_begin + k), *s.file_begin + k);
      }
    }
    EXPECT_EQ(expected_begin, doc.virtual_text.size());
    EXPECT_EQ(doc.to_virtual_offset(static_cast<uint32_t>(file.find("<fileHeader"))), std::nullopt);
  }
}

TEST(PlcOpenReader, SegmentsCarryRolesAndOwners) {
  const std::string file = decoded_data("Codesys_export.xml");
  const ContainerDocument doc = read_plcopen(file);
  const auto segment_at = [&](std::string_view needle) {
    const size_t at = doc.virtual_text.find(needle);
    EXPECT_NE(at, std::string::npos) << needle;
    return doc.segment_at(static_cast<uint32_t>(at));
  };
  EXPECT_EQ(segment_at("VAR_OUTPUT")->role, "declaration");
  EXPECT_EQ(segment_at("rtStart(CLK")->role, "implementation");
  EXPECT_EQ(segment_at("METHOD PRIVATE")->role, "method M_Reset/declaration");
  EXPECT_EQ(segment_at("M_Reset := TRUE")->role, "method M_Reset/implementation");
  EXPECT_EQ(segment_at("GET\n")->role, "property P_Runs/get");
  EXPECT_EQ(segment_at("nCopy := nRuns")->role, "property P_Runs/get/implementation");
  EXPECT_EQ(segment_at("ACTION A_Stop")->role, "action A_Stop");
  EXPECT_EQ(segment_at("nRuns := 0")->object_name, "FB_Conveyor");
  EXPECT_EQ(segment_at("F_Limit := LIMIT")->object_name, "F_Limit");
  EXPECT_EQ(segment_at("TASK MainTask")->object_name, "Device");
}

TEST(PlcOpenReader, BeremizProjectLayout) {
  const std::string file = decoded_data("Beremiz_plc.xml");
  const ContainerDocument doc = read_plcopen(file);
  EXPECT_TRUE(doc.issues.empty());
  for (const std::string_view expected : {
           "TYPE E_Mode : (Off := 0, Auto := 1, Manual := 2) := Off; END_TYPE\n",
           "TYPE ST_Pump : STRUCT\n  bRun : BOOL;\n  fFlow : REAL := 0.5;\n"
           "  aHistory : ARRAY [0..9, 1..2] OF LREAL;\n  sName : STRING(32) := 'P&1';\nEND_STRUCT; END_TYPE\n",
           "TYPE T_Percent : INT (0..100); END_TYPE\n",
           "TYPE T_Levels : ARRAY [1..4] OF T_Percent := [3(10), 50]; END_TYPE\n",
           "TYPE T_Label : WSTRING; END_TYPE\n",
           "FUNCTION F_Scale : REAL\nVAR_INPUT\n  nRaw : INT;\n  fMax : REAL := 100.0;\nEND_VAR\n",
           "  stPump : ST_Pump := (bRun := FALSE, fFlow := 1.5);\n",
           "VAR RETAIN\n  nStarts : UDINT;\nEND_VAR\n",
           "stPump.bRun := tonDelay.Q;\nACTION A_Reset:\nnStarts := 0;\nstPump.bRun := FALSE;\nEND_ACTION\n"
           "END_FUNCTION_BLOCK\n",
           "ST Out\nEND_FUNCTION_BLOCK\n",
           "FUNCTION_BLOCK Interlock\nVAR_INPUT\n  A : BOOL;\n  B : BOOL;\nEND_VAR\nVAR_OUTPUT\n  Y : BOOL;\nEND_VAR\n"
           "END_FUNCTION_BLOCK\n",
           "ACTION Count:\nnCount := nCount + 1;\nEND_ACTION\nTRANSITION Done:\nnCount >= 10\nEND_TRANSITION\n"
           "END_PROGRAM\n",
           "  xStartButton AT %IX0.0 : BOOL;\n",
           "  pLevel : POINTER TO INT;\n",
           "VAR_EXTERNAL CONSTANT\n  nMaxLevel : INT;\nEND_VAR\n",
           "CONFIGURATION config\nVAR_GLOBAL CONSTANT\n  nMaxLevel : INT := 900;\nEND_VAR\nRESOURCE resource1 ON PLC\n"
           "VAR_GLOBAL\n  gnAlarms : DINT := 0;\nEND_VAR\n"
           "  TASK MainTask(INTERVAL := T#20ms, PRIORITY := 1);\n  TASK SlowTask(INTERVAL := T#1s, PRIORITY := 5);\n"
           "  PROGRAM MainInst WITH MainTask : Main;\n  PROGRAM SeqInst WITH SlowTask : Sequence;\n"
           "END_RESOURCE\nEND_CONFIGURATION\n",
       }) {
    EXPECT_NE(doc.virtual_text.find(expected), std::string::npos) << "missing:\n" << expected;
  }
  // The entity in the attribute maps onto "&amp;".
  const auto amp = doc.virtual_text.find("'P&1'") + 2;
  EXPECT_EQ(std::string_view(file).substr(*doc.to_file_offset(static_cast<uint32_t>(amp)), 5), "&amp;");

  const ContainerObject* ladder = find_object(doc, "Interlock");
  ASSERT_NE(ladder, nullptr);
  EXPECT_EQ(ladder->kind, "FUNCTION_BLOCK");
  EXPECT_EQ(ladder->language, "LD");
  EXPECT_EQ(ladder->note, "LD implementation is graphical; not read as text");
  const ContainerObject* sequence = find_object(doc, "Sequence");
  ASSERT_NE(sequence, nullptr);
  EXPECT_EQ(sequence->language, "SFC");
  ASSERT_NE(find_object(doc, "Sequence.Done"), nullptr);
  EXPECT_EQ(find_object(doc, "Sequence.Done")->kind, "TRANSITION");
  EXPECT_EQ(find_object(doc, "FB_Pump.A_Reset")->kind, "ACTION");
  EXPECT_EQ(find_object(doc, "CounterIL")->language, "IL");
  EXPECT_EQ(find_object(doc, "ST_Pump")->kind, "TYPE");
  EXPECT_EQ(find_object(doc, "config")->kind, "CONFIGURATION");
}

TEST(PlcOpenReader, CodesysExportLayout) {
  const std::string file = decoded_data("Codesys_export.xml");
  const ContainerDocument doc = read_plcopen(file);
  EXPECT_TRUE(doc.issues.empty());
  for (
      const std::string_view expected : {
          "TYPE E_State : (Idle, Running, Fault); END_TYPE\n",
          "FUNCTION_BLOCK FB_Conveyor EXTENDS FB_Base IMPLEMENTS I_Runnable\n",
          "VAR PERSISTENT\n  nRuns : UDINT;\nEND_VAR\n",
          "  pSelf : POINTER TO FB_Conveyor;\n  rtStart : Standard.R_TRIG;\n",
          "END_IF\nMETHOD PRIVATE M_Reset : BOOL\nVAR_INPUT\n  xHard : BOOL;\nEND_VAR\n",
          "M_Reset := TRUE;\nEND_METHOD\nPROPERTY P_Runs : UDINT\nGET\nVAR\n  nCopy : UDINT;\nEND_VAR\n"  // NOLINT(bugprone-suspicious-missing-comma)
          "nCopy := nRuns;\nP_Runs := nCopy;\nEND_GET\nSET\nnRuns := P_Runs;\nEND_SET\nEND_PROPERTY\n"
          "ACTION A_Stop:\neState := E_State.Idle;\nEND_ACTION\nEND_FUNCTION_BLOCK\n",
          "  aSpeeds : ARRAY [1..3] OF INT := [10, 2(20)];\n",
          "PROGRAM P_Diagram\nVAR\n  xLamp : BOOL;\nEND_VAR\nEND_PROGRAM\n",
          // A POU stored in the application's addData (export with device).
          "FUNCTION F_Limit : INT\nVAR_INPUT\n  nIn : INT;\nEND_VAR\nF_Limit := LIMIT(0, nIn, 100);\nEND_FUNCTION\n",
          // xsd:duration interval; typeName="" means the program's own name.
          "RESOURCE Application ON PLC\nVAR_GLOBAL\n  xRun : BOOL;\nEND_VAR\n"
          "  TASK MainTask(INTERVAL := T#0.02s, PRIORITY := 1);\n  PROGRAM PLC_PRG WITH MainTask : PLC_PRG;\n",
      }) {
    EXPECT_NE(doc.virtual_text.find(expected), std::string::npos) << "missing:\n" << expected;
  }
  EXPECT_EQ(find_object(doc, "FB_Conveyor.M_Reset")->kind, "METHOD");
  EXPECT_EQ(find_object(doc, "FB_Conveyor.P_Runs")->kind, "PROPERTY");
  EXPECT_EQ(find_object(doc, "P_Diagram")->note, "FBD implementation is graphical; not read as text");
}

TEST(PlcOpenReader, PlainTextInterfaceIsUsedAsRealText) {
  const std::string file =
      "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n"
      "<project xmlns=\"http://www.plcopen.org/xml/tc6_0200\">\n"
      "  <types><dataTypes /><pous>\n"
      "    <pou name=\"FB_A\" pouType=\"functionBlock\">\n"
      "      <interface><inputVars><variable name=\"x\"><type><BOOL /></type></variable></inputVars></interface>\n"
      "      <body><ST><xhtml xmlns=\"http://www.w3.org/1999/xhtml\">y := x;</xhtml></ST></body>\n"
      "      <addData>\n"
      "        <data name=\"http://www.3s-software.com/plcopenxml/interfaceasplaintext\" "
      "handleUnknown=\"implementation\">\n"
      "          <InterfaceAsPlainText><xhtml xmlns=\"http://www.w3.org/1999/xhtml\">FUNCTION_BLOCK FB_A\n"
      "VAR_INPUT\n  x : BOOL; // the input\nEND_VAR\nVAR\n  y : REFERENCE TO BOOL;\nEND_VAR\n</xhtml>"
      "</InterfaceAsPlainText>\n"
      "        </data>\n"
      "      </addData>\n"
      "    </pou>\n"
      "  </pous></types>\n"
      "  <instances><configurations /></instances>\n"
      "</project>\n";
  const ContainerDocument doc = read_plcopen(file);
  EXPECT_TRUE(doc.issues.empty());
  EXPECT_EQ(doc.virtual_text,
            "FUNCTION_BLOCK FB_A\nVAR_INPUT\n  x : BOOL; // the input\nEND_VAR\nVAR\n  y : REFERENCE TO BOOL;\n"
            "END_VAR\ny := x;\nEND_FUNCTION_BLOCK\n");
  EXPECT_EQ(file_position_of(doc, file, "y : REFERENCE TO BOOL"), (LineColumn{14, 3}));
}

TEST(PlcOpenReader, WholeProjectsParseWithoutDiagnostics) {
  for (const char* name : kDataFiles) {
    SCOPED_TRACE(name);
    const std::string file = decoded_data(name);
    const Document document = Document::from_bytes(std::string("project/") + name, file);
    ASSERT_NE(document.container(), nullptr);
    EXPECT_EQ(document.container()->kind, ContainerKind::PlcOpen);
    for (const Diagnostic& d : document.diagnostics()) {
      const FilePosition p = document.position_of_file_offset(d.range.begin);
      ADD_FAILURE() << d.code << " " << p.line << ":" << p.column << " " << d.message;
    }
  }
}

TEST(PlcOpenReader, SyntaxErrorInABodyPointsAtTheXmlLine) {
  std::string file = decoded_data("Small_plcopen.xml");
  const size_t at = file.find("nTick + 1;");
  ASSERT_NE(at, std::string::npos);
  file.replace(at, 10, "nTick + ;");
  const Document document = Document::from_bytes("plc.xml", file);
  ASSERT_FALSE(document.diagnostics().empty());
  const Diagnostic& d = document.diagnostics().front();
  EXPECT_EQ(d.code, "S002") << d.message;
  const FilePosition p = document.position_of_file_offset(d.range.begin);
  EXPECT_EQ(p.line, 49u);
  EXPECT_GE(p.column, 12u);
}

TEST(PlcOpenReader, MalformedXmlIsAnIssueNotACrash) {
  const std::string whole = decoded_data("Beremiz_plc.xml");
  // Cut inside the FB_Pump body: what came before is still read.
  const std::string file = whole.substr(0, whole.find("IF tonDelay.Q"));
  const ContainerDocument doc = read_plcopen(file);
  ASSERT_FALSE(doc.issues.empty());
  EXPECT_EQ(doc.issues.front().message.rfind("malformed XML at line ", 0), 0u) << doc.issues.front().message;
  EXPECT_NE(doc.virtual_text.find("TYPE ST_Pump"), std::string::npos);

  const std::string broken =
      "<?xml version=\"1.0\"?>\n<project xmlns=\"http://www.plcopen.org/xml/tc6_0201\">\n"
      "  <types><pous><pou name=\"P\" pouType=\"program\"></types>\n</project>\n";
  const ContainerDocument broken_doc = read_plcopen(broken);
  ASSERT_EQ(broken_doc.issues.size(), 1u);
  EXPECT_EQ(broken_doc.issues.front().message.rfind("malformed XML at line 3: ", 0), 0u)
      << broken_doc.issues.front().message;

  const Document document = Document::from_bytes("plc.xml", broken);
  ASSERT_FALSE(document.diagnostics().empty());
  EXPECT_EQ(document.diagnostics().front().code, codes::kContainer);

  // Every truncation of a real layout is read without crashing (ASan/UBSan check this).
  for (const char* name : kDataFiles) {
    const std::string text = decoded_data(name);
    for (size_t cut = 0; cut < text.size(); cut += 37) (void)read_plcopen(std::string_view(text).substr(0, cut));
  }
  // Garbage and odd shapes never crash.
  for (const std::string_view text :
       {std::string_view(""), std::string_view("<project"), std::string_view("<project xmlns=\"x\"><types>"),
        std::string_view("<project><types><pous><pou name=\"X\" pouType=\"function\"><interface><returnType/>"
                         "</interface><body><ST/></body></pou></pous></types></project>"),
        std::string_view("<project><types><dataTypes><dataType name=\"T\"><baseType><array><baseType/></array>"
                         "</baseType></dataType></dataTypes></types></project>")}) {
    (void)read_plcopen(text);
  }
}

TEST(PlcOpenReader, UnknownRootIsReported) {
  const ContainerDocument doc = read_plcopen("<?xml version=\"1.0\"?>\n<other/>\n");
  ASSERT_EQ(doc.issues.size(), 1u);
  EXPECT_NE(doc.issues.front().message.find("root element is <other>"), std::string::npos);
  EXPECT_TRUE(doc.virtual_text.empty());
}

TEST(PlcOpenReader, DetectedByContentWhateverTheExtension) {
  const std::string file = decoded_data("Beremiz_plc.xml");
  EXPECT_EQ(detect_container("proj/plc.xml", file), ContainerKind::PlcOpen);
  EXPECT_EQ(detect_container("proj/export.plcopen", file), ContainerKind::PlcOpen);
  EXPECT_EQ(detect_container("Codesys_export.xml", decoded_data("Codesys_export.xml")), ContainerKind::PlcOpen);
  EXPECT_EQ(detect_container("x.xml", "<project xmlns:ppx=\"http://www.plcopen.org/xml/tc6_0201\"/>"),
            ContainerKind::PlcOpen);
  EXPECT_EQ(detect_container("x.xml", "<!-- c --><ppx:project xmlns:ppx=\"http://www.plcopen.org/xml/tc6_0200\"/>"),
            ContainerKind::PlcOpen);
  // Other XML stays an ordinary file.
  EXPECT_EQ(
      detect_container("pom.xml", "<?xml version=\"1.0\"?>\n<project xmlns=\"http://maven.apache.org/POM/4.0.0\"/>"),
      ContainerKind::None);
  EXPECT_EQ(detect_container("x.xml", "<beans>http://www.plcopen.org/xml/tc6_0201</beans>"), ContainerKind::None);
  EXPECT_EQ(read_container("plc.xml", file).kind, ContainerKind::PlcOpen);
  EXPECT_EQ(container_kind_name(ContainerKind::PlcOpen), "plcopen");
}

TEST(PlcOpenReader, UnquotedStringValuesAreQuoted) {
  const std::string file = decoded_data("Beremiz_quirks.xml");
  const ContainerDocument doc = read_plcopen(file);
  EXPECT_TRUE(doc.issues.empty());
  for (const std::string_view expected : {
           "  sPlain : STRING := 'test';\n",
           "  sSpaces : STRING := 'hello world';\n",
           "  sQuoted : STRING(10) := 'done';\n",  // already quoted: as it stands
           "  sEscape : STRING := 'it$'s 5$$ \"x\"';\n",
           "  sDerived : T_Alias := '2';\n",  // T_Alias -> T_Msg -> STRING(40)
           "  wLabel : WSTRING := \"x y\";\n",
           "  aNames : ARRAY [1..2] OF STRING := ['a', 'b c'];\n",
           "  stDev : ST_Device := (sName := 'pump 1', nId := 7);\n",
           "  nCount : INT := 3;\n",
       }) {
    EXPECT_NE(doc.virtual_text.find(expected), std::string::npos) << "missing:\n" << expected;
  }
  // The quotes are synthetic; the value's characters map to the attribute.
  const size_t quote = doc.virtual_text.find("'hello world'");
  ASSERT_NE(quote, std::string::npos);
  const Segment* synthetic = doc.segment_at(static_cast<uint32_t>(quote));
  ASSERT_NE(synthetic, nullptr);
  EXPECT_FALSE(synthetic->file_begin.has_value());
  EXPECT_EQ(file_position_of(doc, file, "hello world"), (LineColumn{59, 37}));
  // An inserted '$' is synthetic; the escaped character maps onto its entity.
  const size_t escape = doc.virtual_text.find("$'s");
  ASSERT_NE(escape, std::string::npos);
  EXPECT_FALSE(doc.segment_at(static_cast<uint32_t>(escape))->file_begin.has_value());
  EXPECT_EQ(std::string_view(file).substr(*doc.to_file_offset(static_cast<uint32_t>(escape + 1)), 6), "&apos;");
  EXPECT_EQ(file_position_of(doc, file, "s 5"), (LineColumn{75, 45}));
}

TEST(PlcOpenReader, ForeignCodeInAnStBodyIsSkipped) {
  const std::string file = decoded_data("Beremiz_quirks.xml");
  const ContainerDocument doc = read_plcopen(file);
  EXPECT_NE(doc.virtual_text.find("FUNCTION_BLOCK ReadInputs\nVAR_OUTPUT\n  xStart : BOOL;\nEND_VAR\n"
                                  "END_FUNCTION_BLOCK\n"),
            std::string::npos);
  EXPECT_NE(doc.virtual_text.find("FUNCTION_BLOCK PyBlock\nVAR_INPUT\n  nIn : INT;\nEND_VAR\nEND_FUNCTION_BLOCK\n"),
            std::string::npos);
  EXPECT_EQ(doc.virtual_text.find("#include"), std::string::npos);
  EXPECT_EQ(doc.virtual_text.find("import math"), std::string::npos);
  EXPECT_EQ(find_object(doc, "ReadInputs")->note, "ST body holds C/C++ code, not ST; not read as text");
  EXPECT_EQ(find_object(doc, "PyBlock")->note, "ST body holds Python code, not ST; not read as text");
  EXPECT_EQ(find_object(doc, "Strings")->note, "");
}

TEST(PlcOpenReader, BeremizAssignTransitionsLoseTheirAssign) {
  const std::string file = decoded_data("Beremiz_quirks.xml");
  const ContainerDocument doc = read_plcopen(file);
  EXPECT_NE(doc.virtual_text.find("ACTION Act:\nA := B;\nEND_ACTION\n"
                                  "TRANSITION Go:\n A AND B;\nEND_TRANSITION\n"
                                  "TRANSITION Back:\n(* leave *)\n   NOT A;\nEND_TRANSITION\n"
                                  "TRANSITION Plain:\nA OR B\nEND_TRANSITION\nEND_FUNCTION_BLOCK\n"),
            std::string::npos)
      << doc.virtual_text;
  EXPECT_EQ(file_position_of(doc, file, " A AND B;"), (LineColumn{222, 37}));
  EXPECT_EQ(file_position_of(doc, file, "(* leave *)"), (LineColumn{229, 35}));
  EXPECT_EQ(file_position_of(doc, file, " NOT A;"), (LineColumn{230, 5}));
  // The ':=' itself is file text the grammar does not see.
  EXPECT_EQ(doc.to_virtual_offset(static_cast<uint32_t>(file.find(":= A AND B"))), std::nullopt);
}

TEST(PlcOpenReader, CodesysApplicationInTheProjectAddData) {
  const std::string file = decoded_data("Codesys_application.xml");
  const ContainerDocument doc = read_plcopen(file);
  EXPECT_TRUE(doc.issues.empty());
  for (const std::string_view expected : {
           "CONFIGURATION Plant\nRESOURCE Plant ON PLC\n"
           "VAR_GLOBAL\n  nQos : INT := 1;\nEND_VAR\nVAR_GLOBAL\nEND_VAR\n"
           "  TASK MainTask(INTERVAL := T#0.05s, PRIORITY := 4);\n  TASK Background(PRIORITY := 15);\n"
           "  PROGRAM PLC_PRG WITH MainTask : PLC_PRG;\n  PROGRAM PLC_BG WITH Background : PLC_BG;\n"
           "END_RESOURCE\nEND_CONFIGURATION\n",
           "PROGRAM PLC_PRG\nVAR\n  dev : I_Device;\nEND_VAR\nIF dev <> 0 THEN\n\tdev.Poll();\nEND_IF\nEND_PROGRAM\n",
       }) {
    EXPECT_NE(doc.virtual_text.find(expected), std::string::npos) << "missing:\n" << expected;
  }
  // The resource's name maps to its attribute; the configuration's copy is synthetic.
  EXPECT_EQ(file_position_of(doc, file, "Plant", doc.virtual_text.find("RESOURCE")), (LineColumn{80, 23}));
  EXPECT_FALSE(doc.segment_at(static_cast<uint32_t>(doc.virtual_text.find("Plant\n")))->file_begin.has_value());
  EXPECT_EQ(find_object(doc, "Plant")->kind, "CONFIGURATION");

  // A broken initial value in a GVL of the application is now seen by the grammar.
  std::string broken = file;
  broken.replace(broken.find("value=\"1\""), 9, "value=\"1 +\"");
  const Document document = Document::from_bytes("Plant.xml", broken);
  ASSERT_FALSE(document.diagnostics().empty());
  const FilePosition p = document.position_of_file_offset(document.diagnostics().front().range.begin);
  EXPECT_EQ(p.line, 104u);
}

TEST(PlcOpenReader, CodesysInterfaces) {
  const std::string file = decoded_data("Codesys_application.xml");
  const ContainerDocument doc = read_plcopen(file);
  EXPECT_NE(doc.virtual_text.find("INTERFACE I_Device\nMETHOD Poll : BOOL\nEND_METHOD\n"
                                  "METHOD Process\nVAR_INPUT\n  pData : POINTER TO ARRAY [0..124] OF WORD;\nEND_VAR\n"
                                  "END_METHOD\nPROPERTY Id : INT\nGET\nEND_GET\nEND_PROPERTY\nEND_INTERFACE\n"
                                  "INTERFACE I_Bus EXTENDS I_Device\nEND_INTERFACE\n"),
            std::string::npos)
      << doc.virtual_text;
  EXPECT_EQ(file_position_of(doc, file, "I_Device"), (LineColumn{22, 24}));
  EXPECT_EQ(file_position_of(doc, file, "Poll"), (LineColumn{24, 25}));
  EXPECT_EQ(file_position_of(doc, file, "I_Device", doc.virtual_text.find("EXTENDS")), (LineColumn{73, 24}));
  EXPECT_EQ(find_object(doc, "I_Device")->kind, "INTERFACE");
  EXPECT_EQ(find_object(doc, "I_Device.Poll")->kind, "METHOD");
  EXPECT_EQ(find_object(doc, "I_Device.Id")->kind, "PROPERTY");
  const size_t end = doc.virtual_text.find("END_INTERFACE");
  EXPECT_EQ(doc.segment_at(static_cast<uint32_t>(end))->object_name, "I_Device");
}

TEST(PlcOpenReader, LessThanInAnAttributeValueIsReported) {
  const std::string file =
      "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n"
      "<!-- a <comment> with \"<quotes>\" -->\n"
      "<project xmlns=\"http://www.plcopen.org/xml/tc6_0200\">\n"
      "  <fileHeader companyName=\"\" productName=\"CODESYS\" creationDateTime=\"<NORMALIZED>\" />\n"
      "  <types><dataTypes /><pous><pou name=\"P\" pouType=\"program\">\n"
      "    <body><ST><xhtml xmlns=\"http://www.w3.org/1999/xhtml\">x := a &lt; b;</xhtml></ST></body>\n"
      "  </pou></pous></types>\n"
      "</project>\n";
  const ContainerDocument doc = read_plcopen(file);
  ASSERT_EQ(doc.issues.size(), 1u);
  EXPECT_EQ(doc.issues.front().message, "malformed XML at line 4: '<' inside an attribute value");
  EXPECT_EQ(doc.issues.front().offset, file.find("<NORMALIZED>"));
  // The rest is still read.
  EXPECT_NE(doc.virtual_text.find("PROGRAM P\nx := a < b;\nEND_PROGRAM\n"), std::string::npos) << doc.virtual_text;

  // '<' in CDATA, comments, text and single-quoted attributes with '>' are fine.
  for (const std::string_view fine : {
           std::string_view("<project a='x>y' b=\"1\"><![CDATA[<a b=\"<\">]]><!-- <x y=\"<\"> --></project>"),
           std::string_view("<?xml version=\"1.0\"?><!DOCTYPE project [<!ENTITY e \"<\">]><project/>"),
       }) {
    EXPECT_TRUE(read_plcopen(fine).issues.empty()) << fine;
  }
}

TEST(PlcOpenReader, VariableNamesThatAreNotIdentifiersAreReported) {
  const std::string file =
      "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n"
      "<project xmlns=\"http://www.plcopen.org/xml/tc6_0201\">\n"
      "  <types><dataTypes/><pous><pou name=\"P\" pouType=\"program\">\n"
      "    <interface><localVars>\n"
      "      <variable name=\"Input/OutputVariable\"><type><DINT/></type></variable>\n"
      "      <variable name=\"nOk\"><type><DINT/></type></variable>\n"
      "    </localVars></interface>\n"
      "    <body><FBD/></body>\n"
      "  </pou></pous></types>\n"
      "</project>\n";
  const ContainerDocument doc = read_plcopen(file);
  ASSERT_EQ(doc.issues.size(), 1u);
  EXPECT_EQ(doc.issues.front().message,
            "variable name 'Input/OutputVariable' is not an IEC identifier; the variable is left out");
  EXPECT_EQ(doc.issues.front().offset, file.find("Input/"));
  EXPECT_EQ(doc.virtual_text, "PROGRAM P\nVAR\n  nOk : DINT;\nEND_VAR\nEND_PROGRAM\n");
  const Document document = Document::from_bytes("plc.xml", file);
  ASSERT_EQ(document.diagnostics().size(), 1u);
  EXPECT_EQ(document.diagnostics().front().code, codes::kContainer);
}

TEST(PlcOpenReader, CommentsBeforeTheRootAreSkippedWhole) {
  EXPECT_TRUE(
      looks_like_plcopen("<?xml version=\"1.0\"?>\n<!-- Methods live in the <addData> block. -->\n"
                         "<project xmlns=\"http://www.plcopen.org/xml/tc6_0200\"/>"));
  EXPECT_TRUE(
      looks_like_plcopen("<!DOCTYPE project [<!ENTITY e \"<x>\">]>\n<!--a--><!--<b>-->"
                         "<project xmlns=\"http://www.plcopen.org/xml/tc6_0201\"/>"));
  EXPECT_FALSE(looks_like_plcopen("<!-- <project xmlns=\"http://www.plcopen.org/xml/tc6_0201\"> -->\n<other/>"));
  EXPECT_FALSE(looks_like_plcopen("<!-- never closed <project xmlns=\"http://www.plcopen.org/xml/tc6_0201\">"));
  EXPECT_EQ(detect_container("FB_TEMPLATE.xml", decoded_data("Codesys_application.xml")), ContainerKind::PlcOpen);
  EXPECT_EQ(detect_container("plc.xml", decoded_data("Beremiz_quirks.xml")), ContainerKind::PlcOpen);
}

}  // namespace
}  // namespace rung::containers
