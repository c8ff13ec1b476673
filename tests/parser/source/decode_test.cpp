#include "parser/source/decode.hpp"

#include <gtest/gtest.h>

#include <random>
#include <string>

namespace rung::source {
namespace {

using namespace std::string_literals;

TEST(Decode, EmptyFileIsEmptyUtf8) {
  const DecodedText d = decode("");
  EXPECT_EQ(d.utf8, "");
  EXPECT_EQ(d.encoding, Encoding::Utf8);
  EXPECT_FALSE(d.had_bom);
  EXPECT_FALSE(d.is_binary);
  EXPECT_TRUE(d.issues.empty());
}

TEST(Decode, PlainAsciiPassesThrough) {
  const DecodedText d = decode("PROGRAM Main\nEND_PROGRAM\n");
  EXPECT_EQ(d.utf8, "PROGRAM Main\nEND_PROGRAM\n");
  EXPECT_EQ(d.encoding, Encoding::Utf8);
  EXPECT_TRUE(d.issues.empty());
}

TEST(Decode, FileOfOnlyCrLfIsText) {
  const DecodedText d = decode("\r\n\r\n\r\n");
  EXPECT_FALSE(d.is_binary);
  EXPECT_EQ(d.utf8, "\r\n\r\n\r\n");
}

TEST(Decode, Utf8BomIsDroppedAndRemembered) {
  const DecodedText d = decode("\xEF\xBB\xBFx := 1; (* \xC3\xA4 *)");
  EXPECT_TRUE(d.had_bom);
  EXPECT_EQ(d.encoding, Encoding::Utf8);
  EXPECT_EQ(d.utf8, "x := 1; (* \xC3\xA4 *)");
}

TEST(Decode, BomOnlyFileIsEmptyText) {
  const DecodedText d = decode("\xEF\xBB\xBF");
  EXPECT_TRUE(d.had_bom);
  EXPECT_EQ(d.utf8, "");
  EXPECT_FALSE(d.is_binary);
}

TEST(Decode, ValidUtf8WithoutBomStaysUtf8) {
  const DecodedText d = decode("s := 'Gr\xC3\xBC\xC3\x9F' ; (* \xE2\x82\xAC \xF0\x9F\x98\x80 *)");
  EXPECT_EQ(d.encoding, Encoding::Utf8);
  EXPECT_FALSE(d.had_bom);
  EXPECT_EQ(d.utf8, "s := 'Gr\xC3\xBC\xC3\x9F' ; (* \xE2\x82\xAC \xF0\x9F\x98\x80 *)");
  EXPECT_TRUE(d.issues.empty());
}

TEST(Decode, Cp1252UmlautAndEuro) {
  // "(* Zähler € *)" as CODESYS V2 writes it: ä = 0xE4, € = 0x80.
  const DecodedText d = decode("(* Z\xE4hler \x80 *)");
  EXPECT_EQ(d.encoding, Encoding::Cp1252);
  EXPECT_EQ(d.utf8, "(* Z\xC3\xA4hler \xE2\x82\xAC *)");
  EXPECT_TRUE(d.issues.empty());
}

TEST(Decode, Cp1252WholeHighBlockUsesTheRealTable) {
  // 0x8A 0x9C 0x9F 0x99 0x85: Š œ Ÿ ™ …
  const DecodedText d = decode("x\x8A\x9C\x9F\x99\x85");
  EXPECT_EQ(d.encoding, Encoding::Cp1252);
  EXPECT_EQ(d.utf8, "x\xC5\xA0\xC5\x93\xC5\xB8\xE2\x84\xA2\xE2\x80\xA6");
}

TEST(Decode, Cp1252UndefinedBytesBecomeReplacementWithIssue) {
  const DecodedText d = decode(
      "a\x81"
      "b\x8D"
      "c\x8F"
      "d\x90"
      "e\x9D");
  EXPECT_EQ(d.encoding, Encoding::Cp1252);
  const std::string fffd = "\xEF\xBF\xBD";
  EXPECT_EQ(d.utf8, "a" + fffd + "b" + fffd + "c" + fffd + "d" + fffd + "e" + fffd);
  ASSERT_EQ(d.issues.size(), 5u);
  EXPECT_EQ(d.issues[0].offset, 1u);
  EXPECT_EQ(d.issues[0].message, "byte 0x81 is undefined in cp1252; replaced by U+FFFD");
  EXPECT_EQ(d.issues[1].offset, 5u);
  EXPECT_EQ(d.issues[4].message, "byte 0x9D is undefined in cp1252; replaced by U+FFFD");
}

TEST(Decode, Latin1RangeBytesMapToSameCodePoint) {
  const DecodedText d = decode("\xA0\xB0\xFF");
  EXPECT_EQ(d.encoding, Encoding::Cp1252);
  EXPECT_EQ(d.utf8, "\xC2\xA0\xC2\xB0\xC3\xBF");
}

TEST(Decode, OverlongUtf8IsNotUtf8) {
  // C0 AF is an overlong '/'; with nothing else multibyte, the file is cp1252.
  const DecodedText d = decode(
      "a\xC0\xAF"
      "b");
  EXPECT_EQ(d.encoding, Encoding::Cp1252);
  EXPECT_EQ(d.utf8,
            "a\xC3\x80\xC2\xAF"
            "b");
}

TEST(Decode, MostlyUtf8WithOneBadByteStaysUtf8) {
  // Three good multibyte characters and one stray byte: a damaged UTF-8 file.
  const DecodedText d = decode("\xC3\xA4\xC3\xB6\xC3\xBC x \xFF y");
  EXPECT_EQ(d.encoding, Encoding::Utf8);
  EXPECT_EQ(d.utf8, "\xC3\xA4\xC3\xB6\xC3\xBC x \xEF\xBF\xBD y");
  ASSERT_EQ(d.issues.size(), 1u);
  EXPECT_EQ(d.issues[0].offset, 9u);
  EXPECT_EQ(d.issues[0].message, "invalid UTF-8 byte 0xFF replaced by U+FFFD");
}

TEST(Decode, BomForcesUtf8AndReplacesSurrogatesAndTruncation) {
  // ED A0 80 encodes a surrogate (invalid); E2 82 is a truncated euro sign at the end.
  const DecodedText d = decode(
      "\xEF\xBB\xBF"
      "a\xED\xA0\x80"
      "b\xE2\x82");
  EXPECT_EQ(d.encoding, Encoding::Utf8);
  EXPECT_TRUE(d.had_bom);
  // Maximal subparts: ED, A0, 80 are three separate errors; E2 82 is one.
  const std::string fffd = "\xEF\xBF\xBD";
  EXPECT_EQ(d.utf8, "a" + fffd + fffd + fffd + "b" + fffd);
  EXPECT_EQ(d.issues.size(), 4u);
}

TEST(Decode, BomWithOverlongSequenceReplacesIt) {
  const DecodedText d = decode("\xEF\xBB\xBF\xE0\x80\xAFz");
  const std::string fffd = "\xEF\xBF\xBD";
  EXPECT_EQ(d.utf8, fffd + fffd + fffd + "z");
}

TEST(Decode, Utf16LittleEndianWithBom) {
  // "A€😀\r\n" in UTF-16LE with BOM.
  const std::string bytes =
      "\xFF\xFE"
      "A\x00"
      "\xAC\x20"
      "\x3D\xD8\x00\xDE"
      "\r\x00\n\x00"s;
  const DecodedText d = decode(bytes);
  EXPECT_EQ(d.encoding, Encoding::Utf16Le);
  EXPECT_TRUE(d.had_bom);
  EXPECT_FALSE(d.is_binary);
  EXPECT_EQ(d.utf8, "A\xE2\x82\xAC\xF0\x9F\x98\x80\r\n");
  EXPECT_TRUE(d.issues.empty());
}

TEST(Decode, Utf16BigEndianWithBom) {
  const std::string bytes =
      "\xFE\xFF"
      "\x00P\x00L\x00"
      "C"s;
  const DecodedText d = decode(bytes);
  EXPECT_EQ(d.encoding, Encoding::Utf16Be);
  EXPECT_EQ(d.utf8, "PLC");
}

TEST(Decode, Utf16WithoutBomIsRecognised) {
  std::string bytes;
  for (const char c : std::string("PROGRAM Main\r\nEND_PROGRAM\r\n")) {
    bytes.push_back(c);
    bytes.push_back('\0');
  }
  const DecodedText d = decode(bytes);
  EXPECT_EQ(d.encoding, Encoding::Utf16Le);
  EXPECT_FALSE(d.had_bom);
  EXPECT_FALSE(d.is_binary);
  EXPECT_EQ(d.utf8, "PROGRAM Main\r\nEND_PROGRAM\r\n");
}

TEST(Decode, Utf16UnpairedSurrogateAndOddLength) {
  const std::string bytes =
      "\xFF\xFE"
      "\x00\xD8"
      "A\x00"
      "B"s;  // lone high surrogate, 'A', half a unit
  const DecodedText d = decode(bytes);
  EXPECT_EQ(d.utf8,
            "\xEF\xBF\xBD"
            "A\xEF\xBF\xBD");
  ASSERT_EQ(d.issues.size(), 2u);
  EXPECT_EQ(d.issues[0].message, "unpaired UTF-16 surrogate 0xD800 replaced by U+FFFD");
  EXPECT_EQ(d.issues[0].offset, 0u);
  EXPECT_EQ(d.issues[1].message, "UTF-16 file ends in the middle of a code unit");
  EXPECT_EQ(d.issues[1].offset, 4u);
}

TEST(Decode, PngHeaderIsBinary) {
  const std::string png = "\x89PNG\r\n\x1A\n\x00\x00\x00\rIHDR\x00\x00\x01\x00"s;
  const DecodedText d = decode(png);
  EXPECT_TRUE(d.is_binary);
  EXPECT_EQ(d.utf8, "");
}

TEST(Decode, RandomBytesAreBinary) {
  std::mt19937 rng(42);
  std::string bytes(4096, '\0');
  for (char& c : bytes) c = static_cast<char>(rng() & 0xFF);
  EXPECT_TRUE(decode(bytes).is_binary);
}

TEST(Decode, ManyControlCharactersWithoutNulAreBinary) {
  std::string bytes;
  for (int i = 0; i < 100; ++i) bytes += "ab\x01\x02\x03";
  EXPECT_TRUE(decode(bytes).is_binary);
}

TEST(Decode, TabsFormFeedsAndDosEofAreText) {
  const DecodedText d = decode("\tx := 1;\f\r\n\x1A");
  EXPECT_FALSE(d.is_binary);
  EXPECT_EQ(d.utf8, "\tx := 1;\f\r\n\x1A");
}

TEST(Decode, Utf16ThatDecodesToControlsIsBinary) {
  const std::string bytes =
      "\xFF\xFE"
      "\x01\x00\x02\x00\x03\x00\x00\x00"s;
  EXPECT_TRUE(decode(bytes).is_binary);
}

TEST(Decode, IssuesAreCappedWithASummary) {
  std::string bytes;
  for (int i = 0; i < 500; ++i) bytes += "x\x81";
  const DecodedText d = decode(bytes);
  ASSERT_EQ(d.issues.size(), max_decode_issues + 1);
  EXPECT_EQ(d.issues.back().message, "400 more encoding problems not listed");
}

TEST(Decode, LargeInputDecodesCompletely) {
  // Correctness on a big buffer (speed is measured in bench/, not here).
  std::string big;
  const std::string line = "    nCounter := nCounter + 1; (* Z\xC3\xA4hler *)\r\n";
  while (big.size() < size_t{4} * 1024 * 1024) big += line;
  const DecodedText d = decode(big);
  EXPECT_EQ(d.encoding, Encoding::Utf8);
  EXPECT_EQ(d.utf8.size(), big.size());
  EXPECT_EQ(d.utf8, big);
}

TEST(Decode, EncodingNames) {
  EXPECT_EQ(encoding_name(Encoding::Utf8), "UTF-8");
  EXPECT_EQ(encoding_name(Encoding::Cp1252), "cp1252");
  EXPECT_EQ(encoding_name(Encoding::Utf16Le), "UTF-16LE");
  EXPECT_EQ(encoding_name(Encoding::Utf16Be), "UTF-16BE");
}

}  // namespace
}  // namespace rung::source

namespace rung::source {
namespace {

TEST(Decode, TrailingNulPaddingIsDroppedWithAWarning) {
  std::string bytes = "PROGRAM P\nEND_PROGRAM\n";
  bytes.append(6, '\0');
  DecodedText d = decode(bytes);
  EXPECT_FALSE(d.is_binary);
  EXPECT_EQ(d.utf8, "PROGRAM P\nEND_PROGRAM\n");
  ASSERT_EQ(d.issues.size(), 1u);
  EXPECT_NE(d.issues[0].message.find("6 NUL bytes"), std::string::npos);
  // NULs inside the text still make it binary.
  std::string inner("PROG\0RAM P\n", 11);
  inner.append(4, '\0');
  EXPECT_TRUE(decode(std::string_view(inner.data(), inner.size())).is_binary);
}

}  // namespace
}  // namespace rung::source
