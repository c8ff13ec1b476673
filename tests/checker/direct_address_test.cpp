// Direct addresses: parsing, byte placement in the three addressing modes, type fit, overlaps.
// Line numbers (Lnnn) point into the seed manuals in ../shared/seeds: 000 = CODESYS V3 textbook,
// 001 = AK800, 002 = MP300, 003 = OpenPCS.
#include "checker/semantic/direct_address.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <random>
#include <set>

#include "parser/document.hpp"
#include "parser/file_walk.hpp"
#include "tests/support/test_paths.hpp"

namespace rung::check {
namespace {

DirectAddress parse_ok(std::string_view text, AddressingMode mode = AddressingMode::Byte) {
  DirectAddressResult result = parse_direct_address(text, mode);
  EXPECT_TRUE(result.ok()) << text << ": " << result.error;
  return result.address.value_or(DirectAddress{});
}

std::string parse_error(std::string_view text, AddressingMode mode = AddressingMode::Byte) {
  DirectAddressResult result = parse_direct_address(text, mode);
  EXPECT_FALSE(result.ok()) << text << " should be rejected";
  EXPECT_LE(result.error_offset, text.size()) << text;
  return result.error;
}

// Covered bytes as a pair, for compact expectations.
std::pair<uint64_t, uint64_t> bytes(std::string_view text, AddressingMode mode = AddressingMode::Byte) {
  DirectAddress a = parse_ok(text, mode);
  return {a.first_byte, a.last_byte};
}

// Absolute bit number of a bit address, as BITADR reports it (without the area base).
uint64_t bit_number(std::string_view text, AddressingMode mode = AddressingMode::Byte) {
  DirectAddress a = parse_ok(text, mode);
  return a.first_byte * 8 + a.bit.value_or(0);
}

using Pair = std::pair<uint64_t, uint64_t>;

// ---------------------------------------------------------------------------------------------
// Syntax

TEST(DirectAddressParse, AreaSizeAndNumbers) {
  DirectAddress a = parse_ok("%IX0.3");
  EXPECT_EQ(a.area, AddressArea::Input);
  EXPECT_EQ(a.size, AddressSize::Bit);
  EXPECT_EQ(a.numbers, (std::vector<uint32_t>{0, 3}));
  EXPECT_FALSE(a.wildcard);
  EXPECT_TRUE(a.hierarchy.empty());
  EXPECT_TRUE(a.is_bit());
  EXPECT_EQ(a.size_bits(), 1u);

  EXPECT_EQ(parse_ok("%QW0").area, AddressArea::Output);
  EXPECT_EQ(parse_ok("%MD48").area, AddressArea::Memory);
  EXPECT_EQ(parse_ok("%MB5").size, AddressSize::Byte);
  EXPECT_EQ(parse_ok("%MW1").size, AddressSize::Word);
  EXPECT_EQ(parse_ok("%QD4").size, AddressSize::Double);
  EXPECT_EQ(parse_ok("%ML1").size, AddressSize::Long);
  EXPECT_EQ(parse_ok("%ML1").size_bits(), 64u);
  EXPECT_EQ(parse_ok("%QD4").size_bits(), 32u);
}

TEST(DirectAddressParse, CaseInsensitive) {
  // OpenPCS writes `VAR x1 at %ix0.0: bool;` and `%qw1.0` (003 L7083-7094).
  DirectAddress a = parse_ok("%ix0.0");
  EXPECT_EQ(a.area, AddressArea::Input);
  EXPECT_EQ(a.size, AddressSize::Bit);
  EXPECT_EQ(parse_ok("%qw1.0").size, AddressSize::Word);
  EXPECT_EQ(format_direct_address(parse_ok("%mx2.7")), "%MX2.7");
}

TEST(DirectAddressParse, NoSizePrefixIsABit) {
  // %QX7.5 and %Q7.5 are both output byte 7 bit 5 (002 L18259-18271); %I0.0 = %IX0.0 (003 L1176).
  DirectAddress with = parse_ok("%QX7.5");
  DirectAddress without = parse_ok("%Q7.5");
  EXPECT_EQ(without.size, AddressSize::None);
  EXPECT_TRUE(without.is_bit());
  EXPECT_EQ(without.first_byte, with.first_byte);
  EXPECT_EQ(without.bit, with.bit);
  EXPECT_EQ(format_direct_address(without), "%QX7.5");
  EXPECT_EQ(bytes("%I0.0"), Pair(0, 0));
}

TEST(DirectAddressParse, Wildcards) {
  // CODESYS incomplete addresses `AT %I*` / `AT %Q*`, completed by VAR_CONFIG (002 L11605-11625);
  // the AK800 table lists '*' as "location allocated by the system" (001 L957).
  for (std::string_view text : {"%I*", "%Q*", "%M*", "%IX*", "%qw*"}) {
    DirectAddress a = parse_ok(text);
    EXPECT_TRUE(a.wildcard) << text;
    EXPECT_TRUE(a.numbers.empty()) << text;
  }
  EXPECT_FALSE(parse_ok("%I*").is_bit());
  EXPECT_EQ(parse_ok("%I*").size_bits(), 0u);
  EXPECT_EQ(format_direct_address(parse_ok("%q*")), "%Q*");
  EXPECT_EQ(format_direct_address(parse_ok("%iw*")), "%IW*");
}

TEST(DirectAddressParse, HierarchicalAddresses) {
  // %IW2.5.7.1 = bus 2, rack 5, module 7, channel 1 (003 L11235-11241; 002 L18279 "PLC-dependent").
  DirectAddress w = parse_ok("%IW2.5.7.1");
  EXPECT_EQ(w.hierarchy, (std::vector<uint32_t>{2, 5, 7}));
  EXPECT_EQ(w.first_byte, 2u);
  EXPECT_EQ(w.last_byte, 3u);
  // For a bit address the last two numbers are byte.bit, the rest the hierarchy.
  DirectAddress x = parse_ok("%IX1.2.3");
  EXPECT_EQ(x.hierarchy, (std::vector<uint32_t>{1}));
  EXPECT_EQ(x.first_byte, 2u);
  EXPECT_EQ(x.bit, 3);
  EXPECT_EQ(format_direct_address(x), "%IX1.2.3");
  // Eight levels is the most OpenPCS allows (S1017, 003 L11161-11166).
  EXPECT_EQ(parse_ok("%IW1.2.3.4.5.6.7.8").hierarchy.size(), 7u);
}

TEST(DirectAddressParse, LargestFieldIsAccepted) {
  // Each field may be up to 4294967295 (S1011, 003 L11070-11077); the byte arithmetic must not wrap.
  DirectAddress a = parse_ok("%ML4294967295");
  EXPECT_EQ(a.first_byte, 4294967295ull * 8);
  EXPECT_EQ(a.last_byte, 4294967295ull * 8 + 7);
  EXPECT_EQ(bit_number("%MX4294967295.7"), 4294967295ull * 8 + 7);
}

TEST(DirectAddressParse, MalformedAddresses) {
  EXPECT_EQ(parse_error(""), "a direct address starts with '%'");
  EXPECT_EQ(parse_error("IX0.0"), "a direct address starts with '%'");
  EXPECT_EQ(parse_error("%"), "'%' must be followed by an area: I (input), Q (output) or M (memory)");
  EXPECT_EQ(parse_error("%ZW1"), "'Z' is not an address area: use I (input), Q (output) or M (memory)");
  EXPECT_EQ(parse_error("%MW"), "'%MW' has no address number");
  EXPECT_EQ(parse_error("%I"), "'%I' has no address number");
  EXPECT_EQ(parse_error("%MX1."), "'.' in a direct address must be followed by a number");
  EXPECT_EQ(parse_error("%MX1..2"), "'.' in a direct address must be followed by a number");
  EXPECT_EQ(parse_error("%MW1a"), "unexpected 'a' in direct address");
  EXPECT_EQ(parse_error("%MWX1"), "'%MW' has no address number");
  EXPECT_EQ(parse_error("%MW-1"), "'%MW' has no address number");
  EXPECT_EQ(parse_error("%MW 1"), "'%MW' has no address number");
  EXPECT_EQ(parse_error("%MW1 "), "unexpected blank in direct address");
  EXPECT_EQ(parse_error("%MW1\n"), "unexpected character in direct address");
  EXPECT_EQ(parse_error("%I*1"), "nothing may follow '*' (an address the configuration assigns)");
  EXPECT_EQ(parse_error("%I*.0"), "nothing may follow '*' (an address the configuration assigns)");
  EXPECT_EQ(parse_error("%MW4294967296"), "address number 4294967296 is larger than 4294967295");
  EXPECT_EQ(parse_error("%MW99999999999999999999999999999999999"),
            "address number 999999999999999999999999... is larger than 4294967295");
  EXPECT_EQ(parse_error("%IW1.2.3.4.5.6.7.8.9"), "a direct address has at most 8 levels, this one has 9");
  // The grammar's other direct_variable form is CODESYS's partial access of a variable.
  EXPECT_EQ(
      parse_error("%X3"),
      "'%X3' is a bit/byte access of a variable (x.%X3), not a direct address: an address needs an area I, Q or M");
  EXPECT_EQ(parse_error("%\xE4\xB8\xAD"), "'%' must be followed by an area: I (input), Q (output) or M (memory)");
}

TEST(DirectAddressParse, ErrorOffsetPointsAtTheProblem) {
  EXPECT_EQ(parse_direct_address("%ZW1").error_offset, 1u);
  EXPECT_EQ(parse_direct_address("%MW").error_offset, 3u);
  EXPECT_EQ(parse_direct_address("%QX1.9").error_offset, 5u);
  EXPECT_EQ(parse_direct_address("%MW12x").error_offset, 5u);
  EXPECT_EQ(parse_direct_address("%IW1.2.3.4.5.6.7.8.9").error_offset, 19u);
}

// ---------------------------------------------------------------------------------------------
// Placement, default (CODESYS V3 byte-oriented) mode

TEST(DirectAddressBytes, BitAddressesAreByteDotBit) {
  // %MX12.0 is the first bit of %MB12; %IX1.3 is bit 3 of input byte 1 (000 L4591, L4597).
  DirectAddress a = parse_ok("%MX12.0");
  EXPECT_EQ(a.first_byte, 12u);
  EXPECT_EQ(a.last_byte, 12u);
  EXPECT_EQ(a.bit, 0);
  EXPECT_EQ(parse_ok("%IX1.3").first_byte, 1u);
  EXPECT_EQ(parse_ok("%IX1.3").bit, 3);
  // %MX2.7 is the 8th bit of %MB2 (001 L970); %MX1.3 = byte 1 bit 3.
  EXPECT_EQ(parse_ok("%MX2.7").first_byte, 2u);
  EXPECT_EQ(parse_ok("%MX2.7").bit, 7);
  EXPECT_EQ(parse_ok("%MX1.3").bit, 3);
  // %IB1 holds %IX1.0..%IX1.7, not bits 8..15 of anything (001 L976).
  EXPECT_EQ(bytes("%IX1.0"), bytes("%IB1"));
  EXPECT_EQ(bytes("%IX1.7"), bytes("%IB1"));
}

TEST(DirectAddressBytes, BitIndexIsZeroToSeven) {
  // n = 0..7 (001 L1016-1017); %MX0.8 is invalid (001 digest test 4).
  EXPECT_EQ(parse_error("%MX0.8"), "bit 8 is out of range: the bits of a byte are numbered 0..7");
  EXPECT_EQ(parse_error("%QX1.9"), "bit 9 is out of range: the bits of a byte are numbered 0..7");
  EXPECT_EQ(parse_error("%IX0.11"), "bit 11 is out of range: the bits of a byte are numbered 0..7");
  EXPECT_EQ(parse_error("%Q0.8"), "bit 8 is out of range: the bits of a byte are numbered 0..7");
  parse_ok("%MX3212.7");  // table example (001 L1019)
}

TEST(DirectAddressBytes, SizesCountUnitsOfTheirOwnSize) {
  EXPECT_EQ(bytes("%MB5"), Pair(5, 5));
  EXPECT_EQ(bytes("%MW1"), Pair(2, 3));
  EXPECT_EQ(bytes("%MD12"), Pair(48, 51));
  EXPECT_EQ(bytes("%ML1"), Pair(8, 15));
  // %IW4 = input bytes 8 and 9 (000 L4593).
  EXPECT_EQ(bytes("%IW4"), Pair(8, 9));
  // %ID48 = %IW96 + %IW97 = %IB192..%IB195 (000 L4569-4577, 001 L968).
  EXPECT_EQ(bytes("%ID48"), Pair(192, 195));
  EXPECT_EQ(bytes("%IW96").first, 192u);
  EXPECT_EQ(bytes("%IW97").second, 195u);
  // %MW12 = %MB24 + %MB25 (001 L970); %MW601 = %MB1202..1203 (001 L976).
  EXPECT_EQ(bytes("%MW12"), Pair(24, 25));
  EXPECT_EQ(bytes("%MW601"), Pair(1202, 1203));
  // %MD300 = %MW600..601 = %MB1200..1203 (001 L981-987); %MD0 = %MW0+%MW1 = %MB0..3 (001 L5333).
  EXPECT_EQ(bytes("%MD300"), Pair(1200, 1203));
  EXPECT_EQ(bytes("%MW600"), Pair(1200, 1201));
  EXPECT_EQ(bytes("%MD0"), Pair(0, 3));
  EXPECT_EQ(bytes("%MW1").second, bytes("%MD0").second);
}

TEST(DirectAddressBytes, BitadrAgreesWithTheManuals) {
  // BITADR(var1 AT %IX2.3) = 16#80000013 = input base + 19 (000 L14552-14580, 002 L16032-16054).
  EXPECT_EQ(bit_number("%IX2.3"), 19u);
  EXPECT_EQ(bit_number("%IX2.3", AddressingMode::ByteOffset), 19u);
  EXPECT_EQ(bit_number("%IX2.3", AddressingMode::Word), 35u);
}

TEST(DirectAddressBytes, SingleNumberBitAddressCountsBits) {
  // `CMD_TMR(IN := %IX5, ...)` (002 L436): IEC bit numbering from the start of the area.
  DirectAddress a = parse_ok("%IX5");
  EXPECT_EQ(a.first_byte, 0u);
  EXPECT_EQ(a.bit, 5);
  EXPECT_EQ(bit_number("%QX75"), 75u);
  EXPECT_EQ(bit_number("%Q75", AddressingMode::Word), 75u);
}

// ---------------------------------------------------------------------------------------------
// The other addressing modes (002 L18286-18309)

TEST(DirectAddressModes, WordModeBitsAreWordDotBit) {
  // %MX96.0 is the first bit of word 96 = byte 192; bits run to 15 (002 L18212-18234, L18296-18298).
  EXPECT_EQ(bit_number("%MX96.0", AddressingMode::Word), 192u * 8);
  DirectAddress high = parse_ok("%MX96.15", AddressingMode::Word);
  EXPECT_EQ(high.first_byte, 193u);
  EXPECT_EQ(high.bit, 7);
  // The textbook's word-addressed I/O (000 L21971-21977).
  EXPECT_EQ(parse_ok("%IX0.8", AddressingMode::Word).first_byte, 1u);
  EXPECT_EQ(parse_ok("%IX0.11", AddressingMode::Word).bit, 3);
  EXPECT_EQ(parse_error("%IX0.16", AddressingMode::Word),
            "bit 16 is out of range: the bits of a word are numbered 0..15");
  // Sizes still count their own units: %MD48 = bytes 192..195, %MW96/%MW97 (002 L18212-18216).
  EXPECT_EQ(bytes("%MD48", AddressingMode::Word), Pair(192, 195));
  EXPECT_EQ(bytes("%MW97", AddressingMode::Word), Pair(194, 195));
}

TEST(DirectAddressModes, ByteOffsetModeNumbersAreBytes) {
  // D0 = B0..B3, W0 = B0+B1, W1 = B1+B2, W2 = B2+B3 (002 L18305-18309).
  AddressingMode m = AddressingMode::ByteOffset;
  EXPECT_EQ(bytes("%MD0", m), Pair(0, 3));
  EXPECT_EQ(bytes("%MW0", m), Pair(0, 1));
  EXPECT_EQ(bytes("%MW1", m), Pair(1, 2));
  EXPECT_EQ(bytes("%MW2", m), Pair(2, 3));
  EXPECT_EQ(bytes("%MD1", m), Pair(1, 4));
  EXPECT_EQ(bytes("%ML3", m), Pair(3, 10));
  EXPECT_EQ(bytes("%MX3.7", m), Pair(3, 3));
  EXPECT_EQ(parse_error("%MX3.8", m), "bit 8 is out of range: the bits of a byte are numbered 0..7");
}

// ---------------------------------------------------------------------------------------------
// Type fit

TEST(DirectAddressTypeFit, SizesThatAgree) {
  EXPECT_EQ(classify_address_type(parse_ok("%IX0.0"), 1, TypeCategory::Boolean), AddressFit::Fits);
  EXPECT_EQ(classify_address_type(parse_ok("%I0.0"), 1, TypeCategory::Boolean), AddressFit::Fits);
  // BIT at %MX0.4 (001 L5719).
  EXPECT_EQ(classify_address_type(parse_ok("%MX0.4"), 1, TypeCategory::Boolean), AddressFit::Fits);
  EXPECT_EQ(classify_address_type(parse_ok("%QB7"), 8, TypeCategory::Elementary), AddressFit::Fits);
  EXPECT_EQ(classify_address_type(parse_ok("%IW0"), 16, TypeCategory::Elementary), AddressFit::Fits);  // WORD, INT
  EXPECT_EQ(classify_address_type(parse_ok("%MD12"), 32, TypeCategory::Elementary),
            AddressFit::Fits);  // REAL (002 L10815)
  EXPECT_EQ(classify_address_type(parse_ok("%ID48"), 32, TypeCategory::Elementary), AddressFit::Fits);  // DWORD, TIME
  EXPECT_EQ(classify_address_type(parse_ok("%ML1"), 64, TypeCategory::Elementary), AddressFit::Fits);   // LWORD, LREAL
  EXPECT_TRUE(address_fits_type(parse_ok("%MW1"), 16, TypeCategory::Elementary));
  // An unknown size is not held against the declaration.
  EXPECT_EQ(classify_address_type(parse_ok("%MW1"), 0, TypeCategory::Elementary), AddressFit::Fits);
}

TEST(DirectAddressTypeFit, BitAddressNeedsBool) {
  // `bTest AT %IX10.3: INT` is a size mismatch (000 L3172).
  EXPECT_EQ(classify_address_type(parse_ok("%IX10.3"), 16, TypeCategory::Elementary), AddressFit::Mismatch);
  EXPECT_EQ(classify_address_type(parse_ok("%MX0.0"), 8, TypeCategory::Elementary), AddressFit::Mismatch);
  EXPECT_EQ(classify_address_type(parse_ok("%MX0.0"), 0, TypeCategory::NotElementary), AddressFit::Mismatch);
  EXPECT_FALSE(address_fits_type(parse_ok("%IX10.3"), 16, TypeCategory::Elementary));
}

TEST(DirectAddressTypeFit, OtherSizesAtByteAddressesAreStartAddresses) {
  // A REAL at %MW200 takes %MD100's bytes: the address is the start, the type the length (001 L1200).
  EXPECT_EQ(classify_address_type(parse_ok("%MW200"), 32, TypeCategory::Elementary), AddressFit::SizeDiffers);
  EXPECT_FALSE(address_fits_type(parse_ok("%MW200"), 32, TypeCategory::Elementary));
  // A BOOL at a byte/word/dword address takes a whole byte (002 L10851-10853, L18311-18313).
  EXPECT_EQ(classify_address_type(parse_ok("%QW0"), 1, TypeCategory::Boolean), AddressFit::SizeDiffers);
  EXPECT_EQ(classify_address_type(parse_ok("%MB3"), 1, TypeCategory::Boolean), AddressFit::SizeDiffers);
  // `arrInputBuffer AT %IW100 : ARRAY[1..32] OF REAL` (000 L9954): legal in CODESYS.
  EXPECT_EQ(classify_address_type(parse_ok("%IW100"), 0, TypeCategory::NotElementary), AddressFit::StartAddress);
  EXPECT_TRUE(address_fits_type(parse_ok("%IW100"), 0, TypeCategory::NotElementary));
  EXPECT_TRUE(address_fits_type(parse_ok("%MB0"), 0, TypeCategory::NotElementary));  // STRING, struct
}

TEST(DirectAddressTypeFit, WildcardsFitAnything) {
  for (auto category : {TypeCategory::Boolean, TypeCategory::Elementary, TypeCategory::NotElementary}) {
    EXPECT_EQ(classify_address_type(parse_ok("%I*"), 64, category), AddressFit::Fits);
    EXPECT_EQ(classify_address_type(parse_ok("%QX*"), 16, category), AddressFit::Fits);
  }
}

// ---------------------------------------------------------------------------------------------
// Overlaps

LocatedVariable located(std::string name, std::string_view address, uint64_t size_bytes = 0,
                        AddressingMode mode = AddressingMode::Byte) {
  LocatedVariable v;
  v.name = std::move(name);
  v.address = parse_ok(address, mode);
  v.size_bytes = size_bytes;
  return v;
}

// The overlapping pairs by name, "a/b" with a before b in the input.
std::vector<std::string> overlap_names(const std::vector<LocatedVariable>& vars) {
  std::vector<std::string> out;
  for (const AddressOverlap& o : find_address_overlaps(vars))
    out.push_back(vars[o.first].name + "/" + vars[o.second].name);
  return out;
}

using Names = std::vector<std::string>;

TEST(DirectAddressOverlap, WordOverlapsItsTwoBytes) {
  // %MW1 = low byte %MB2 + high byte %MB3 (001 L968, L976).
  std::vector<LocatedVariable> vars = {located("w1", "%MW1"), located("b1", "%MB1"), located("b2", "%MB2"),
                                       located("b3", "%MB3"), located("b4", "%MB4")};
  EXPECT_EQ(overlap_names(vars), (Names{"w1/b2", "w1/b3"}));
  auto overlaps = find_address_overlaps(vars);
  ASSERT_EQ(overlaps.size(), 2u);
  EXPECT_EQ(overlaps[0].first_shared_byte, 2u);
  EXPECT_EQ(overlaps[0].last_shared_byte, 2u);
  EXPECT_EQ(overlaps[1].first_shared_byte, 3u);
}

TEST(DirectAddressOverlap, DoubleWordOverlapsItsWords) {
  // %MD12 = %MW24..25; %ID48 = %IW96 + %IW97 (000 L4573-4577, 001 L968).
  std::vector<LocatedVariable> vars = {located("d", "%MD12"), located("w23", "%MW23"), located("w24", "%MW24"),
                                       located("w25", "%MW25"), located("w26", "%MW26")};
  EXPECT_EQ(overlap_names(vars), (Names{"d/w24", "d/w25"}));
  std::vector<LocatedVariable> input = {located("d", "%ID48"), located("lo", "%IW96"), located("hi", "%IW97"),
                                        located("b", "%IB195"), located("next", "%IB196")};
  EXPECT_EQ(overlap_names(input), (Names{"d/lo", "d/hi", "d/b", "hi/b"}));
}

TEST(DirectAddressOverlap, BitsOfOneByteDoNotOverlap) {
  std::vector<LocatedVariable> vars;
  vars.reserve(9);
  for (int bit = 0; bit < 8; ++bit) vars.push_back(located("x" + std::to_string(bit), "%MX0." + std::to_string(bit)));
  EXPECT_TRUE(find_address_overlaps(vars).empty());
  // The same bit twice does.
  vars.push_back(located("again", "%MX0.3"));
  EXPECT_EQ(overlap_names(vars), (Names{"x3/again"}));
}

TEST(DirectAddressOverlap, BitInsideByteWordAndDoubleWord) {
  // Forcing %MX0.0 also forces bit 0 of %MB0, %MW0 and %MD0 (001 L972-974).
  std::vector<LocatedVariable> vars = {located("x", "%MX0.0"), located("b", "%MB0"), located("w", "%MW0"),
                                       located("d", "%MD0"), located("other", "%MB4")};
  EXPECT_EQ(overlap_names(vars), (Names{"x/b", "x/w", "x/d", "b/w", "b/d", "w/d"}));
  // %MX1.3 lies in %MW0's high byte, not in %MW1 (bytes 2..3).
  std::vector<LocatedVariable> high = {located("x", "%MX1.3"), located("w0", "%MW0"), located("w1", "%MW1")};
  EXPECT_EQ(overlap_names(high), (Names{"x/w0"}));
}

TEST(DirectAddressOverlap, AreasAreSeparate) {
  std::vector<LocatedVariable> vars = {located("i", "%IW0"), located("q", "%QW0"), located("m", "%MW0"),
                                       located("ix", "%IX0.0")};
  EXPECT_EQ(overlap_names(vars), (Names{"i/ix"}));
}

TEST(DirectAddressOverlap, TypeSizeExtendsAStartAddress) {
  // A REAL AT %MW200 covers %MD100 = bytes 400..403 (001 L1200).
  std::vector<LocatedVariable> vars = {located("r", "%MW200", 4), located("d", "%MD100"), located("w201", "%MW201"),
                                       located("w202", "%MW202")};
  EXPECT_EQ(overlap_names(vars), (Names{"r/d", "r/w201", "d/w201"}));
  // An array AT %IW100 of 32 REALs covers bytes 200..327 (000 L9954).
  std::vector<LocatedVariable> array = {located("arr", "%IW100", 128), located("last", "%IB327"),
                                        located("after", "%IB328")};
  EXPECT_EQ(overlap_names(array), (Names{"arr/last"}));
}

TEST(DirectAddressOverlap, BoolAtAWordTakesOneByte) {
  // varbool1 AT %QW0 changes %QX0.0..%QX0.7 (002 L18311-18313), not byte 1.
  std::vector<LocatedVariable> vars = {located("varbool1", "%QW0", 1), located("x3", "%QX0.3"),
                                       located("x10", "%QX1.0")};
  EXPECT_EQ(overlap_names(vars), (Names{"varbool1/x3"}));
}

TEST(DirectAddressOverlap, WildcardsNeverOverlap) {
  // Two FB instances with `AT %I*` get their addresses from VAR_CONFIG (002 L11618-11686).
  std::vector<LocatedVariable> vars = {located("a", "%I*"), located("b", "%I*"), located("c", "%IX0.0")};
  EXPECT_TRUE(find_address_overlaps(vars).empty());
}

TEST(DirectAddressOverlap, HierarchiesAreComparedOnlyWhenEqual) {
  std::vector<LocatedVariable> vars = {located("a", "%IW2.5.7.1"),   located("b", "%IW2.5.8.1"),
                                       located("c", "%IB2.5.7.2"),   located("d", "%IW1"),
                                       located("e", "%IX2.5.7.3.0"), located("f", "%IX2.5.3.0")};
  EXPECT_EQ(overlap_names(vars), (Names{"a/c", "a/e"}));
}

TEST(DirectAddressOverlap, ByteOffsetModeOverlapsNeighbouringWords) {
  // "W1 or D1, D2, D3 must not be used to avoid overlaps" (002 L18305-18309).
  AddressingMode m = AddressingMode::ByteOffset;
  std::vector<LocatedVariable> vars = {located("w0", "%MW0", 0, m), located("w1", "%MW1", 0, m),
                                       located("w2", "%MW2", 0, m), located("d0", "%MD0", 0, m)};
  EXPECT_EQ(overlap_names(vars), (Names{"w0/w1", "w0/d0", "w1/w2", "w1/d0", "w2/d0"}));
  // The default mode keeps them apart.
  std::vector<LocatedVariable> apart = {located("w0", "%MW0"), located("w1", "%MW1"), located("w2", "%MW2")};
  EXPECT_TRUE(find_address_overlaps(apart).empty());
}

TEST(DirectAddressOverlap, ResultIsSortedAndIndependentOfInputGrouping) {
  std::vector<LocatedVariable> vars = {located("z", "%QB9"), located("a", "%MD0"), located("q", "%QW4"),
                                       located("b", "%MB3"), located("y", "%QX9.1")};
  auto overlaps = find_address_overlaps(vars);
  ASSERT_EQ(overlaps.size(), 4u);
  EXPECT_EQ(overlap_names(vars), (Names{"z/q", "z/y", "a/b", "q/y"}));
  for (const auto& o : overlaps) EXPECT_LT(o.first, o.second);
  EXPECT_TRUE(std::is_sorted(overlaps.begin(), overlaps.end(), [](const auto& l, const auto& r) {
    return std::tie(l.first, l.second) < std::tie(r.first, r.second);
  }));
}

TEST(DirectAddressOverlap, HugeTypeSizeDoesNotWrap) {
  std::vector<LocatedVariable> vars = {located("huge", "%ML4294967295", UINT64_MAX), located("low", "%MB0"),
                                       located("high", "%MX4294967295.7")};
  EXPECT_TRUE(find_address_overlaps(vars).empty());
  vars.push_back(located("inside", "%ML4294967295"));
  EXPECT_EQ(overlap_names(vars), (Names{"huge/inside"}));
}

// A naive O(n^2) reference on random declarations.
TEST(DirectAddressOverlap, MatchesQuadraticReference) {
  std::mt19937 random(61131);
  const char* sizes[] = {"X", "B", "W", "D", "L"};
  const char* areas[] = {"I", "Q", "M"};
  std::vector<LocatedVariable> vars;
  for (int i = 0; i < 600; ++i) {
    std::string size = sizes[random() % 5];
    std::string text = std::string("%") + areas[random() % 3] + size;
    if (random() % 10 == 0) text += std::to_string(random() % 2) + ".";  // a hierarchy level
    text += std::to_string(random() % 40);
    if (size == "X") text += "." + std::to_string(random() % 8);
    uint64_t type_size = size == "X" ? 0 : (random() % 4 == 0 ? random() % 12 : 0);
    vars.push_back(located("v" + std::to_string(i), text, type_size));
  }
  auto bits = [](const LocatedVariable& v) {
    const DirectAddress& a = v.address;
    if (a.is_bit()) return std::pair<uint64_t, uint64_t>(a.first_byte * 8 + *a.bit, a.first_byte * 8 + *a.bit);
    uint64_t n = v.size_bytes ? v.size_bytes : a.last_byte - a.first_byte + 1;
    return std::pair<uint64_t, uint64_t>(a.first_byte * 8, (a.first_byte + n) * 8 - 1);
  };
  std::vector<std::pair<size_t, size_t>> expected;
  for (size_t i = 0; i < vars.size(); ++i) {
    for (size_t j = i + 1; j < vars.size(); ++j) {
      const DirectAddress& a = vars[i].address;
      const DirectAddress& b = vars[j].address;
      if (a.area != b.area || a.hierarchy != b.hierarchy) continue;
      auto [a0, a1] = bits(vars[i]);
      auto [b0, b1] = bits(vars[j]);
      if (a0 <= b1 && b0 <= a1) expected.emplace_back(i, j);
    }
  }
  std::vector<std::pair<size_t, size_t>> actual;
  for (const auto& o : find_address_overlaps(vars)) actual.emplace_back(o.first, o.second);
  EXPECT_GT(expected.size(), 100u);
  EXPECT_EQ(actual, expected);
}

TEST(DirectAddressOverlap, ManyDisjointVariablesAreFast) {
  // 100,000 consecutive words and bits: the sweep must not compare every pair.
  std::vector<LocatedVariable> vars;
  vars.reserve(100000);
  for (int i = 0; i < 50000; ++i) vars.push_back(located("w", "%MW" + std::to_string(i)));
  for (int i = 0; i < 50000; ++i) vars.push_back(located("x", "%QX" + std::to_string(i) + ".1"));
  EXPECT_TRUE(find_address_overlaps(vars).empty());
}

// ---------------------------------------------------------------------------------------------
// The seed corpus: every address an example writes must be valid, unless its header says otherwise.

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// The comments before the first line of code (source line numbers, expected result, notes).
std::string header_of(const std::string& text) {
  std::string header;
  size_t i = 0;
  while (true) {
    while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
    if (text.compare(i, 2, "(*") != 0) return header;
    size_t end = text.find("*)", i);
    if (end == std::string::npos) end = text.size();
    header += text.substr(i, end - i) + "\n";
    i = end + 2;
  }
}

// The header names the address (or its byte, as in "%IX0.8..%IX0.11") and says it is not valid
// everywhere.
bool header_flags_address(const std::string& header, const std::string& address) {
  std::string h = lower(header);
  size_t dot = address.rfind('.');
  std::string named = lower(dot == std::string::npos ? address : address.substr(0, dot + 1));
  if (h.find(named) == std::string::npos) return false;
  for (const char* word : {"wrong", "invalid", "reject", "only valid", "word-addressed", "mismatch"}) {
    if (h.find(word) != std::string::npos) return true;
  }
  return false;
}

struct FoundAddress {
  std::string text;
  bool in_at = false;  // in an `AT %...` declaration
};

// Every direct_variable token of the file's parse tree, except CODESYS's `x.%X3` partial access.
std::vector<FoundAddress> addresses_in(const Document& doc) {
  std::vector<FoundAddress> found;
  const SyntaxTree* tree = doc.tree();
  if (!tree) return found;
  tree->for_each_token([&](const Token& token) {
    if (token.node_kind != "direct_variable") return;
    std::string text = tree->text().substr(token.range.begin, token.range.end - token.range.begin);
    if (text.size() > 1 && std::string("IQMiqm").find(text[1]) == std::string::npos) return;
    SyntaxNode node = tree->root().descendant_for_range(token.range.begin, token.range.end);
    bool in_at = node && node.parent() && node.parent().kind() == "location";
    found.push_back({text, in_at});
  });
  return found;
}

// Every `AT %...` in a text, comments and prose included (the .txt examples are not parsed).
std::vector<std::string> at_addresses_in(const std::string& text) {
  auto is_word_char = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  std::vector<std::string> found;
  for (size_t i = 0; i + 2 < text.size(); ++i) {
    if (lower(text.substr(i, 2)) != "at" || (i > 0 && is_word_char(text[i - 1]))) continue;
    size_t p = i + 2;
    while (p < text.size() && (text[p] == ' ' || text[p] == '\t')) ++p;
    if (p >= text.size() || text[p] != '%') continue;
    size_t end = p + 1;
    while (end < text.size() && (is_word_char(text[end]) || text[end] == '.' || text[end] == '*')) ++end;
    while (end > p + 1 && text[end - 1] == '.') --end;  // "AT %MW100.." in prose
    if (end == p + 1) continue;                         // "AT%" as the name of the feature (003 S4000)
    found.push_back(text.substr(p, end - p));
  }
  return found;
}

// Checks one address of a corpus file; returns whether it needed the word-addressed reading.
bool expect_valid(const std::string& file, const std::string& header, const std::string& address) {
  DirectAddressResult result = parse_direct_address(address);
  if (result.ok()) return false;
  // Only the header may excuse an address, and then it must be valid on some target.
  EXPECT_TRUE(header_flags_address(header, address)) << file << ": " << address << ": " << result.error;
  EXPECT_TRUE(parse_direct_address(address, AddressingMode::Word).ok()) << file << ": " << address;
  return true;
}

TEST(DirectAddressCorpus, EverySeedAddressParses) {
  auto root = test::shared_dir() / "corpus/seeds";
  ASSERT_TRUE(std::filesystem::exists(root)) << "the shared corpus must be at " << root;
  size_t in_code = 0;
  size_t after_at = 0;
  std::set<std::string> word_addressed_files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(root)) {
    if (!entry.is_regular_file()) continue;
    std::string text = test::read_file(entry.path());
    if (text.find('%') == std::string::npos) continue;
    std::string name = std::filesystem::relative(entry.path(), root).string();
    std::string header = header_of(text);
    for (const std::string& address : at_addresses_in(text)) {
      ++after_at;
      if (expect_valid(name, header, address)) word_addressed_files.insert(name);
    }
    if (source_kind_of(entry.path()) == SourceKind::None) continue;
    std::string error;
    auto doc = Document::load(entry.path(), &error);
    ASSERT_TRUE(doc) << error;
    for (const FoundAddress& address : addresses_in(*doc)) {
      ++in_code;
      if (expect_valid(name, header, address.text)) word_addressed_files.insert(name);
    }
  }
  // About 135 `AT %` texts and 180 addresses in code; a drop means the scan lost them.
  EXPECT_GT(after_at, 120u);
  EXPECT_GT(in_code, 160u);
  // The two engineering examples with %IX0.8.. (000 L21516, L21971-21977), whose headers say so.
  EXPECT_EQ(word_addressed_files,
            (std::set<std::string>{"000b/093_fb_forward_backward.st", "000b/095_const_pressure_water_supply.st"}));
}

}  // namespace
}  // namespace rung::check
