// Direct addresses (`AT %IX0.0`, `%MW1`, `%QD4`, `%I*`): what an address text means, whether a
// type may sit at it, and which located variables share memory.
//
// Sources (line numbers in /work/shared/seeds/*.txt; digests in /work/shared/docs/seeds/):
//   000 = CODESYS V3 textbook, 001 = Kinco AK800 manual, 002 = MP300 manual (CODESYS V2.3/V3 help),
//   003 = OpenPCS manual.
// Syntax: '%' + area I/Q/M + optional size X/B/W/D/L (none = bit) + dotted unsigned numbers, or '*'
// for an address the configuration assigns later (000 L4519-4557, 002 L18243-18267, L11609,
// 003 L1164-1184, L11224-11243).
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "parser/diagnostic.hpp"

namespace rung::check {

enum class AddressArea { Input, Output, Memory };  // %I, %Q, %M
char area_letter(AddressArea area);  // I, Q or M

// The size prefix. None is written without a letter and means a bit, like X (002 L18257-18271:
// %Q7.5 = %QX7.5; 003 L1176: %I0.0 = %IX0.0).
enum class AddressSize { None, Bit, Byte, Word, Double, Long };

// How the number of an address maps to bytes. The manuals disagree, and a target setting decides
// (002 L18286-18290), so the checker takes it from the project.
enum class AddressingMode {
  // CODESYS V3 as the textbook and AK800 describe it, and the default: the number of a B/W/D/L
  // address counts units of its own size (%MW1 = bytes 2..3, %MD12 = bytes 48..51 = %MW24..25,
  // 000 L4569-4597, 001 L968-970, L5331-5333), and a bit address is byte.bit with bits 0..7 of
  // that byte (001 L976, L1016-1017).
  Byte,
  // Word-oriented "IEC addressing" (002 L18212-18234, L18296-18298): sizes count like Byte, but
  // a bit address is word.bit with bits 0..15 (%MX96.15 = bit 7 of byte 193). BITADR(%IX2.3) is
  // 35 here and 19 in Byte mode (002 L16032-16054). The textbook's engineering examples use
  // %IX0.8..%IX0.11, valid only in this mode (000 L21516, L21971-21977).
  Word,
  // "Byte addressing mode" (002 L18296-18309): every number is a byte offset whatever the size,
  // so %MW0 and %MW1 overlap in byte 1 and %MD1 = bytes 1..4. OpenPCS reads word addresses this
  // way too (003 L7091-7094: %QW1.0 starts at the second output byte; L13828-13832 asks for even
  // word addresses). Note: OpenPCS writes byte-sized addresses with two fields (%IB0.0, %ID0.4,
  // 003 L1178-1184) whose second field it does not explain; they are read as IEC hierarchical
  // addresses here (see DirectAddress::hierarchy), so they only overlap addresses of the same
  // first field, which may miss an overlap but never invents one.
  ByteOffset,
};

struct DirectAddress {
  AddressArea area = AddressArea::Input;
  AddressSize size = AddressSize::None;
  // `%I*` / `%Q*` (CODESYS, 002 L11605-11609) and `%M*` (IEC): no location yet; VAR_CONFIG or
  // the I/O mapping gives it. The fields below are then empty/zero.
  bool wildcard = false;
  // The dotted numbers as written, each at most 4294967295 (003 L11075), at most 8 (L11166).
  std::vector<uint32_t> numbers;
  // IEC hierarchical addresses (%IW2.5.7.1 = bus 2, rack 5, module 7, channel 1, 003 L11235-11241)
  // name a module before the location inside it. For a bit address the last two numbers are the
  // byte (or word) and the bit, for any other size the last number is the unit; the numbers
  // before are the hierarchy, and addresses only overlap within the same hierarchy.
  std::vector<uint32_t> hierarchy;
  // The bytes the address itself covers (inclusive), counted from the start of the area.
  uint64_t first_byte = 0;
  uint64_t last_byte = 0;
  // For a bit address, the bit inside first_byte (0..7). A bit address with a single number
  // (%IX5, IEC style, 002 L436) counts bits from the start of the area: byte 0, bit 5. CODESYS
  // itself writes byte.bit; callers that want to insist can test `numbers.size() == 1`.
  std::optional<uint8_t> bit;

