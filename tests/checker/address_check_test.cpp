// AT declarations end to end (texts in, diagnostics out): E505 malformed addresses, E503 types
// that do not fit the address size, E504 variables that share memory, in one file and across
// files, under byte addressing (CODESYS V3) and byte-offset addressing (OpenPCS).
// Lnnn point into the seed manuals in ../shared/seeds: 000 = CODESYS V3 textbook, 001 = AK800,
// 002 = MP300, 003 = OpenPCS.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "checker/check.hpp"

namespace rung::check {
namespace {

using Files = std::vector<std::pair<std::string, std::string>>;

struct Found {
  std::string path;
  Diagnostic diagnostic;
};

std::vector<Found> check(const Files& files, project::Profile profile = project::Profile::Codesys,
                         const std::string& addressing = {}) {
  project::ProjectConfig config;
  config.profile = profile;
  config.addressing = addressing;
  auto workspace = Workspace::from_texts(files, config);
  std::vector<Found> found;
  for (const auto& file : workspace->check_all(1)) {
    for (const auto& diagnostic : file.diagnostics) found.push_back({file.path, diagnostic});
  }
  return found;
}

// A PROGRAM declaring `declarations` in its VAR block.
std::string program(const std::string& declarations) {
  return "PROGRAM P\nVAR\n" + declarations + "END_VAR\nEND_PROGRAM\n";
}

std::vector<Found> check_program(const std::string& declarations, project::Profile profile = project::Profile::Codesys,
                                 const std::string& addressing = {}) {
  return check({{"P.st", program(declarations)}}, profile, addressing);
}

std::vector<std::string> codes(const std::vector<Found>& found) {
  std::vector<std::string> out;
  for (const Found& f : found) out.push_back(f.diagnostic.code);
  return out;
}

size_t count(const std::vector<Found>& found, std::string_view code) {
  return static_cast<size_t>(
      std::count_if(found.begin(), found.end(), [&](const Found& f) { return f.diagnostic.code == code; }));
}

using Codes = std::vector<std::string>;

// --- E503: the type against the address size ---------------------------------------------------

TEST(AddressCheck, IntOnABitAddressIsAnError) {
  // 000 L3172: the textbook's own slip `bTest AT %IX10.3: INT`.
  auto found = check_program("bTest AT %IX10.3 : INT;\n");
  ASSERT_EQ(codes(found), Codes{"E503"});
  EXPECT_EQ(found[0].diagnostic.severity, Severity::Error);
  EXPECT_EQ(found[0].diagnostic.message, "'bTest' is INT, but %IX10.3 is a single bit: only BOOL fits a bit address");
  EXPECT_EQ(found[0].diagnostic.help, "use a 16-bit address (%IW…) or declare 'bTest' as BOOL");
  EXPECT_EQ(codes(check_program("bTest AT %IX10.3 : BOOL;\n")), Codes{});
}

TEST(AddressCheck, EveryTypeAtTheAddressOfItsSizeIsClean) {
  // Checked in the strict profile, where any size difference is an error.
  const std::string declarations =
      "xBit AT %MX0.0 : BOOL; b8 AT %MB1 : BYTE; si AT %MB2 : SINT; us AT %MB3 : USINT;\n"
      "w AT %MW2 : WORD; i AT %MW3 : INT; ui AT %MW4 : UINT;\n"
      "dw AT %MD3 : DWORD; di AT %MD4 : DINT; ud AT %MD5 : UDINT; r AT %MD6 : REAL; t AT %MD7 : TIME;\n"
      "lw AT %ML4 : LWORD; li AT %ML5 : LINT; lr AT %ML6 : LREAL;\n";
  EXPECT_EQ(codes(check_program(declarations, project::Profile::Iec)), Codes{});
  EXPECT_EQ(codes(check_program(declarations, project::Profile::Codesys)), Codes{});
}

TEST(AddressCheck, AnotherSizeIsAWarningInCodesysAndAnErrorInIec) {
  // 001 L1200: CODESYS reads the address as the start, the type gives the length.
  auto codesys = check_program("n AT %MW2 : DINT;\n");
  ASSERT_EQ(codes(codesys), Codes{"E503"});
  EXPECT_EQ(codesys[0].diagnostic.severity, Severity::Warning);
  EXPECT_EQ(codesys[0].diagnostic.message,
            "'n' is DINT (32 bits), but %MW2 is a word (16 bits): it starts there and covers bytes 4..7");
  auto iec = check_program("n AT %MW2 : DINT;\n", project::Profile::Iec);
  ASSERT_EQ(codes(iec), Codes{"E503"});
  EXPECT_EQ(iec[0].diagnostic.severity, Severity::Error);
  EXPECT_EQ(codes(check_program("n AT %MD2 : DINT;\n", project::Profile::Iec)), Codes{});
  // A smaller type uses only the start of the address.
  auto smaller = check_program("b AT %QW4 : BYTE;\n");
  ASSERT_EQ(codes(smaller), Codes{"E503"});
  EXPECT_NE(smaller[0].diagnostic.message.find("it uses only byte 8"), std::string::npos);
}

TEST(AddressCheck, BoolOnAByteAddressTakesTheByteInCodesysOnly) {
  // 002 L10851-10853: a BOOL at a byte/word address occupies one whole byte.
  EXPECT_EQ(codes(check_program("b AT %QB7 : BOOL;\n")), Codes{});
  auto iec = check_program("b AT %QB7 : BOOL;\n", project::Profile::Iec);
  ASSERT_EQ(codes(iec), Codes{"E503"});
  EXPECT_EQ(iec[0].diagnostic.help, "use a bit address such as %QX7.0");
}

TEST(AddressCheck, ArraysAtAByteAddressInCodesysButNotInOpenPcs) {
  // 000 L9954: `arrInputBuffer AT %IW100 : ARRAY[1..32] OF REAL`; OpenPCS L10030, L1154-1156.
  const std::string declaration = "arr AT %IW100 : ARRAY[1..32] OF REAL;\n";
  EXPECT_EQ(codes(check_program(declaration)), Codes{});
  EXPECT_EQ(codes(check_program(declaration, project::Profile::Openpcs)), Codes{"E503"});
  // Not even CODESYS puts an array on a single bit.
  EXPECT_EQ(codes(check_program("arr AT %IX1.0 : ARRAY[0..7] OF BOOL;\n")), Codes{"E503"});
}

// --- E505: addresses that cannot exist --------------------------------------------------------

TEST(AddressCheck, BitNumberAboveSevenIsMalformedUnderByteAddressing) {
  auto found = check_program("bOk AT %QX2.9 : BOOL;\n");
  ASSERT_EQ(codes(found), Codes{"E505"});
  EXPECT_EQ(found[0].diagnostic.message, "'%QX2.9': bit 9 is out of range: the bits of a byte are numbered 0..7");
  // Word-addressed I/O images number the bits of a word 0..15 (002 L18296-18298; the textbook's
  // engineering examples use %IX0.8..%IX0.11).
  EXPECT_EQ(codes(check_program("bOk AT %QX2.9 : BOOL;\n", project::Profile::Codesys, "word")), Codes{});
  EXPECT_EQ(codes(check_program("bOk AT %QX2.16 : BOOL;\n", project::Profile::Codesys, "word")), Codes{"E505"});
}

TEST(AddressCheck, SeveralNamesAtOneAddressIsOneError) {
  // 003 L12065-12079: S4000, several identifiers for one AT address.
  auto found = check_program("a, b, c AT %QX0.0 : BOOL;\n");
  ASSERT_EQ(codes(found), Codes{"E505"});
  EXPECT_NE(found[0].diagnostic.message.find("3 variables"), std::string::npos);
}

TEST(AddressCheck, IncompleteAddressesBelongInInstances) {
  // 002 L11605-11609: %I*/%Q* in a function block, completed per instance.
  EXPECT_EQ(codes(check({{"FB.st",
                          "FUNCTION_BLOCK FB\nVAR x AT %I* : BOOL; y AT %Q* : BOOL; END_VAR\n"
                          "END_FUNCTION_BLOCK\n"}})),
            Codes{});
  EXPECT_EQ(codes(check({{"F.st", "FUNCTION F : BOOL\nVAR x AT %I* : BOOL; END_VAR\nF := x;\nEND_FUNCTION\n"}})),
            Codes{"E505"});
}

// --- E504: shared memory ----------------------------------------------------------------------

TEST(AddressCheck, WordOneOverlapsByteTwo) {
  // 001 L968-970: %MW1 = %MB2 + %MB3 under byte addressing.
  auto found = check({{"GVL.st",
                       "VAR_GLOBAL\n  wStatus AT %MW1 : WORD;\n  byMode AT %MB2 : BYTE;\n"
                       "  byFree AT %MB4 : BYTE;\nEND_VAR\n"}});
  ASSERT_EQ(codes(found), Codes{"E504"});
  const Diagnostic& d = found[0].diagnostic;
  EXPECT_EQ(d.severity, Severity::Warning);
  EXPECT_EQ(d.message, "'byMode' AT %MB2 (byte 2) overlaps 'wStatus' AT %MW1 (bytes 2..3): both use byte 2 of %M");
  ASSERT_EQ(d.labels.size(), 1u);
  EXPECT_EQ(d.labels[0].message, "'wStatus' is declared here");
}

TEST(AddressCheck, DoubleWordTwelveIsWordsTwentyFourAndTwentyFive) {
  // 001 L968, L5331-5333: %MDn = %MW2n + %MW2n+1; each overlapping pair is reported once.
  auto found = check_program("d AT %MD12 : DWORD; w24 AT %MW24 : WORD; w25 AT %MW25 : WORD; w26 AT %MW26 : WORD;\n");
  EXPECT_EQ(codes(found), (Codes{"E504", "E504"}));
  for (const Found& f : found) EXPECT_NE(f.diagnostic.message.find("'d' AT %MD12"), std::string::npos);
}

TEST(AddressCheck, TheTypeGivesTheLengthAtAStartAddress) {
  // A DINT AT %MW2 covers bytes 4..7, so it meets %MW3 (bytes 6..7).
  auto found = check_program("n AT %MW2 : DINT; w AT %MW3 : WORD;\n");
  EXPECT_EQ(count(found, "E504"), 1u);
}

TEST(AddressCheck, BitsOfOneByteDoNotOverlapButTheByteDoes) {
  auto found = check_program("a AT %MX2.0 : BOOL; b AT %MX2.1 : BOOL; c AT %MB2 : BYTE;\n");
  EXPECT_EQ(count(found, "E504"), 2u);
  EXPECT_EQ(count(check_program("a AT %MX2.0 : BOOL; b AT %MX2.1 : BOOL;\n"), "E504"), 0u);
}

TEST(AddressCheck, InputsThatShareAnAddressAreNotReported) {
  // Inputs are read-only (002 L10826): reading one input twice changes nothing.
  EXPECT_EQ(codes(check_program("a AT %IW0 : WORD; b AT %IB1 : BYTE;\n")), Codes{});
  EXPECT_EQ(codes(check_program("a AT %QW0 : WORD; b AT %QB1 : BYTE;\n")), Codes{"E504"});
}

TEST(AddressCheck, OverlapAcrossTwoFilesIsReportedOnceInTheLaterFile) {
  auto found = check({{"A_Gvl.st", "VAR_GLOBAL\n  wStatus AT %MW1 : WORD;\nEND_VAR\n"},
                      {"B_Main.st", "PROGRAM Main\nVAR\n  byMode AT %MB3 : BYTE;\nEND_VAR\nEND_PROGRAM\n"}});
  ASSERT_EQ(codes(found), Codes{"E504"});
  EXPECT_EQ(found[0].path, "B_Main.st");
  EXPECT_TRUE(found[0].diagnostic.labels.empty());  // a label cannot point into another file
  EXPECT_NE(found[0].diagnostic.message.find("('wStatus' is declared in A_Gvl.st:2)"), std::string::npos)
      << found[0].diagnostic.message;
}

TEST(AddressCheck, ByteOffsetAddressingCountsEveryNumberInBytes) {
  // Byte addressing: %MW0 = bytes 0..1, %MW1 = bytes 2..3: only %MB1 meets %MW0.
  // Byte-offset addressing (002 L18296-18309, OpenPCS 003 L7091): %MW1 = bytes 1..2, so %MW0,
  // %MW1 and %MB1 all share byte 1.
  const std::string declarations = "w0 AT %MW0 : WORD; w1 AT %MW1 : WORD; b1 AT %MB1 : BYTE;\n";
  EXPECT_EQ(count(check_program(declarations), "E504"), 1u);
  EXPECT_EQ(count(check_program(declarations, project::Profile::Codesys, "byte-offset"), "E504"), 3u);
  EXPECT_EQ(count(check_program(declarations, project::Profile::Openpcs), "E504"), 3u);
}

TEST(AddressCheck, DeliberateOverlaysCanBeSwitchedOff) {
  project::ProjectConfig config;
  config.severity_overrides["E504"] = std::nullopt;
  auto workspace = Workspace::from_texts({{"P.st", program("w AT %MW1 : WORD; b AT %MB2 : BYTE;\n")}}, config);
  EXPECT_TRUE(workspace->check_all(1)[0].diagnostics.empty());
}

TEST(AddressCheck, AnEditRebuildsTheOverlapTable) {
  project::ProjectConfig config;
  auto workspace = Workspace::from_texts(
      {{"A.st", "VAR_GLOBAL\n  w AT %MW1 : WORD;\nEND_VAR\n"}, {"B.st", program("b AT %MB8 : BYTE;\n")}}, config);
  EXPECT_TRUE(workspace->check_all(1)[1].diagnostics.empty());
  const SourceId b = *workspace->model().find_source("B.st");
  workspace->update(b, program("b AT %MB3 : BYTE;\n"));
  const FileDiagnostics after = workspace->check_source(b);
  ASSERT_EQ(after.diagnostics.size(), 1u);
  EXPECT_EQ(after.diagnostics[0].code, "E504");
}

}  // namespace
}  // namespace rung::check
