#include "parser/containers/detect.hpp"

#include <gtest/gtest.h>

#include <random>

#include "container_test_support.hpp"
#include "parser/containers/read_container.hpp"

namespace rung::containers {
namespace {

TEST(DetectContainer, ByExtensionCaseInsensitive) {
  EXPECT_EQ(detect_container("src/POUs/FB_Motor.TcPOU", ""), ContainerKind::TwinCat);
  EXPECT_EQ(detect_container("x.tcpou", ""), ContainerKind::TwinCat);
  EXPECT_EQ(detect_container("x.TcDUT", ""), ContainerKind::TwinCat);
  EXPECT_EQ(detect_container("x.TcGVL", ""), ContainerKind::TwinCat);
  EXPECT_EQ(detect_container("x.TcIO", ""), ContainerKind::TwinCat);
  EXPECT_EQ(detect_container("x.TcITF", ""), ContainerKind::TwinCat);
  EXPECT_EQ(detect_container("PlcTask.TcTTO", ""), ContainerKind::Unsupported);
  EXPECT_EQ(detect_container("Visu.TcVIS", ""), ContainerKind::Unsupported);
  EXPECT_EQ(detect_container("OSCAT_BASIC_335.EXP", ""), ContainerKind::CodesysExp);
  EXPECT_EQ(detect_container("C:\\proj\\export.exp", ""), ContainerKind::CodesysExp);
  EXPECT_EQ(detect_container("main.st", "PROGRAM Main"), ContainerKind::None);
  EXPECT_EQ(detect_container("noextension", ""), ContainerKind::None);
  EXPECT_EQ(detect_container("dir.TcPOU/file.st", ""), ContainerKind::None);
}

TEST(DetectContainer, ByContent) {
  EXPECT_EQ(detect_container("object.xml", "<?xml version=\"1.0\"?>\r\n<TcPlcObject Version=\"1.1.0.1\">"),
            ContainerKind::TwinCat);
  EXPECT_EQ(detect_container("object.xml", "<project xmlns=\"http://www.plcopen.org/xml/tc6_0200\">"),
            ContainerKind::PlcOpen);
  EXPECT_EQ(detect_container("pom.xml", "<project xmlns=\"http://maven.apache.org/POM/4.0.0\">"), ContainerKind::None);
  EXPECT_EQ(detect_container("lib.txt", "\r\n(* @NESTEDCOMMENTS := 'Yes' *)\r\nPROGRAM P"), ContainerKind::CodesysExp);
  EXPECT_EQ(detect_container("a.st", "(* <TcPlcObject> in a comment *)"), ContainerKind::None);
}

TEST(ReadContainer, Dispatches) {
  const std::string pou = testing::decoded_data("FB_Motor.TcPOU");
  const ContainerDocument twincat = read_container("FB_Motor.TcPOU", pou);
  EXPECT_EQ(twincat.kind, ContainerKind::TwinCat);
  EXPECT_TRUE(twincat.virtual_text.starts_with("FUNCTION_BLOCK FB_Motor"));

  const ContainerDocument exp = read_container("Project.EXP", testing::decoded_data("Project.EXP"));
  EXPECT_EQ(exp.kind, ContainerKind::CodesysExp);
  EXPECT_EQ(exp.objects.size(), 8u);

  const ContainerDocument task = read_container("PlcTask.TcTTO", testing::decoded_data("PlcTask.TcTTO"));
  EXPECT_EQ(task.kind, ContainerKind::Unsupported);
  EXPECT_EQ(task.virtual_text, "");

  const ContainerDocument plain = read_container("main.st", "PROGRAM Main\nEND_PROGRAM\n");
  EXPECT_EQ(plain.kind, ContainerKind::None);
  EXPECT_EQ(plain.virtual_text, "PROGRAM Main\nEND_PROGRAM\n");
  EXPECT_EQ(plain.to_file_offset(8), 8u);
}

// The readers must survive whatever a damaged or foreign file holds: random
// bytes, and real files with bytes flipped or cut anywhere.
TEST(ReadContainer, SurvivesDamagedInput) {
  std::mt19937 rng(7);
  const std::string pou = testing::decoded_data("FB_Motor.TcPOU");
  const std::string exp = testing::decoded_data("Project.EXP");
  const std::string alphabet = "<>![]CDATA/=\"'&;#x(*@)_ \r\nEND_PROGRAM";
  for (int round = 0; round < 300; ++round) {
    std::string a = pou, b = exp;
    for (int k = 0; k < 5; ++k) {
      a[rng() % a.size()] = alphabet[rng() % alphabet.size()];
      b[rng() % b.size()] = alphabet[rng() % alphabet.size()];
    }
    a.resize(rng() % (a.size() + 1));
    b.resize(rng() % (b.size() + 1));
    std::string noise(rng() % 200, '\0');
    for (char& c : noise) c = alphabet[rng() % alphabet.size()];
    for (const std::string* text : {&a, &b, &noise}) {
      for (const char* name : {"x.TcPOU", "x.EXP"}) {
        const ContainerDocument doc = read_container(name, *text);
        // Whatever came out, every virtual byte maps somewhere inside the file.
        for (uint32_t v = 0; v <= doc.virtual_text.size(); v += 7) {
          const auto f = doc.to_file_offset(v);
          if (f) {
            ASSERT_LE(*f, text->size());
          }
        }
      }
    }
  }
}

TEST(ReadContainer, UnderscoreOnlySectionWord) {
  const ContainerDocument doc = read_container("x.EXP", "___\nEND_\n");
  ASSERT_EQ(doc.objects.size(), 1u);
  EXPECT_EQ(doc.objects[0].kind, "___");
  EXPECT_EQ(doc.virtual_text, "   \n    \n");
}

}  // namespace
}  // namespace rung::containers
