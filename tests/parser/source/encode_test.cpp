#include "parser/source/encode.hpp"

#include <gtest/gtest.h>

#include "parser/source/decode.hpp"

namespace rung::source {
namespace {

using namespace std::string_literals;

TEST(Encode, Utf8WithAndWithoutBom) {
  EXPECT_EQ(encode("x\xC3\xA4", Encoding::Utf8, false), "x\xC3\xA4");
  EXPECT_EQ(encode("x\xC3\xA4", Encoding::Utf8, true), "\xEF\xBB\xBFx\xC3\xA4");
}

TEST(Encode, Cp1252RoundTripsUmlautAndEuro) {
  EXPECT_EQ(encode("(* Z\xC3\xA4hler \xE2\x82\xAC *)", Encoding::Cp1252, false), "(* Z\xE4hler \x80 *)");
}

TEST(Encode, Cp1252IgnoresTheBomFlag) {
  EXPECT_EQ(encode("a", Encoding::Cp1252, true), "a");
}

TEST(Encode, Cp1252CannotWriteOmega) {
  const std::string text = "x := 1; (* 10 \xCE\xA9 *)";  // Ω U+03A9
  EXPECT_EQ(encode(text, Encoding::Cp1252, false), std::nullopt);
  EXPECT_EQ(first_unencodable(text, Encoding::Cp1252), 14u);
  EXPECT_EQ(first_unencodable(text, Encoding::Utf8), std::nullopt);
}

TEST(Encode, Cp1252CannotWriteReplacementCharacter) {
  EXPECT_EQ(encode("a\xEF\xBF\xBD", Encoding::Cp1252, false), std::nullopt);
}

TEST(Encode, InvalidUtf8InputFails) {
  EXPECT_EQ(encode("a\xFF", Encoding::Utf8, false), std::nullopt);
  EXPECT_EQ(encode("a\xFF", Encoding::Utf16Le, false), std::nullopt);
  EXPECT_EQ(first_unencodable("a\xFF", Encoding::Utf8), 1u);
}

TEST(Encode, Utf16LeWithBomAndSurrogatePair) {
  EXPECT_EQ(encode("A\xF0\x9F\x98\x80", Encoding::Utf16Le, true),
            "\xFF\xFE"
            "A\x00"
            "\x3D\xD8\x00\xDE"s);
}

TEST(Encode, Utf16BeWithoutBom) {
  EXPECT_EQ(encode("A\xE2\x82\xAC", Encoding::Utf16Be, false),
            "\x00"
            "A\x20\xAC"s);
}

TEST(Encode, DecodeThenEncodeGivesTheOriginalBytes) {
  const std::string cp1252 = "(* \xC4nderung: \x80 5 \x96 6 *)\r\n";
  const DecodedText decoded = decode(cp1252);
  ASSERT_EQ(decoded.encoding, Encoding::Cp1252);
  EXPECT_EQ(encode(decoded.utf8, decoded.encoding, decoded.had_bom), cp1252);

  const std::string utf16 =
      "\xFF\xFE"
      "x\x00\xE4\x00"s;
  const DecodedText decoded16 = decode(utf16);
  EXPECT_EQ(encode(decoded16.utf8, decoded16.encoding, decoded16.had_bom), utf16);
}

}  // namespace
}  // namespace rung::source
