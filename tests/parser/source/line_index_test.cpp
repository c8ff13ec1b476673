#include "parser/source/line_index.hpp"

#include <gtest/gtest.h>

#include <string>

namespace rung::source {
namespace {

Position pos(uint32_t line, uint32_t byte, uint32_t ch, uint32_t utf16) {
  return {line, byte, ch, utf16};
}

TEST(LineIndex, EmptyTextHasOneEmptyLine) {
  const LineIndex index("");
  EXPECT_EQ(index.line_count(), 1u);
  EXPECT_EQ(index.line_start(0), 0u);
  EXPECT_EQ(index.line_end(0), 0u);
  EXPECT_EQ(index.position_of(0), pos(0, 0, 0, 0));
  EXPECT_EQ(index.position_of(100), pos(0, 0, 0, 0));
}

TEST(LineIndex, MixedLineEnds) {
  const std::string text = "a\nbb\r\nccc\rdddd";
  const LineIndex index(text);
  ASSERT_EQ(index.line_count(), 4u);
  EXPECT_EQ(index.line_start(1), 2u);
  EXPECT_EQ(index.line_start(2), 6u);
  EXPECT_EQ(index.line_start(3), 10u);
  EXPECT_EQ(index.line_end(0), 1u);
  EXPECT_EQ(index.line_end(1), 4u);  // before "\r\n"
  EXPECT_EQ(index.line_end(2), 9u);  // before the lone "\r"
  EXPECT_EQ(index.line_end(3), 14u);
  EXPECT_EQ(index.line_text(text, 1), "bb");
  EXPECT_EQ(index.line_text(text, 2), "ccc");
  EXPECT_EQ(index.line_text(text, 3), "dddd");
  EXPECT_EQ(index.position_of(7), pos(2, 1, 1, 1));
  EXPECT_EQ(index.position_of(4), pos(1, 2, 2, 2));  // on the '\r' of "\r\n"
}

TEST(LineIndex, TrailingTerminatorGivesEmptyLastLine) {
  const std::string text = "x\r\n";
  const LineIndex index(text);
  EXPECT_EQ(index.line_count(), 2u);
  EXPECT_EQ(index.line_start(1), 3u);
  EXPECT_EQ(index.line_text(text, 1), "");
  EXPECT_EQ(index.position_of(3), pos(1, 0, 0, 0));
}

TEST(LineIndex, OnlyCrLf) {
  const std::string text = "\r\n\r\n";
  const LineIndex index(text);
  EXPECT_EQ(index.line_count(), 3u);
  EXPECT_EQ(index.line_end(0), 0u);
  EXPECT_EQ(index.line_end(1), 2u);
  EXPECT_EQ(index.position_of(2), pos(1, 0, 0, 0));
}

TEST(LineIndex, CrCrLfIsTwoLineEnds) {
  const LineIndex index("a\r\r\nb");
  EXPECT_EQ(index.line_count(), 3u);
  EXPECT_EQ(index.line_start(2), 4u);
}

TEST(LineIndex, MultibyteAndAstralColumns) {
  // "ä€😀x": ä 2 bytes, € 3 bytes, 😀 4 bytes (a UTF-16 surrogate pair).
  const std::string text = "q\n\xC3\xA4\xE2\x82\xAC\xF0\x9F\x98\x80x";
  const LineIndex index(text);
  EXPECT_EQ(index.position_of(2), pos(1, 0, 0, 0));
  EXPECT_EQ(index.position_of(4), pos(1, 2, 1, 1));   // at €
  EXPECT_EQ(index.position_of(7), pos(1, 5, 2, 2));   // at 😀
  EXPECT_EQ(index.position_of(11), pos(1, 9, 3, 4));  // at x: the emoji counts 2 in UTF-16
  EXPECT_EQ(index.position_of(12), pos(1, 10, 4, 5));
}

TEST(LineIndex, MidCodepointOffsetsRoundDown) {
  const std::string text = "\xC3\xA4\xF0\x9F\x98\x80";
  const LineIndex index(text);
  EXPECT_EQ(index.position_of(1), pos(0, 0, 0, 0));
  EXPECT_EQ(index.position_of(3), pos(0, 2, 1, 1));
  EXPECT_EQ(index.position_of(5), pos(0, 2, 1, 1));
  EXPECT_EQ(index.position_of(6), pos(0, 6, 2, 3));
}

TEST(LineIndex, OffsetsPastTheEndClamp) {
  const LineIndex index("ab\ncd");
  EXPECT_EQ(index.position_of(99), pos(1, 2, 2, 2));
}

TEST(LineIndex, OffsetOfUtf16) {
  const std::string text = "q\n\xC3\xA4\xE2\x82\xAC\xF0\x9F\x98\x80x\r\nz";
  const LineIndex index(text);
  EXPECT_EQ(index.offset_of_utf16(1, 0), 2u);
  EXPECT_EQ(index.offset_of_utf16(1, 1), 4u);
  EXPECT_EQ(index.offset_of_utf16(1, 2), 7u);
  EXPECT_EQ(index.offset_of_utf16(1, 3), 7u);  // inside the surrogate pair: rounds down
  EXPECT_EQ(index.offset_of_utf16(1, 4), 11u);
  EXPECT_EQ(index.offset_of_utf16(1, 5), 12u);   // line end
  EXPECT_EQ(index.offset_of_utf16(1, 50), 12u);  // clamps before "\r\n"
  EXPECT_EQ(index.offset_of_utf16(9, 0), 14u);   // line clamps to the last
  EXPECT_EQ(index.offset_of_utf16(2, 1), 15u);
}

TEST(LineIndex, OffsetOfChar) {
  const std::string text = "\xC3\xA4\xE2\x82\xAC\xF0\x9F\x98\x80x";
  const LineIndex index(text);
  EXPECT_EQ(index.offset_of_char(0, 0), 0u);
  EXPECT_EQ(index.offset_of_char(0, 1), 2u);
  EXPECT_EQ(index.offset_of_char(0, 2), 5u);
  EXPECT_EQ(index.offset_of_char(0, 3), 9u);
  EXPECT_EQ(index.offset_of_char(0, 4), 10u);
  EXPECT_EQ(index.offset_of_char(0, 40), 10u);
}

TEST(LineIndex, RoundTripEveryCharacter) {
  const std::string text = "a\xC3\xA4\r\n\xF0\x9F\x98\x80\rb\xE2\x82\xAC\nc";
  const LineIndex index(text);
  for (uint32_t offset = 0; offset <= text.size(); ++offset) {
    if (offset < text.size() && (static_cast<unsigned char>(text[offset]) & 0xC0) == 0x80) continue;
    const Position p = index.position_of(offset);
    if (p.byte_column > index.line_end(p.line) - index.line_start(p.line)) continue;  // on a terminator
    EXPECT_EQ(index.offset_of_utf16(p.line, p.utf16_column), offset) << offset;
    EXPECT_EQ(index.offset_of_char(p.line, p.char_column), offset) << offset;
  }
}

TEST(LineIndex, InvalidUtf8CountsOneColumnPerBadByte) {
  const std::string text = "\xFF\xFEx";
  const LineIndex index(text);
  EXPECT_EQ(index.position_of(2), pos(0, 2, 2, 2));
}

}  // namespace
}  // namespace rung::source
