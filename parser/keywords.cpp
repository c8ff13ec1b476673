#include "parser/keywords.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <string>
#include <vector>

namespace rung::keywords {

std::string upper(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

namespace {

// Sorted, so that lookups are a binary search. Not here although some compilers reserve them:
// LTIME, LDATE, LTOD, LDT (64-bit types added in CODESYS V3.5; CODESYS 2.3 code such as OSCAT
// BASIC names variables LTIME and LDT) and R_EDGE / F_EDGE (qualifiers only after a BOOL input's
// type; OSCAT names a variable r_edge).
constexpr auto kReserved = std::to_array<std::string_view>({
    "AND",
    "AND_THEN",
    "ARRAY",
    "BOOL",
    "BY",
    "BYTE",
    "CASE",
    "CONSTANT",
    "DATE",
    "DATE_AND_TIME",
    "DINT",
    "DO",
    "DT",
    "DWORD",
    "ELSE",
    "ELSIF",
    "END_ACTION",
    "END_CASE",
    "END_CLASS",
    "END_CONFIGURATION",
    "END_FOR",
    "END_FUNCTION",
    "END_FUNCTION_BLOCK",
    "END_IF",
    "END_INTERFACE",
    "END_METHOD",
    "END_NAMESPACE",
    "END_PROGRAM",
    "END_PROPERTY",
    "END_REPEAT",
    "END_RESOURCE",
    "END_STEP",
    "END_STRUCT",
    "END_TRANSITION",
    "END_TYPE",
    "END_UNION",
    "END_VAR",
    "END_WHILE",
    "EXIT",
    "EXTENDS",
    "FALSE",
    "FOR",
    "FUNCTION",
    "FUNCTION_BLOCK",
    "IF",
    "IMPLEMENTS",
    "INT",
    "LINT",
    "LREAL",
    "LWORD",
    "MOD",
    "NON_RETAIN",
    "NOT",
    "OF",
    "OR",
    "OR_ELSE",
    "PERSISTENT",
    "POINTER",
    "PROGRAM",
    "READ_ONLY",
    "READ_WRITE",
    "REAL",
    "REFERENCE",
    "REF_TO",
    "REPEAT",
    "RETAIN",
    "RETURN",
    "SINT",
    "STRING",
    "STRUCT",
    "SUPER",
    "THEN",
    "THIS",
    "TIME",
    "TIME_OF_DAY",
    "TO",
    "TOD",
    "TRUE",
    "UDINT",
    "UINT",
    "ULINT",
    "UNION",
    "UNTIL",
    "USINT",
    "VAR",
    "VAR_ACCESS",
    "VAR_CONFIG",
    "VAR_EXTERNAL",
    "VAR_GLOBAL",
    "VAR_INPUT",
    "VAR_INST",
    "VAR_IN_OUT",
    "VAR_OUTPUT",
    "VAR_STAT",
    "VAR_TEMP",
    "WHILE",
    "WORD",
    "WSTRING",
    "XOR",
});

constexpr auto kIlOperators = std::to_array<std::string_view>({
    "ADD",   "AND",  "ANDN",  "CAL",    "CALC", "CALCN", "DIV", "EQ",  "GE",  "GT",   "JMP", "JMPC",
    "JMPCN", "LD",   "LDN",   "LE",     "LT",   "MOD",   "MUL", "NE",  "NOT", "OR",   "ORN", "R",
    "RET",   "RETC", "RETCN", "RETURN", "S",    "ST",    "STN", "SUB", "XOR", "XORN",
});

constexpr auto kTypeNames = std::to_array<std::string_view>({
    "BOOL", "BYTE",        "DATE",  "DATE_AND_TIME", "DINT", "DT",    "DWORD", "INT",  "LDATE",
    "LDT",  "LINT",        "LREAL", "LTIME",         "LTOD", "LWORD", "REAL",  "SINT", "STRING",
    "TIME", "TIME_OF_DAY", "TOD",   "UDINT",         "UINT", "ULINT", "USINT", "WORD", "WSTRING",
});

constexpr auto kOperatorWords =
    std::to_array<std::string_view>({"AND", "OR", "XOR", "NOT", "MOD", "AND_THEN", "OR_ELSE"});

struct Block {
  std::string_view opener;
  std::string_view closer;
};

// Words that open a declaration block, with the word that closes it.
constexpr auto kOpeners = std::to_array<Block>({
    {"PROGRAM", "END_PROGRAM"},
    {"FUNCTION", "END_FUNCTION"},
    {"FUNCTION_BLOCK", "END_FUNCTION_BLOCK"},
    {"VAR", "END_VAR"},
    {"VAR_INPUT", "END_VAR"},
    {"VAR_OUTPUT", "END_VAR"},
    {"VAR_IN_OUT", "END_VAR"},
    {"VAR_GLOBAL", "END_VAR"},
    {"VAR_EXTERNAL", "END_VAR"},
    {"VAR_TEMP", "END_VAR"},
    {"VAR_STAT", "END_VAR"},
    {"VAR_CONFIG", "END_VAR"},
    {"STRUCT", "END_STRUCT"},
    {"INTERFACE", "END_INTERFACE"},
    {"METHOD", "END_METHOD"},
    {"PROPERTY", "END_PROPERTY"},
});

constexpr auto kClosers = std::to_array<std::string_view>({
    "END_IF",
    "END_CASE",
    "END_FOR",
    "END_WHILE",
    "END_REPEAT",
    "END_VAR",
    "END_TYPE",
    "END_STRUCT",
    "END_PROGRAM",
    "END_FUNCTION",
    "END_FUNCTION_BLOCK",
    "END_METHOD",
    "END_PROPERTY",
    "END_ACTION",
    "END_INTERFACE",
    "END_UNION",
    "ELSIF",
});

template <size_t N>
bool sorted_contains(const std::array<std::string_view, N>& words, std::string_view word) {
  return std::binary_search(words.begin(), words.end(), word);
}

template <size_t N>
bool contains(const std::array<std::string_view, N>& words, std::string_view word) {
  return std::find(words.begin(), words.end(), word) != words.end();
}

bool is_keyword(const std::string& up) {
  if (sorted_contains(kReserved, up) || contains(kIlOperators, up) || contains(kClosers, up)) return true;
  return std::any_of(kOpeners.begin(), kOpeners.end(), [&](const Block& b) { return b.opener == up; });
}

}  // namespace

bool is_reserved(std::string_view word) {
  return sorted_contains(kReserved, upper(word));
}

bool is_type_name(std::string_view word) {
  return contains(kTypeNames, upper(word));
}

bool is_operator_word(std::string_view word) {
  return contains(kOperatorWords, upper(word));
}

bool is_il_operator(std::string_view word) {
  return contains(kIlOperators, upper(word));
}

std::string_view closer_of(std::string_view opener) {
  std::string up = upper(opener);
  for (const Block& b : kOpeners)
    if (b.opener == up) return b.closer;
  return {};
}

std::string_view misspelled(std::string_view word, bool any_keyword) {
  std::string up = upper(word);
  if (up == "ELSEIF" || up == "ELSE_IF" || up == "ELIF" || up == "ELSIFF") return "ELSIF";
  if (is_keyword(up)) return {};
  // Program1, END_IF2: numbered names, not typing mistakes.
  size_t stem = up.find_last_not_of("0123456789");
  if (stem != std::string::npos && stem + 1 < up.size()) {
    std::string base = up.substr(0, stem + 1);
    if (!base.empty() && base.back() == '_') base.pop_back();
    if (is_keyword(base)) return {};
  }
  // Closing words: up to two letters off (ENDIF, END_FUNCTIONBLOCK).
  if (up.rfind("END", 0) == 0 && up.size() >= 5) {
    std::string_view best;
    size_t best_distance = 3;
    for (std::string_view k : kClosers) {
      size_t d = edit_distance(up, k);
      if (d < best_distance) {
        best_distance = d;
        best = k;
      }
    }
    return best;
  }
  // Openers: one letter off, and only longer words (a name like VARS or PROG is no near miss).
  if (!any_keyword || up.size() < 6) return {};
  for (const Block& b : kOpeners) {
    if (b.opener.size() >= 6 && edit_distance(up, b.opener) == 1) return b.opener;
  }
  return {};
}

size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

}  // namespace rung::keywords