  // A bit address, or `%IX*`. `%I*` has no size at all.
  bool is_bit() const { return size == AddressSize::Bit || (size == AddressSize::None && !wildcard); }
  // 1, 8, 16, 32 or 64; 0 for a wildcard without size.
  uint32_t size_bits() const;
};

struct DirectAddressResult {
  std::optional<DirectAddress> address;
  std::string error;          // set when address is empty
  uint32_t error_offset = 0;  // byte offset into the parsed text where the problem starts

  bool ok() const { return address.has_value(); }
};

// Reads a whole address token such as "%MW1" (case-insensitive, no surrounding blanks). Never
// throws; any malformed text gives an error message.
DirectAddressResult parse_direct_address(std::string_view text, AddressingMode mode = AddressingMode::Byte);

// The canonical spelling: upper case, explicit X for bits ("%q7.5" -> "%QX7.5").
std::string format_direct_address(const DirectAddress& address);

// What the caller knows about the declared type.
enum class TypeCategory {
  Boolean,        // BOOL, BIT
  Elementary,     // any other elementary type: integers, bit strings, REAL, times, dates, enums, pointers
  NotElementary,  // arrays, structures, strings, function block instances
};

enum class AddressFit {
  Fits,  // the sizes agree, or the address is a wildcard
  // A non-elementary type at a byte-sized address: CODESYS takes the address as the start and the
  // type gives the length (000 L9954: `arrInputBuffer AT %IW100 : ARRAY[1..32] OF REAL`).
  // OpenPCS and the AK800 manual forbid arrays/structs at addresses (003 L1154-1156, 001 L2366):
  // a dialect rule the caller applies, not this one.
  StartAddress,
  // An elementary type of another size at a byte-sized address. CODESYS accepts it with the same
  // start-address reading (001 L1200: a REAL "at %MD100" is declared AT %MW200; 002 L10851-10853:
  // a BOOL at a byte/word/dword address takes one whole byte), so it is worth a warning at most.
  SizeDiffers,
  // Anything but BOOL/BIT at a bit address (000 L3172: `bTest AT %IX10.3 : INT`).
  Mismatch,
};

// `type_bits` is the size of an Elementary type (16 for INT, 32 for REAL and TIME, ...); 0 means
// unknown and is not held against the declaration. It is ignored for the other categories.
AddressFit classify_address_type(const DirectAddress& address, uint32_t type_bits, TypeCategory category);

// True when the type agrees with the address: Fits or StartAddress.
bool address_fits_type(const DirectAddress& address, uint32_t type_bits, TypeCategory category);

// A variable declared AT an address.
struct LocatedVariable {
  std::string name;
  TextRange range;
  DirectAddress address;
  // Size of the declared type in bytes; 0 = unknown, use the address's own size. A byte-sized
  // address is only the start of the variable (001 L1200), so a REAL AT %MW200 covers 4 bytes
  // and a BOOL AT %QW0 one byte (002 L10851-10853, L18311-18313). A bit address covers its bit.
  uint64_t size_bytes = 0;
};

struct AddressOverlap {
  size_t first = 0;  // index into the input, first < second
  size_t second = 0;
  uint64_t first_shared_byte = 0;  // the bytes both cover (inclusive)
  uint64_t last_shared_byte = 0;
};

// Pairs of variables that share memory: same area and hierarchy, intersecting bits. Two bits of
// one byte do not overlap; a bit inside a byte or word another variable covers does (forcing
// %MX0.0 also changes %MB0, %MW0 and %MD0, 001 L972-974). Wildcards have no location yet and never
// overlap. Sorted by (first, second). O(n log n + pairs).
std::vector<AddressOverlap> find_address_overlaps(std::span<const LocatedVariable> variables);

}  // namespace rung::check
