// The registry of diagnostic codes: one row per code, the single source of truth for its
// default severity and one-line title. Each code has a page docs/diagnostics/<CODE>.md.
// Syntax codes start with S; later stages add their own letters to the same table.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

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

// Where a code's page (docs/diagnostics/<CODE>.md) is published: SARIF helpUri, LSP codeDescription.
std::string diagnostic_docs_url(std::string_view code);

// A diagnostic of a registered code, with the code's default severity.
Diagnostic make_diagnostic(std::string_view code, std::string message, TextRange range, std::string help = {},
                           std::vector<DiagnosticLabel> labels = {});

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
inline constexpr std::string_view kUndeclaredName = "E001";
inline constexpr std::string_view kUnknownLibraryName = "E002";
inline constexpr std::string_view kDuplicateDeclaration = "E003";
inline constexpr std::string_view kWrongKindOfName = "E004";
inline constexpr std::string_view kUnknownMember = "E005";
inline constexpr std::string_view kQualifiedAccessRequired = "E006";
inline constexpr std::string_view kAmbiguousName = "E007";
inline constexpr std::string_view kTypeMismatch = "E101";
inline constexpr std::string_view kLiteralOutOfRange = "E102";
inline constexpr std::string_view kConditionNotBool = "E103";
inline constexpr std::string_view kInvalidOperand = "E104";
inline constexpr std::string_view kImplicitNarrowing = "E105";
inline constexpr std::string_view kStringTooLong = "E106";
inline constexpr std::string_view kIndexOutOfRange = "E107";
inline constexpr std::string_view kWrongIndexCount = "E108";
inline constexpr std::string_view kInvalidArrayBounds = "E109";
inline constexpr std::string_view kInvalidDereference = "E110";
inline constexpr std::string_view kDuplicateEnumValue = "E111";
inline constexpr std::string_view kSectionNotAllowed = "E201";
inline constexpr std::string_view kRetainNotAllowed = "E202";
inline constexpr std::string_view kMissingReturnValue = "E203";
inline constexpr std::string_view kMissingInterfaceMember = "E204";
inline constexpr std::string_view kSignatureMismatch = "E205";
inline constexpr std::string_view kAbstractInstance = "E206";
inline constexpr std::string_view kFinalOverride = "E207";
inline constexpr std::string_view kAccessViolation = "E208";
inline constexpr std::string_view kRecursion = "E209";
inline constexpr std::string_view kInvalidThisSuper = "E210";
inline constexpr std::string_view kInvalidInheritance = "E211";
inline constexpr std::string_view kInvalidCallTarget = "E212";
inline constexpr std::string_view kLocalTypeInInterface = "E213";
inline constexpr std::string_view kFunctionWithoutInput = "E214";
inline constexpr std::string_view kQualifierNotAllowed = "E215";
inline constexpr std::string_view kEnoWithoutEn = "E216";
inline constexpr std::string_view kStepNameNotAllowed = "E218";
inline constexpr std::string_view kInitialStepCount = "E219";
inline constexpr std::string_view kUnknownParameter = "E301";
inline constexpr std::string_view kMissingParameter = "E302";
inline constexpr std::string_view kDuplicateParameter = "E303";
inline constexpr std::string_view kTooManyArguments = "E304";
inline constexpr std::string_view kInOutNotAssignable = "E305";
inline constexpr std::string_view kMixedArguments = "E306";
inline constexpr std::string_view kNotCallable = "E307";
inline constexpr std::string_view kWrongArgumentDirection = "E308";
inline constexpr std::string_view kArgumentOrder = "E309";
inline constexpr std::string_view kAssignToConstant = "E401";
inline constexpr std::string_view kAssignToInput = "E402";
inline constexpr std::string_view kNotAssignable = "E403";
inline constexpr std::string_view kCaseLabelType = "E404";
inline constexpr std::string_view kDuplicateCaseLabel = "E405";
inline constexpr std::string_view kForVariableType = "E406";
inline constexpr std::string_view kForVariableModified = "E407";
inline constexpr std::string_view kExitOutsideLoop = "E408";
inline constexpr std::string_view kUnreachableCode = "E409";
inline constexpr std::string_view kUnknownLabel = "E410";
inline constexpr std::string_view kDuplicateLabel = "E411";
inline constexpr std::string_view kExternalWithoutGlobal = "E501";
inline constexpr std::string_view kExternalTypeMismatch = "E502";
inline constexpr std::string_view kAddressTypeMismatch = "E503";
inline constexpr std::string_view kAddressOverlap = "E504";
inline constexpr std::string_view kInvalidAddress = "E505";
inline constexpr std::string_view kUnknownProgramOrTask = "E506";
inline constexpr std::string_view kTaskWithoutTrigger = "E507";
inline constexpr std::string_view kVarConfigPath = "E508";
inline constexpr std::string_view kInitialValueNotAllowed = "E509";
inline constexpr std::string_view kObsolete = "E601";
inline constexpr std::string_view kPragmaWarning = "E602";
inline constexpr std::string_view kPragmaError = "E603";
inline constexpr std::string_view kUnknownPragma = "E604";
inline constexpr std::string_view kPragmaInfo = "E605";
inline constexpr std::string_view kConditionalPragma = "E606";
inline constexpr std::string_view kNotConstant = "E701";
inline constexpr std::string_view kDivisionByZero = "E702";
inline constexpr std::string_view kConstantOverflow = "E703";
inline constexpr std::string_view kImplementationLimit = "E704";
inline constexpr std::string_view kIlResultUndefined = "E801";
inline constexpr std::string_view kIlNotInParentheses = "E802";
inline constexpr std::string_view kIlOperandCount = "E803";
}  // namespace codes

}  // namespace rung
