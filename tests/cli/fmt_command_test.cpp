// `rung fmt` driven through the real binary on temporary folders, as a user or a CI job runs it.
//
// Expected texts come from the engine itself (format_text / format_file_text with the same
// settings), so these tests check what the command does with the engine's result (which files,
// which bytes, which encoding, which exit code), not the layout. Tests named *Changes* need an
// engine that changes lower-case keywords (the default keyword_case is "upper").
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <string>

#include "formatter/container_format.hpp"
#include "formatter/format.hpp"
#include "formatter/unified_diff.hpp"
#include "parser/source/encode.hpp"
#include "tests/support/test_paths.hpp"

namespace rung {
namespace {

namespace fs = std::filesystem;

struct RunResult {
  int exit_code;
  std::string out;
  std::string err;
};

class FmtCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    static int counter = 0;
    dir_ = fs::temp_directory_path() / ("rung_fmt_test_" + std::to_string(getpid()) + "_" + std::to_string(counter++));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // Runs rung in the temporary folder; `input` is given on stdin.
  RunResult rung(const std::string& args, const std::string& input = "") {
    const fs::path in = dir_ / ".stdin", out = dir_ / ".stdout", err = dir_ / ".stderr";
    test::write_file(in, input);
    const std::string command = "cd '" + dir_.string() + "' && '" + test::rung_binary().string() + "' " + args + " <'" +
                                in.string() + "' >'" + out.string() + "' 2>'" + err.string() + "'";
    const int status = std::system(command.c_str());
    RunResult r{WIFEXITED(status) ? WEXITSTATUS(status) : -1, test::read_file(out), test::read_file(err)};
    fs::remove(in);
    fs::remove(out);
    fs::remove(err);
    return r;
  }

  void write(const std::string& name, const std::string& bytes) { test::write_file(dir_ / name, bytes); }
  std::string read(const std::string& name) { return test::read_file(dir_ / name); }

  fs::path dir_;
};

// The engine's layout of a plain text with the default settings.
std::string engine(const std::string& text) {
  return format::format_text(text, project::FormatSettings{}).text;
}

const std::string kLowerCase =
    "program main\nvar\n\tx : int;\nend_var\nif x > 1 then\n\tx := 0;\nend_if\nend_program\n";

const std::string kBroken = "program main\nvar\n\tx : int;\nend_var\nx := (1 + ;\nend_program\n";  // line 5

TEST_F(FmtCommand, MissingPathIsExitTwo) {
  const RunResult r = rung("fmt nowhere.st");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("nowhere.st: no such file or folder"), std::string::npos) << r.err;
}

TEST_F(FmtCommand, WrongOptionCombinationsAreExitTwo) {
  EXPECT_EQ(rung("fmt --stdin-filename a.st").exit_code, 2);
  write("a.st", "PROGRAM P\nEND_PROGRAM\n");
  EXPECT_EQ(rung("fmt --stdin a.st").exit_code, 2);
}

TEST_F(FmtCommand, ABrokenRungTomlStopsEverything) {
  write("rung.toml", "[format]\nindent_width = 99\n");
  write("a.st", kLowerCase);
  const RunResult r = rung("fmt");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("error[P003]"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("nothing was formatted"), std::string::npos) << r.err;
  EXPECT_EQ(read("a.st"), kLowerCase);
}

TEST_F(FmtCommand, AnUnknownKeyIsOnlyAWarning) {
  write("rung.toml", "[format]\nindentation = 2\n");
  write("a.st", engine(kLowerCase));
  const RunResult r = rung("fmt --check");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("warning[P002]"), std::string::npos) << r.err;
}

TEST_F(FmtCommand, FormattedFilesAreLeftAlone) {
  const std::string formatted = engine(kLowerCase);
  write("src/a.st", formatted);
  const fs::file_time_type before = fs::last_write_time(dir_ / "src/a.st");
  const RunResult check = rung("fmt --check src");
  EXPECT_EQ(check.exit_code, 0) << check.err;
  EXPECT_EQ(check.out, "");
  EXPECT_NE(check.err.find("1 file already formatted"), std::string::npos) << check.err;
  const RunResult write_run = rung("fmt src");
  EXPECT_EQ(write_run.exit_code, 0) << write_run.err;
  EXPECT_EQ(read("src/a.st"), formatted);
  EXPECT_EQ(fs::last_write_time(dir_ / "src/a.st"), before);  // not even rewritten
  EXPECT_EQ(rung("fmt -q src").err, "");
}

