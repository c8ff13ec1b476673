// Identifiers in IEC 61131-3 are case-insensitive (ASCII). These helpers compare, hash and
// upper-case names without allocating, and suggest near names for "did you mean" hints.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <string_view>

namespace rung::check {

constexpr char ascii_upper(char c) {
  return (c >= 'a' && c <= 'z') ? static_cast<char>(c - 32) : c;
}

// A byte that may stand in an identifier: ASCII letters, digits, '_', and any byte of a UTF-8
// sequence (identifiers may hold letters beyond ASCII). For whole-word searches in source text.
constexpr bool is_identifier_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
         static_cast<unsigned char>(c) >= 0x80;
}

bool names_equal(std::string_view a, std::string_view b);
std::string upper_name(std::string_view name);

// Hash and equality for maps keyed by names (heterogeneous: look up with any string_view).
struct NameHash {
  using is_transparent = void;
  size_t operator()(std::string_view name) const;
};
struct NameEqual {
  using is_transparent = void;
  bool operator()(std::string_view a, std::string_view b) const { return names_equal(a, b); }
};

// Case-insensitive edit distance (Damerau: a swap of two neighbours costs 1), capped at `limit` + 1.
size_t name_distance(std::string_view a, std::string_view b, size_t limit);

// The candidate closest to `name` if it is close enough to be a likely typo; empty otherwise.
// Deterministic: ties go to the alphabetically first candidate.
std::string_view closest_name(std::string_view name, std::span<const std::string_view> candidates);

}  // namespace rung::check
