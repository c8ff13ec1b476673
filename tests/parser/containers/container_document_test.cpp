#include "parser/containers/container_document.hpp"

#include <gtest/gtest.h>

namespace rung::containers {
namespace {

// "AB" from file offset 10, synthetic "--", "CD" from file offset 3 (out of file order).
ContainerDocument sample() {
  VirtualTextBuilder builder;
  builder.append_real("AB", 10, "declaration", "X");
  builder.append_synthetic("--", "separator", "X");
  builder.append_real("CD", 3, "implementation", "X");
  return builder.finish(ContainerKind::TwinCat);
}

TEST(ContainerDocument, BuilderKeepsSegmentsContiguous) {
  const ContainerDocument doc = sample();
  EXPECT_EQ(doc.virtual_text, "AB--CD");
  ASSERT_EQ(doc.segments.size(), 3u);
  EXPECT_EQ(doc.segments[1].virtual_begin, 2u);
  EXPECT_EQ(doc.segments[1].length, 2u);
  EXPECT_FALSE(doc.segments[1].file_begin.has_value());
  EXPECT_EQ(doc.segments[2].virtual_begin, 4u);
}

TEST(ContainerDocument, ToFileOffset) {
  const ContainerDocument doc = sample();
  EXPECT_EQ(doc.to_file_offset(0), 10u);
  EXPECT_EQ(doc.to_file_offset(1), 11u);
  EXPECT_EQ(doc.to_file_offset(2), 3u);  // synthetic: start of the next real segment
  EXPECT_EQ(doc.to_file_offset(3), 3u);
  EXPECT_EQ(doc.to_file_offset(5), 4u);
  EXPECT_EQ(doc.to_file_offset(6), 5u);   // end of the text: end of the last real segment
  EXPECT_EQ(doc.to_file_offset(60), 5u);  // clamps
}

TEST(ContainerDocument, TrailingSyntheticMapsToTheEndOfThePreviousReal) {
  VirtualTextBuilder builder;
  builder.append_real("AB", 7, "declaration", "X");
  builder.append_synthetic("GET\n", "property P/get", "X");
  const ContainerDocument doc = builder.finish(ContainerKind::TwinCat);
  EXPECT_EQ(doc.to_file_offset(3), 9u);
}

TEST(ContainerDocument, OnlySyntheticTextHasNoFileOffset) {
  VirtualTextBuilder builder;
  builder.append_synthetic("GET\n", "property P/get", "X");
  const ContainerDocument doc = builder.finish(ContainerKind::TwinCat);
  EXPECT_EQ(doc.to_file_offset(0), std::nullopt);
  EXPECT_EQ(ContainerDocument{}.to_file_offset(0), std::nullopt);
}

TEST(ContainerDocument, ToVirtualOffsetUsesFileOrder) {
  const ContainerDocument doc = sample();
  EXPECT_EQ(doc.to_virtual_offset(3), 4u);
  EXPECT_EQ(doc.to_virtual_offset(4), 5u);
  EXPECT_EQ(doc.to_virtual_offset(5), 6u);  // end of a segment counts as inside
  EXPECT_EQ(doc.to_virtual_offset(6), std::nullopt);
  EXPECT_EQ(doc.to_virtual_offset(10), 0u);
  EXPECT_EQ(doc.to_virtual_offset(12), 2u);
  EXPECT_EQ(doc.to_virtual_offset(2), std::nullopt);
  EXPECT_EQ(doc.to_virtual_offset(13), std::nullopt);
}

TEST(ContainerDocument, ToVirtualOffsetWithoutIndexScans) {
  ContainerDocument doc = sample();
  doc.segments.push_back({6, 1, 20u, "action A", "X"});
  doc.virtual_text += "E";
  EXPECT_EQ(doc.to_virtual_offset(20), 6u);
  EXPECT_EQ(doc.to_virtual_offset(3), 4u);
}

TEST(ContainerDocument, ContiguousPiecesMerge) {
  VirtualTextBuilder builder;
  builder.append_real("ab", 0, "declaration", "X");
  builder.append_real("cd", 2, "declaration", "X");
  builder.append_real("ef", 9, "declaration", "X");
  builder.append_real("", 50, "declaration", "X");
  const ContainerDocument doc = builder.finish(ContainerKind::TwinCat);
  ASSERT_EQ(doc.segments.size(), 2u);
  EXPECT_EQ(doc.segments[0].length, 4u);
  EXPECT_EQ(doc.segments[1].file_begin, 9u);
}

TEST(ContainerDocument, SegmentAt) {
  const ContainerDocument doc = sample();
  ASSERT_NE(doc.segment_at(5), nullptr);
  EXPECT_EQ(doc.segment_at(5)->role, "implementation");
  EXPECT_EQ(doc.segment_at(6), nullptr);
}

TEST(ContainerDocument, PlainDocumentIsIdentity) {
  const ContainerDocument doc = plain_document("x := 1;");
  EXPECT_EQ(doc.kind, ContainerKind::None);
  EXPECT_EQ(doc.virtual_text, "x := 1;");
  EXPECT_EQ(doc.to_file_offset(4), 4u);
  EXPECT_EQ(doc.to_virtual_offset(7), 7u);
  EXPECT_EQ(container_kind_name(doc.kind), "none");
  EXPECT_EQ(container_kind_name(ContainerKind::CodesysExp), "codesys-exp");
}

}  // namespace
}  // namespace rung::containers