TEST_F(FmtCommand, InvalidBytesAreNeverWrittenBack) {
  // Mostly UTF-8 with one stray byte: decoding turns it into U+FFFD, so writing would lose it.
  const std::string bytes = "PROGRAM P\n(* gr\xC3\xBC\xC3\x9F\x65 \xFF *)\nEND_PROGRAM\n";
  write("a.st", bytes);
  const RunResult r = rung("fmt a.st");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("a.st:2:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("not formatted"), std::string::npos) << r.err;
  EXPECT_EQ(read("a.st"), bytes);
}

TEST_F(FmtCommand, PlcOpenFilesAreNotedNotFormatted) {
  const std::string xml =
      "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<project xmlns=\"http://www.plcopen.org/xml/tc6_0201\">\n"
      "<types><dataTypes/><pous/></types>\n</project>\n";
  write("plc.xml", xml);
  const RunResult r = rung("fmt plc.xml");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("plc.xml: note: PLCopen XML is not formatted"), std::string::npos) << r.err;
  EXPECT_EQ(read("plc.xml"), xml);
}

TEST_F(FmtCommand, StdinEchoesAFormattedText) {
  const std::string formatted = engine(kLowerCase);
  const RunResult r = rung("fmt --stdin --stdin-filename main.st", formatted);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, formatted);
  EXPECT_EQ(rung("fmt --stdin --check", formatted).exit_code, 0);
}

TEST_F(FmtCommand, WithoutPathsTheProjectSourcesMinusExclude) {
  write("rung.toml", "[project]\nsources = [\"src\"]\nexclude = [\"src/generated/**\"]\n");
  write("src/a.st", kLowerCase);
  write("src/generated/b.st", kLowerCase);
  write("other/c.st", kLowerCase);
  const RunResult r = rung("fmt --check");
  const bool engine_changes = engine(kLowerCase) != kLowerCase;
  EXPECT_EQ(r.exit_code, engine_changes ? 1 : 0) << r.err;
  EXPECT_EQ(r.out, engine_changes ? "src/a.st\n" : "");
  EXPECT_EQ(r.out.find("generated"), std::string::npos);
  EXPECT_EQ(r.out.find("other"), std::string::npos);
}

// ---- with an engine that changes lower-case keywords

TEST_F(FmtCommand, CheckListsChangedFilesAndWritesNothing) {
  ASSERT_NE(engine(kLowerCase), kLowerCase) << "needs the formatter engine";
  write("a.st", kLowerCase);
  write("b.st", engine(kLowerCase));
  const RunResult r = rung("fmt --check .");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.out, "a.st\n");
  EXPECT_NE(r.err.find("1 of 2 files needs formatting"), std::string::npos) << r.err;
  EXPECT_EQ(read("a.st"), kLowerCase);
}

TEST_F(FmtCommand, DiffPrintsUnifiedDiffsAndWritesNothing) {
  ASSERT_NE(engine(kLowerCase), kLowerCase) << "needs the formatter engine";
  write("src/a.st", kLowerCase);
  const RunResult r = rung("fmt --diff --color never src/a.st");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.out, format::unified_diff(kLowerCase, engine(kLowerCase), "a/src/a.st", "b/src/a.st"));
  EXPECT_NE(r.out.find("+END_IF"), std::string::npos) << r.out;
  EXPECT_EQ(read("src/a.st"), kLowerCase);
  // --color always marks removed lines red.
  EXPECT_NE(rung("fmt --diff --color always src/a.st").out.find("\x1b[1;31m-"), std::string::npos);
}

