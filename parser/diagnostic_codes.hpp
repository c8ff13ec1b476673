// The registry of diagnostic codes: one row per code, the single source of truth for its
// default severity and one-line title. Each code has a page docs/diagnostics/<CODE>.md.
// Syntax codes start with S; later stages add their own letters to the same table.
#pragma once

#include <span>
#include <string_view>

#include "parser/diagnostic.hpp"

namespace rung {

struct DiagnosticCodeInfo {
  std::string_view code;
  Severity default_severity;
  std::string_view title;    // short kebab-case name, e.g. "missing-end-keyword"
  std::string_view summary;  // one sentence for `rung explain` listings
};

std::span<const DiagnosticCodeInfo> all_diagnostic_codes();
const DiagnosticCodeInfo* find_diagnostic_code(std::string_view code);

namespace codes {
inline constexpr std::string_view kSyntaxError = "S001";
inline constexpr std::string_view kMissingToken = "S002";
inline constexpr std::string_view kUnclosedBlock = "S003";
inline constexpr std::string_view kElseIf = "S004";
inline constexpr std::string_view kUnterminatedComment = "S005";
inline constexpr std::string_view kUnterminatedString = "S006";
inline constexpr std::string_view kInvalidCharacter = "S007";
inline constexpr std::string_view kEncoding = "S008";
inline constexpr std::string_view kBinaryFile = "S009";
inline constexpr std::string_view kContainer = "S010";
inline constexpr std::string_view kParseAborted = "S011";
inline constexpr std::string_view kTooManyErrors = "S012";
inline constexpr std::string_view kIoError = "S013";
inline constexpr std::string_view kMisspelledKeyword = "S014";
inline constexpr std::string_view kWrongOperator = "S015";
inline constexpr std::string_view kConfigSyntax = "P001";
inline constexpr std::string_view kConfigUnknownKey = "P002";
inline constexpr std::string_view kConfigBadValue = "P003";
}  // namespace codes

}  // namespace rung
