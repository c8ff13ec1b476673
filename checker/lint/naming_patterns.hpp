// Name prefixes of rung.toml [lint.naming] (rules L001-L004): a pattern is one prefix or several
// alternatives separated by '|' ("F_|FC_"); an empty pattern means "not checked". Matching is
// case-sensitive, as naming conventions are: bStart follows "b", BStart does not.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace rung::lint::naming {

// The alternatives of a pattern, blanks around each trimmed, empty ones dropped.
std::vector<std::string_view> alternatives(std::string_view pattern);

// Whether `name` starts with one of the alternatives and goes on after it as a new word: a prefix
// ending in a letter or digit ("b", "FB") must be followed by an upper-case letter, a digit or
// '_' (bStart, FBMotor, b_Start; not bstart), a prefix ending in another character ("FB_", "g_")
// by anything. The name must be longer than the prefix.
bool has_prefix(std::string_view name, std::string_view pattern);

// Like has_prefix, for prefixes that concatenate: `chain` holds one pattern per level of a type
// (POINTER TO ARRAY OF BYTE: "p", "a", "by"). The first level is required, the next ones may
// follow it (pData, paData, pabyData all follow the chain p/a/by). An empty level ends the chain.
bool has_prefix_chain(std::string_view name, std::span<const std::string> chain);

// The first length of `name` that a prefix of `pattern` matches, or 0 (to strip a scope prefix
// such as "g_" before the type prefix is checked).
size_t matched_prefix_length(std::string_view name, std::string_view pattern);

// A name that would follow `pattern`: its first alternative, then `name` with its first letter in
// upper case when the prefix ends in a letter or digit ("b" + "start" -> "bStart").
std::string suggested_name(std::string_view name, std::string_view pattern);

// The pattern as a message shows it: 'FB_' or one of 'F_', 'FC_'.
std::string describe_pattern(std::string_view pattern);

}  // namespace rung::lint::naming