TEST_F(FmtCommand, ChangesAreWrittenInPlace) {
  ASSERT_NE(engine(kLowerCase), kLowerCase) << "needs the formatter engine";
  write("a.st", kLowerCase);
  fs::permissions(dir_ / "a.st", fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
  const RunResult r = rung("fmt a.st");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(read("a.st"), engine(kLowerCase));
  EXPECT_NE(r.err.find("formatted 1 of 1 file"), std::string::npos) << r.err;
  EXPECT_EQ(fs::status(dir_ / "a.st").permissions() & fs::perms::all,
            fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
  // No temporary file is left beside it.
  size_t entries = 0;
  for (const auto& entry : fs::directory_iterator(dir_)) entries += entry.path().filename() == "a.st" ? 1 : 10;
  EXPECT_EQ(entries, 1u);
  // Formatting again changes nothing.
  EXPECT_EQ(rung("fmt --check a.st").exit_code, 0);
}

TEST_F(FmtCommand, Cp1252StaysCp1252AndCrLfStaysCrLf) {
  ASSERT_NE(engine(kLowerCase), kLowerCase) << "needs the formatter engine";
  // "Zähler" in cp1252 (0xE4), CRLF line ends, as a CODESYS V2 export writes files.
  std::string text =
      "program main\r\nvar\r\n\tx : int; (* Z\xC3\xA4hler *)\r\nend_var\r\nif x > 1 then\r\n\tx := "
      "0;\r\nend_if\r\nend_program\r\n";
  const std::optional<std::string> cp1252 = source::encode(text, source::Encoding::Cp1252, false);
  ASSERT_TRUE(cp1252.has_value());
  write("a.st", *cp1252);
  const RunResult r = rung("fmt a.st");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  const std::string bytes = read("a.st");
  EXPECT_NE(bytes, *cp1252);
  EXPECT_EQ(bytes, source::encode(engine(text), source::Encoding::Cp1252, false));
  EXPECT_NE(bytes.find("Z\xE4hler"), std::string::npos);
  for (size_t i = bytes.find('\n'); i != std::string::npos; i = bytes.find('\n', i + 1)) {
    ASSERT_GT(i, 0u);
    EXPECT_EQ(bytes[i - 1], '\r') << "LF without CR at byte " << i;
  }
}

TEST_F(FmtCommand, AUtf8BomStays) {
  ASSERT_NE(engine(kLowerCase), kLowerCase) << "needs the formatter engine";
  write("a.st", "\xEF\xBB\xBF" + kLowerCase);
  EXPECT_EQ(rung("fmt a.st").exit_code, 0);
  EXPECT_EQ(read("a.st"), "\xEF\xBB\xBF" + engine(kLowerCase));
}

TEST_F(FmtCommand, ATcPouKeepsEveryByteOutsideTheSt) {
  const std::string pou =
      "<?xml version=\"1.0\" encoding=\"utf-8\"?>\r\n<TcPlcObject Version=\"1.1.0.1\" "
      "ProductVersion=\"3.1.4024.0\">\r\n"
      "  <POU Name=\"FB_Lamp\" Id=\"{0d4c5e1a-0000-4000-8000-00000000000a}\" SpecialFunc=\"None\">\r\n"
      "    <Declaration><![CDATA[function_block FB_Lamp\r\nvar_input\r\n\tbOn : "
      "bool;\r\nend_var\r\n]]></Declaration>\r\n"
      "    <Implementation>\r\n      <ST><![CDATA[if bOn then\r\n\tbOn := false;\r\nend_if]]></ST>\r\n"
      "    </Implementation>\r\n  </POU>\r\n</TcPlcObject>";
  const format::FileFormatResult expected =
      format::format_file_text(containers::ContainerKind::TwinCat, pou, project::FormatSettings{});
  ASSERT_TRUE(expected.result.changed) << "needs the formatter engine";
  write("FB_Lamp.TcPOU", pou);
  const RunResult r = rung("fmt FB_Lamp.TcPOU");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  const std::string bytes = read("FB_Lamp.TcPOU");
  EXPECT_EQ(bytes, expected.result.text);
  const std::string head = pou.substr(0, pou.find("<![CDATA[") + 9);
  const std::string tail = pou.substr(pou.rfind("]]>"));
  EXPECT_EQ(bytes.substr(0, head.size()), head);
  EXPECT_EQ(bytes.substr(bytes.size() - tail.size()), tail);
  EXPECT_NE(bytes.find("END_IF]]></ST>"), std::string::npos) << bytes;
}

TEST_F(FmtCommand, ABrokenFileIsUntouched) {
  const std::string broken = kBroken;
  write("bad.st", broken);
  write("good.st", kLowerCase);
  const RunResult r = rung("fmt .");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("bad.st:5:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(": not formatted: "), std::string::npos) << r.err;
  EXPECT_EQ(read("bad.st"), broken);
  EXPECT_EQ(read("good.st"), engine(kLowerCase));  // the other files are still formatted
}

TEST_F(FmtCommand, StdinFormatsToStdout) {
  ASSERT_NE(engine(kLowerCase), kLowerCase) << "needs the formatter engine";
  const RunResult r = rung("fmt --stdin --stdin-filename src/main.st", kLowerCase);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, engine(kLowerCase));
  const RunResult check = rung("fmt --stdin --check", kLowerCase);
  EXPECT_EQ(check.exit_code, 1);
  const RunResult diff = rung("fmt --stdin --diff --stdin-filename main.st", kLowerCase);
  EXPECT_EQ(diff.exit_code, 1);
  EXPECT_EQ(diff.out, format::unified_diff(kLowerCase, engine(kLowerCase), "a/main.st", "b/main.st"));
  // Settings come from the rung.toml of the named file's folder.
  write("proj/rung.toml", "[format]\nkeyword_case = \"preserve\"\n");
  const RunResult preserved = rung("fmt --stdin --stdin-filename proj/main.st", kLowerCase);
  EXPECT_EQ(preserved.exit_code, 0) << preserved.err;
  EXPECT_NE(preserved.out.find("end_if"), std::string::npos) << preserved.out;
}

TEST_F(FmtCommand, StdinWithSyntaxErrorsGivesTheTextBack) {
  const std::string broken = kBroken;
  const RunResult r = rung("fmt --stdin --stdin-filename main.st", broken);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.out, broken);
  EXPECT_NE(r.err.find("main.st:5:"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace rung
