// vcs::read_objects and vcs::text_view: what a file declares, in the normal form `rung diff`
// compares, and the ST text `rung textconv` prints.
#include "vcs/object_model.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "tests/support/test_paths.hpp"

namespace rung::vcs {
namespace {

std::string motor() {
  return test::read_file(test::source_dir() / "tests/parser/containers/data/FB_Motor.TcPOU");
}

std::vector<std::string> part_names(const Object& object) {
  std::vector<std::string> names;
  for (const Part& part : object.parts) names.push_back(part.kind + " " + part.name);
  return names;
}

TEST(ObjectModel, TwinCatPouWithItsMembersInOrder) {
  const FileObjects file = read_objects("FB_Motor.TcPOU", motor());
  EXPECT_TRUE(file.errors.empty());
  ASSERT_EQ(file.objects.size(), 1u);
  const Object& fb = file.objects[0];
  EXPECT_EQ(fb.kind, "FUNCTION_BLOCK");
  EXPECT_EQ(fb.name, "FB_Motor");
  EXPECT_EQ(part_names(fb),
            (std::vector<std::string>{"FUNCTION_BLOCK ", "METHOD M_Start", "PROPERTY P_Speed", "GET P_Speed.GET",
                                      "SET P_Speed.SET", "ACTION A_Reset", "TRANSITION T_Done"}));
  ASSERT_EQ(fb.parts[0].declarations.size(), 4u);
  const Declaration& enable = fb.parts[0].declarations[0];
  EXPECT_EQ(enable.block, "VAR_INPUT");
  EXPECT_EQ(enable.name, "bEnable");
  EXPECT_EQ(enable.type_key, "BOOL");
  EXPECT_EQ(enable.text, "bEnable : BOOL");
  EXPECT_EQ(fb.parts[0].body_key, "IF bEnable THEN nState := 1 ; END_IF bRunning := nState = 1 ;");
  EXPECT_EQ(fb.parts[1].body_text, "fSpeed := fTarget;\nM_Start := TRUE;\n");
}

TEST(ObjectModel, LineIdsGuidsLayoutAndKeywordCaseDoNotChangeTheKeys) {
  std::string other = motor();
  const auto replace = [&](const std::string& from, const std::string& to) {
    const size_t at = other.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    other.replace(at, from.size(), to);
  };
  replace("<LineId Id=\"3\" Count=\"2\" />", "<LineId Id=\"7\" Count=\"5\" />");
  replace("{8c1e1f7a-3b4c-4d5e-9f60-1a2b3c4d5e70}", "{11111111-3b4c-4d5e-9f60-1a2b3c4d5e70}");
  replace("IF bEnable THEN\r\n    nState := 1;", "if bEnable then nState:=1;");
  replace("// Freigabe für den Motor", "// a comment that changed");
  const FileObjects a = read_objects("FB_Motor.TcPOU", motor());
  const FileObjects b = read_objects("FB_Motor.TcPOU", other);
  ASSERT_EQ(a.objects.size(), 1u);
  ASSERT_EQ(b.objects.size(), 1u);
  EXPECT_EQ(a.objects[0].content_key(), b.objects[0].content_key());
  // With comments the changed comment counts.
  const FileObjects c = read_objects("FB_Motor.TcPOU", other, ReadOptions{true});
  const FileObjects d = read_objects("FB_Motor.TcPOU", motor(), ReadOptions{true});
  EXPECT_NE(c.objects[0].content_key(), d.objects[0].content_key());
  EXPECT_EQ(c.objects[0].parts[0].declarations[0].comment, "// a comment that changed");
}

TEST(ObjectModel, PlainStTypesGvlsAndAttributes) {
  const std::string text =
      "TYPE E_Mode : (Off := 0, Auto := 1); END_TYPE\n"
      "TYPE ST_Cfg : STRUCT\n  a : INT := 3;\nEND_STRUCT\nEND_TYPE\n"
      "VAR_GLOBAL CONSTANT\n  {attribute 'hide'}\n  cMax : INT := 10;\nEND_VAR\n"
      "FUNCTION F_Twice : INT\nVAR_INPUT x : INT; END_VAR\nF_Twice := 2 * x;\nEND_FUNCTION\n";
  const FileObjects file = read_objects("src/Globals.st", text);
  ASSERT_EQ(file.objects.size(), 4u);
  EXPECT_EQ(file.objects[0].kind + " " + file.objects[0].name, "TYPE E_Mode");
  ASSERT_EQ(file.objects[0].parts[0].declarations.size(), 2u);
  EXPECT_EQ(file.objects[0].parts[0].declarations[1].block, "ENUM");
  EXPECT_EQ(file.objects[0].parts[0].declarations[1].value_key, "1");
  EXPECT_EQ(file.objects[1].kind + " " + file.objects[1].name, "TYPE ST_Cfg");
  EXPECT_EQ(file.objects[1].parts[0].declarations[0].value_key, "3");
  EXPECT_EQ(file.objects[2].kind + " " + file.objects[2].name, "GVL Globals");
  ASSERT_EQ(file.objects[2].parts[0].declarations.size(), 1u);
  EXPECT_EQ(file.objects[2].parts[0].declarations[0].block, "VAR_GLOBAL CONSTANT");
  EXPECT_EQ(file.objects[2].parts[0].declarations[0].attributes, "{attribute 'hide'}");
  EXPECT_EQ(file.objects[3].kind + " " + file.objects[3].name, "FUNCTION F_Twice");
  // The function's own name in its body is written \x01 in the keys (renames match by content).
  EXPECT_EQ(file.objects[3].parts[0].body_key, "\x01 := 2 * x ;");
}

TEST(ObjectModel, HostileInputsGiveErrorsNotCrashes) {
  const FileObjects broken = read_objects("FB_Broken.TcPOU", "<?xml version=\"1.0\"?>\n<TcPlcObject><POU Name=\"X\">");
  ASSERT_FALSE(broken.errors.empty());
  EXPECT_NE(broken.errors[0].find("malformed XML"), std::string::npos) << broken.errors[0];
  const FileObjects binary = read_objects("a.st", std::string("\x00\x01\x02\x03garbage\x00", 12));
  EXPECT_EQ(binary.errors, std::vector<std::string>{"binary file; not PLC source"});
  EXPECT_TRUE(binary.objects.empty());
  const FileObjects empty = read_objects("empty.st", "");
  EXPECT_TRUE(empty.objects.empty());
  EXPECT_TRUE(empty.errors.empty());
}

TEST(TextView, TwinCatFileAsStText) {
  const TextView view = text_view("FB_Motor.TcPOU", motor());
  EXPECT_TRUE(view.errors.empty());
  EXPECT_EQ(view.text,
            "FUNCTION_BLOCK FB_Motor\n"
            "VAR_INPUT\n"
            "\tbEnable : BOOL; // Freigabe für den Motor\n"
            "END_VAR\n"
            "VAR_OUTPUT\n"
            "\tbRunning : BOOL;\n"
            "END_VAR\n"
            "VAR\n"
            "\tnState : INT;\n"
            "\tfSpeed : LREAL;\n"
            "END_VAR\n"
            "\n"
            "IF bEnable THEN\n"
            "\tnState := 1;\n"
            "END_IF\n"
            "bRunning := nState = 1;\n"
            "METHOD M_Start : BOOL\n"
            "VAR_INPUT\n"
            "\tfTarget : LREAL;\n"
            "END_VAR\n"
            "\n"
            "fSpeed := fTarget;\n"
            "M_Start := TRUE;\n"
            "PROPERTY P_Speed : LREAL\n"
            "GET\n"
            "VAR\n"
            "END_VAR\n"
            "\n"
            "P_Speed := fSpeed;\n"
            "SET\n"
            "VAR\n"
            "END_VAR\n"
            "\n"
            "fSpeed := P_Speed;\n"
            "ACTION A_Reset:\n"
            "nState := 0;\n"
            "fSpeed := 0;\n"
            "TRANSITION T_Done:\n"
            "\tnState = 2\n");
}

TEST(TextView, CodesysExportWithoutMarkersAndPlcOpenAsSt) {
  const std::string data = (test::source_dir() / "tests/parser/containers/data").string();
  const TextView exp = text_view("FB_Client.EXP", test::read_file(data + "/FB_Client.EXP"));
  EXPECT_TRUE(exp.errors.empty());
  EXPECT_EQ(exp.text.find("(* @"), std::string::npos);
  EXPECT_EQ(exp.text.rfind("(*\tA client block; its comment sits between the markers and the header.\n", 0), 0u)
      << exp.text;
  const TextView xml = text_view("Small_plcopen.xml", test::read_file(data + "/Small_plcopen.xml"));
  EXPECT_EQ(
      xml.text.rfind("TYPE E_Mode : (Off := 0, Auto := 1); END_TYPE\nPROGRAM Blink\nVAR_INPUT\n\txOn : BOOL;\n", 0), 0u)
      << xml.text;
}

}  // namespace
}  // namespace rung::vcs
