#include "parser/file_walk.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include "tests/support/test_paths.hpp"

namespace rung {
namespace {

TEST(FileWalk, KnowsEveryFileKindCaseInsensitively) {
  EXPECT_EQ(source_kind_of("a.st"), SourceKind::StructuredText);
  EXPECT_EQ(source_kind_of("a.ST"), SourceKind::StructuredText);
  EXPECT_EQ(source_kind_of("a.il"), SourceKind::InstructionList);
  EXPECT_EQ(source_kind_of("FB.TcPOU"), SourceKind::TwinCat);
  EXPECT_EQ(source_kind_of("FB.tcpou"), SourceKind::TwinCat);
  EXPECT_EQ(source_kind_of("T.TcDUT"), SourceKind::TwinCat);
  EXPECT_EQ(source_kind_of("G.TcGVL"), SourceKind::TwinCat);
  EXPECT_EQ(source_kind_of("I.TcIO"), SourceKind::TwinCat);
  EXPECT_EQ(source_kind_of("Lib.EXP"), SourceKind::CodesysExport);
  EXPECT_EQ(source_kind_of("notes.txt"), SourceKind::None);
  EXPECT_EQ(source_kind_of("Makefile"), SourceKind::None);
}

TEST(FileWalk, WalksFoldersSortedAndSkipsHiddenAndBuild) {
  auto root = std::filesystem::temp_directory_path() / ("rung_file_walk_test_" + std::to_string(getpid()));
  std::filesystem::remove_all(root);
  test::write_file(root / "b.st", "");
  test::write_file(root / "a/c.TcPOU", "");
  test::write_file(root / "a/readme.md", "");
  test::write_file(root / ".git/x.st", "");
  test::write_file(root / "build/y.st", "");
  test::write_file(root / "plc.xml",
                   "<?xml version=\"1.0\"?>\n<project xmlns=\"http://www.plcopen.org/xml/tc6_0201\">");
  test::write_file(root / "other.xml", "<?xml version=\"1.0\"?>\n<config/>");
  WalkResult r = collect_source_files({root, root / "b.st", root / "missing"});
  ASSERT_EQ(r.files.size(), 3u);
  EXPECT_EQ(r.files[0], root / "a/c.TcPOU");
  EXPECT_EQ(r.files[1], root / "b.st");
  EXPECT_EQ(r.files[2], root / "plc.xml");  // PLCopen by content; other.xml is not
  ASSERT_EQ(r.errors.size(), 1u);
  EXPECT_NE(r.errors[0].find("missing"), std::string::npos);
  std::filesystem::remove_all(root);
}

}  // namespace
}  // namespace rung
