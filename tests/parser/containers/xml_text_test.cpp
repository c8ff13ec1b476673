#include "parser/containers/xml_text.hpp"

#include <gtest/gtest.h>

namespace rung::containers {
namespace {

TEST(XmlText, Unescape) {
  EXPECT_EQ(unescape_xml("a &lt; b &amp;&amp; c &gt; d"), "a < b && c > d");
  EXPECT_EQ(unescape_xml("&quot;&apos;&#65;&#x42;&#x20AC;"), "\"'AB\xE2\x82\xAC");
  EXPECT_EQ(unescape_xml("&unknown; & &#0; &#xD800; &#;"), "&unknown; & &#0; &#xD800; &#;");
  EXPECT_EQ(unescape_xml(""), "");
}

TEST(XmlText, EscapedTextMapsPiecewise) {
  // File:  "x := a &lt; b;" at file offset 100.
  VirtualTextBuilder builder;
  append_escaped_text(builder, "x := a &lt; b;", 100, "implementation", "P");
  const ContainerDocument doc = builder.finish(ContainerKind::TwinCat);
  EXPECT_EQ(doc.virtual_text, "x := a < b;");
  EXPECT_EQ(doc.to_file_offset(0), 100u);
  EXPECT_EQ(doc.to_file_offset(7), 107u);  // '<' -> the '&' of "&lt;"
  EXPECT_EQ(doc.to_file_offset(8), 111u);  // ' ' after the entity
  EXPECT_EQ(doc.to_file_offset(9), 112u);  // 'b'
  EXPECT_EQ(doc.to_virtual_offset(112), 9u);
  EXPECT_EQ(doc.to_virtual_offset(109), std::nullopt);  // inside "&lt;"
}

TEST(XmlText, MultibyteReplacement) {
  VirtualTextBuilder builder;
  append_escaped_text(builder, "&#x20AC;!", 0, "r", "o");
  const ContainerDocument doc = builder.finish(ContainerKind::TwinCat);
  EXPECT_EQ(doc.virtual_text, "\xE2\x82\xAC!");
  EXPECT_EQ(doc.to_file_offset(0), 0u);
  EXPECT_EQ(doc.to_file_offset(3), 8u);
}

}  // namespace
}  // namespace rung::containers
