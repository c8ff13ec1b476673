#include "parser/diagnostic_codes.hpp"

#include <array>

namespace rung {
namespace {

constexpr std::array kCodes = {
    DiagnosticCodeInfo{codes::kSyntaxError, Severity::Error, "syntax-error",
                       "The parser met text it cannot fit into any statement or declaration."},
    DiagnosticCodeInfo{codes::kMissingToken, Severity::Error, "missing-token",
                       "A required token such as ';', ':=' or ')' is missing."},
    DiagnosticCodeInfo{codes::kUnclosedBlock, Severity::Error, "missing-end-keyword",
                       "A block (IF, CASE, FOR, VAR, STRUCT, ...) is never closed by its END_ keyword."},
    DiagnosticCodeInfo{codes::kElseIf, Severity::Error, "else-if",
                       "'ELSE IF' opens a nested IF that needs its own END_IF; ELSIF was probably meant."},
    DiagnosticCodeInfo{codes::kUnterminatedComment, Severity::Error, "unterminated-comment",
                       "A '(*' or '/*' comment is never closed."},
    DiagnosticCodeInfo{codes::kUnterminatedString, Severity::Error, "unterminated-string",
                       "A string literal has no closing quote on its line."},
    DiagnosticCodeInfo{codes::kInvalidCharacter, Severity::Error, "invalid-character",
                       "A character that cannot start any token of IEC 61131-3."},
    DiagnosticCodeInfo{codes::kEncoding, Severity::Warning, "encoding",
                       "The file has bytes that are not valid in its text encoding; they were replaced."},
    DiagnosticCodeInfo{codes::kBinaryFile, Severity::Error, "binary-file", "The file is binary, not PLC source text."},
    DiagnosticCodeInfo{codes::kContainer, Severity::Error, "container",
                       "A vendor container file (TwinCAT XML, CODESYS .EXP) is malformed."},
    DiagnosticCodeInfo{codes::kParseAborted, Severity::Error, "parse-aborted",
                       "The file is too large or too deeply nested to parse within rung's limits."},
    DiagnosticCodeInfo{codes::kTooManyErrors, Severity::Info, "too-many-errors",
                       "More syntax errors follow; only the first ones of the file are shown."},
    DiagnosticCodeInfo{codes::kIoError, Severity::Error, "io-error", "The file could not be read."},
    DiagnosticCodeInfo{codes::kMisspelledKeyword, Severity::Error, "misspelled-keyword",
                       "A word that is almost a keyword (ELSEIF, ENDIF, END_IFF) where the keyword belongs."},
    DiagnosticCodeInfo{codes::kWrongOperator, Severity::Error, "wrong-operator",
                       "An operator from another language (==, !=, &&, ||, !) or '=' where ':=' assigns."},
    DiagnosticCodeInfo{codes::kConfigSyntax, Severity::Error, "rung-toml-syntax", "rung.toml is not valid TOML."},
    DiagnosticCodeInfo{codes::kConfigUnknownKey, Severity::Warning, "rung-toml-unknown-key",
                       "rung.toml has a key or diagnostic code rung does not know (often a typo)."},
    DiagnosticCodeInfo{codes::kConfigBadValue, Severity::Error, "rung-toml-bad-value",
                       "A rung.toml setting has a value of the wrong kind or out of range."},
};

}  // namespace

std::span<const DiagnosticCodeInfo> all_diagnostic_codes() {
  return kCodes;
}

const DiagnosticCodeInfo* find_diagnostic_code(std::string_view code) {
  for (const auto& info : kCodes) {
    if (info.code.size() == code.size()) {
      bool same = true;
      for (size_t i = 0; i < code.size(); ++i) {
        char a = info.code[i], b = code[i];
        if (a >= 'a' && a <= 'z') a = static_cast<char>(a - 32);
        if (b >= 'a' && b <= 'z') b = static_cast<char>(b - 32);
        if (a != b) {
          same = false;
          break;
        }
      }
      if (same) return &info;
    }
  }
  return nullptr;
}

}  // namespace rung
