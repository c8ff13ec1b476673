#include "checker/semantic/direct_address.hpp"

#include <algorithm>
#include <limits>
#include <string>
#include <tuple>
#include <variant>

#include <fmt/format.h>

namespace rung::check {
namespace {

// Limits OpenPCS states and no other manual contradicts: a field is at most 4294967295 (S1011,
// 003 L11070-11077) and an address has at most 8 fields (S1017, 003 L11161-11166).
constexpr uint64_t kMaxField = std::numeric_limits<uint32_t>::max();
constexpr size_t kMaxFields = 8;
constexpr const char* kAreaExpected = "'%' must be followed by an area: I (input), Q (output) or M (memory)";

char upper(char c) {
  return (c >= 'a' && c <= 'z') ? static_cast<char>(c - 'a' + 'A') : c;
}

bool is_digit(char c) {
  return c >= '0' && c <= '9';
}

bool is_printable(char c) {
  return c >= 0x21 && c <= 0x7e;
}

// A character for a message; raw bytes of UTF-8 or control characters would garble it.
std::string describe(char c) {
  if (is_printable(c)) return std::string("'") + c + "'";
  return c == ' ' || c == '\t' ? "blank" : "character";
}

// Long texts (a fuzzer's million digits) are cut so that messages stay readable.
std::string excerpt(std::string_view text) {
  constexpr size_t kMax = 24;
  return text.size() <= kMax ? std::string(text) : std::string(text.substr(0, kMax)) + "...";
}

DirectAddressResult succeed(DirectAddress address) {
  DirectAddressResult result;
  result.address = std::move(address);
  return result;
}

DirectAddressResult fail(size_t offset, std::string message) {
  DirectAddressResult result;
  result.error = std::move(message);
  result.error_offset = static_cast<uint32_t>(std::min<size_t>(offset, std::numeric_limits<uint32_t>::max()));
  return result;
}

std::optional<AddressArea> area_of(char c) {
  switch (upper(c)) {
    case 'I': return AddressArea::Input;
    case 'Q': return AddressArea::Output;
    case 'M': return AddressArea::Memory;
    default: return std::nullopt;
  }
}

std::optional<AddressSize> size_of(char c) {
  switch (upper(c)) {
    case 'X': return AddressSize::Bit;
    case 'B': return AddressSize::Byte;
    case 'W': return AddressSize::Word;
    case 'D': return AddressSize::Double;
    case 'L': return AddressSize::Long;
    default: return std::nullopt;
  }
}

char size_letter(AddressSize size) {
  switch (size) {
    case AddressSize::None:
    case AddressSize::Bit: return 'X';
    case AddressSize::Byte: return 'B';
    case AddressSize::Word: return 'W';
    case AddressSize::Double: return 'D';
    case AddressSize::Long: return 'L';
  }
  return '?';
}

uint64_t unit_bytes(AddressSize size) {
  switch (size) {
    case AddressSize::Word: return 2;
    case AddressSize::Double: return 4;
    case AddressSize::Long: return 8;
    default: return 1;
  }
}

// The message when the character after '%' is not an area letter. CODESYS's partial access of a
// variable (`x.%X3`, the grammar's other direct_variable form) looks like an address but is not.
DirectAddressResult unknown_area(std::string_view text) {
  bool rest_is_number = text.size() > 2 && std::all_of(text.begin() + 2, text.end(), is_digit);
  if (size_of(text[1]) && rest_is_number) {
    return fail(1, fmt::format("'{0}' is a bit/byte access of a variable (x.{0}), not a direct address: an address "
                               "needs an area I, Q or M",
                               excerpt(text)));
  }
  if (!is_printable(text[1])) return fail(1, kAreaExpected);
  return fail(1, describe(text[1]) + " is not an address area: use I (input), Q (output) or M (memory)");
}

// The dotted numbers with the offsets where each starts.
struct Fields {
  std::vector<uint32_t> numbers;
  std::vector<size_t> offsets;
};

// Reads "n{.n}" from `pos` to the end of `text`, or says what is wrong.
std::variant<Fields, DirectAddressResult> read_fields(std::string_view text, size_t pos) {
  Fields fields;
  while (true) {
    size_t start = pos;
    uint64_t value = 0;
    while (pos < text.size() && is_digit(text[pos])) {
      value = std::min(value * 10 + static_cast<uint64_t>(text[pos] - '0'), kMaxField + 1);
      ++pos;
    }
    if (pos == start) {
      if (fields.numbers.empty()) return fail(start, fmt::format("'{}' has no address number", excerpt(text.substr(0, start))));
      return fail(start, "'.' in a direct address must be followed by a number");
    }
    if (value > kMaxField) {
      return fail(start, "address number " + excerpt(text.substr(start, pos - start)) + " is larger than 4294967295");
    }
    fields.numbers.push_back(static_cast<uint32_t>(value));
    fields.offsets.push_back(start);
    if (pos == text.size()) return fields;
    if (text[pos] != '.') return fail(pos, "unexpected " + describe(text[pos]) + " in direct address");
    ++pos;
  }
}

// Where a bit address lies. The last two numbers are byte.bit (word.bit in Word mode); a single
// number counts bits from the start of the area, as IEC writes %QX75.
std::optional<DirectAddressResult> place_bit(DirectAddress& address, const Fields& fields, AddressingMode mode) {
  const auto& n = address.numbers;
  if (n.size() == 1) {
    address.first_byte = n[0] / 8;
    address.bit = static_cast<uint8_t>(n[0] % 8);
  } else {
    uint64_t unit = n[n.size() - 2];
    uint32_t bit = n.back();
    bool words = mode == AddressingMode::Word;
    if (bit > (words ? 15u : 7u)) {
      return fail(fields.offsets.back(), "bit " + std::to_string(bit) + " is out of range: the bits of a " +
                                             (words ? "word are numbered 0..15" : "byte are numbered 0..7"));
    }
    address.first_byte = (words ? unit * 2 : unit) + bit / 8;
    address.bit = static_cast<uint8_t>(bit % 8);
    address.hierarchy.assign(n.begin(), n.end() - 2);
  }
  address.last_byte = address.first_byte;
  return std::nullopt;
}

// Where a B/W/D/L address lies: its last number counts units of its size, or bytes in ByteOffset mode.
void place_unit(DirectAddress& address, AddressingMode mode) {
  uint64_t unit = address.numbers.back();
  uint64_t bytes = unit_bytes(address.size);
  address.first_byte = mode == AddressingMode::ByteOffset ? unit : unit * bytes;
  address.last_byte = address.first_byte + bytes - 1;
  address.hierarchy.assign(address.numbers.begin(), address.numbers.end() - 1);
}

}  // namespace

char area_letter(AddressArea area) {
  switch (area) {
    case AddressArea::Input: return 'I';
    case AddressArea::Output: return 'Q';
    case AddressArea::Memory: return 'M';
  }
  return '?';
}


uint32_t DirectAddress::size_bits() const {
  switch (size) {
    case AddressSize::None: return wildcard ? 0 : 1;
    case AddressSize::Bit: return 1;
    case AddressSize::Byte: return 8;
    case AddressSize::Word: return 16;
    case AddressSize::Double: return 32;
    case AddressSize::Long: return 64;
  }
  return 0;
}

DirectAddressResult parse_direct_address(std::string_view text, AddressingMode mode) {
  if (text.empty() || text[0] != '%') return fail(0, "a direct address starts with '%'");
  if (text.size() == 1) return fail(1, kAreaExpected);
  std::optional<AddressArea> area = area_of(text[1]);
  if (!area) return unknown_area(text);

  DirectAddress address;
  address.area = *area;
  size_t pos = 2;
  if (pos < text.size()) {
    if (auto size = size_of(text[pos])) {
      address.size = *size;
      ++pos;
    }
  }
  if (pos < text.size() && text[pos] == '*') {
    if (pos + 1 < text.size()) return fail(pos + 1, "nothing may follow '*' (an address the configuration assigns)");
    address.wildcard = true;
    return succeed(std::move(address));
  }

  auto fields = read_fields(text, pos);
  if (auto* error = std::get_if<DirectAddressResult>(&fields)) return std::move(*error);
  const Fields& read = std::get<Fields>(fields);
  if (read.numbers.size() > kMaxFields) {
    return fail(read.offsets[kMaxFields],
                "a direct address has at most 8 levels, this one has " + std::to_string(read.numbers.size()));
  }
  address.numbers = read.numbers;
  if (address.is_bit()) {
    if (auto error = place_bit(address, read, mode)) return std::move(*error);
  } else {
    place_unit(address, mode);
  }
  return succeed(std::move(address));
}

std::string format_direct_address(const DirectAddress& address) {
  std::string out = "%";
  out += area_letter(address.area);
  if (address.wildcard) {
    if (address.size != AddressSize::None) out += size_letter(address.size);
    return out + "*";
  }
  out += size_letter(address.size);
  for (size_t i = 0; i < address.numbers.size(); ++i) {
    if (i > 0) out += '.';
    out += std::to_string(address.numbers[i]);
  }
  return out;
}

AddressFit classify_address_type(const DirectAddress& address, uint32_t type_bits, TypeCategory category) {
  if (address.wildcard) return AddressFit::Fits;
  if (address.is_bit()) return category == TypeCategory::Boolean ? AddressFit::Fits : AddressFit::Mismatch;
  switch (category) {
    case TypeCategory::NotElementary: return AddressFit::StartAddress;
    case TypeCategory::Boolean: return AddressFit::SizeDiffers;  // a whole byte, 002 L10851-10853
    case TypeCategory::Elementary:
      return type_bits == 0 || type_bits == address.size_bits() ? AddressFit::Fits : AddressFit::SizeDiffers;
  }
  return AddressFit::Mismatch;
}

bool address_fits_type(const DirectAddress& address, uint32_t type_bits, TypeCategory category) {
  AddressFit fit = classify_address_type(address, type_bits, category);
  return fit == AddressFit::Fits || fit == AddressFit::StartAddress;
}

namespace {

// The bits a located variable covers, inclusive, counted from the start of its area.
struct Extent {
  size_t index;
  uint64_t first_bit;
  uint64_t last_bit;
};

// Far beyond any real area (2^32 doublewords) and far from overflowing when multiplied by 8.
constexpr uint64_t kMaxByte = uint64_t{1} << 56;

Extent extent_of(const LocatedVariable& variable, size_t index) {
  const DirectAddress& a = variable.address;
  if (a.is_bit()) {
    uint64_t bit = a.first_byte * 8 + a.bit.value_or(0);
    return {index, bit, bit};
  }
  uint64_t bytes = variable.size_bytes != 0 ? variable.size_bytes : a.last_byte - a.first_byte + 1;
  uint64_t last_byte = std::min(a.first_byte + std::min(bytes, kMaxByte) - 1, kMaxByte);
  return {index, a.first_byte * 8, last_byte * 8 + 7};
}

// Variables can only share memory within one area and one module of a hierarchical address.
bool same_group(const DirectAddress& a, const DirectAddress& b) {
  return a.area == b.area && a.hierarchy == b.hierarchy;
}

bool group_less(const DirectAddress& a, const DirectAddress& b) {
  return std::tie(a.area, a.hierarchy) < std::tie(b.area, b.hierarchy);
}

AddressOverlap overlap_of(const Extent& a, const Extent& b) {
  return {std::min(a.index, b.index), std::max(a.index, b.index), std::max(a.first_bit, b.first_bit) / 8,
          std::min(a.last_bit, b.last_bit) / 8};
}

}  // namespace

std::vector<AddressOverlap> find_address_overlaps(std::span<const LocatedVariable> variables) {
  std::vector<Extent> extents;
  for (size_t i = 0; i < variables.size(); ++i) {
    if (!variables[i].address.wildcard) extents.push_back(extent_of(variables[i], i));
  }
  auto address = [&](const Extent& e) -> const DirectAddress& { return variables[e.index].address; };
  std::sort(extents.begin(), extents.end(), [&](const Extent& a, const Extent& b) {
    if (group_less(address(a), address(b))) return true;
    if (group_less(address(b), address(a))) return false;
    return std::tie(a.first_bit, a.index) < std::tie(b.first_bit, b.index);
  });

  // Sweep in order of first bit, keeping the extents that may still reach the current one in a
  // min-heap by last bit: after dropping those that end before it, every one left overlaps it.
  std::vector<AddressOverlap> overlaps;
  std::vector<Extent> active;
  auto ends_later = [](const Extent& a, const Extent& b) { return a.last_bit > b.last_bit; };
  for (size_t i = 0; i < extents.size(); ++i) {
    const Extent& current = extents[i];
    if (i > 0 && !same_group(address(extents[i - 1]), address(current))) active.clear();
    while (!active.empty() && active.front().last_bit < current.first_bit) {
      std::pop_heap(active.begin(), active.end(), ends_later);
      active.pop_back();
    }
    for (const Extent& other : active) overlaps.push_back(overlap_of(other, current));
    active.push_back(current);
    std::push_heap(active.begin(), active.end(), ends_later);
  }
  std::sort(overlaps.begin(), overlaps.end(), [](const AddressOverlap& a, const AddressOverlap& b) {
    return std::tie(a.first, a.second) < std::tie(b.first, b.second);
  });
  return overlaps;
}

}  // namespace rung::check
