#include "parser/diagnostic_codes.hpp"

#include <array>
#include <string>
#include <utility>

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
    // Semantic checker (checker/)
    DiagnosticCodeInfo{codes::kUndeclaredName, Severity::Error, "undeclared-name",
                       "A variable/name used in an expression is not declared."},
    DiagnosticCodeInfo{codes::kUnknownLibraryName, Severity::Error, "unknown-library-name",
                       "Unknown type / POU / namespace name (often: a vendor library rung has no stubs for; add stubs)."},
    DiagnosticCodeInfo{codes::kDuplicateDeclaration, Severity::Error, "duplicate-declaration",
                       "A name is declared twice in the same scope (also redeclared inherited variable, enum value reused)."},
    DiagnosticCodeInfo{codes::kWrongKindOfName, Severity::Error, "wrong-kind-of-name",
                       "A type used as a value, a variable used as a type, a function used as a variable, ..."},
    DiagnosticCodeInfo{codes::kUnknownMember, Severity::Error, "unknown-member",
                       "'x' has no member 'y' (struct field, FB input/output, method, enum value)."},
    DiagnosticCodeInfo{codes::kQualifiedAccessRequired, Severity::Error, "qualified-access-required",
                       "{attribute 'qualified_only'} GVL or enum accessed without its prefix."},
    DiagnosticCodeInfo{codes::kAmbiguousName, Severity::Error, "ambiguous-name",
                       "Unqualified enum value or name found in several places."},
    DiagnosticCodeInfo{codes::kTypeMismatch, Severity::Error, "type-mismatch",
                       "Cannot convert type 'A' to type 'B'."},
    DiagnosticCodeInfo{codes::kLiteralOutOfRange, Severity::Error, "literal-out-of-range",
                       "A constant does not fit its type (typed literal losing data, 300 into SINT, 99 into INT(0..90))."},
    DiagnosticCodeInfo{codes::kConditionNotBool, Severity::Error, "condition-not-bool",
                       "IF/WHILE/UNTIL/ELSIF condition is not BOOL."},
    DiagnosticCodeInfo{codes::kInvalidOperand, Severity::Error, "invalid-operand",
                       "Operator not defined for these operand types (AND on REAL, + on BOOL, NOT on STRING)."},
    DiagnosticCodeInfo{codes::kImplicitNarrowing, Severity::Warning, "implicit-narrowing",
                       "Implicit conversion that can lose data (DINT into INT, REAL into INT, signed into unsigned)."},
    DiagnosticCodeInfo{codes::kStringTooLong, Severity::Warning, "string-too-long",
                       "String literal longer than the STRING(n) it is assigned to."},
    DiagnosticCodeInfo{codes::kIndexOutOfRange, Severity::Error, "index-out-of-range",
                       "Constant array index outside the declared bounds."},
    DiagnosticCodeInfo{codes::kWrongIndexCount, Severity::Error, "wrong-index-count",
                       "Number of indices differs from the array's dimensions, or index on a non-array."},
    DiagnosticCodeInfo{codes::kInvalidArrayBounds, Severity::Error, "invalid-array-bounds",
                       "Lower bound above upper bound, non-constant bound, ARRAY[*] outside VAR_IN_OUT."},
    DiagnosticCodeInfo{codes::kInvalidDereference, Severity::Error, "invalid-dereference",
                       "'^' on something that is not a POINTER/REFERENCE, REF= on a non-reference."},
    DiagnosticCodeInfo{codes::kDuplicateEnumValue, Severity::Warning, "duplicate-enum-value",
                       "Two enumerators with the same value."},
    DiagnosticCodeInfo{codes::kSectionNotAllowed, Severity::Error, "section-not-allowed",
                       "A VAR section that this kind of POU may not have (per profile)."},
    DiagnosticCodeInfo{codes::kRetainNotAllowed, Severity::Error, "retain-not-allowed",
                       "RETAIN/PERSISTENT where not allowed (FUNCTION, VAR_TEMP, ...)."},
    DiagnosticCodeInfo{codes::kMissingReturnValue, Severity::Warning, "missing-return-value",
                       "A FUNCTION/METHOD with a return type never assigns its result."},
    DiagnosticCodeInfo{codes::kMissingInterfaceMember, Severity::Error, "missing-interface-member",
                       "A POU IMPLEMENTS an interface but lacks one of its methods/properties."},
    DiagnosticCodeInfo{codes::kSignatureMismatch, Severity::Error, "signature-mismatch",
                       "An implementation or override differs from the declared signature."},
    DiagnosticCodeInfo{codes::kAbstractInstance, Severity::Error, "abstract-instance",
                       "An instance of an ABSTRACT FB / an interface."},
    DiagnosticCodeInfo{codes::kFinalOverride, Severity::Error, "final-override",
                       "Overriding a FINAL method or extending a FINAL FB."},
    DiagnosticCodeInfo{codes::kAccessViolation, Severity::Error, "access-violation",
                       "A PRIVATE/PROTECTED/INTERNAL member used from outside."},
    DiagnosticCodeInfo{codes::kRecursion, Severity::Error, "recursion",
                       "A POU calls itself directly or indirectly."},
    DiagnosticCodeInfo{codes::kInvalidThisSuper, Severity::Error, "invalid-this-super",
                       "THIS^/SUPER^ outside an FB, SUPER^ without a base."},
    DiagnosticCodeInfo{codes::kInvalidInheritance, Severity::Error, "invalid-inheritance",
                       "EXTENDS something that is not an FB/struct/interface, or a cycle."},
    DiagnosticCodeInfo{codes::kInvalidCallTarget, Severity::Error, "invalid-call-target",
                       "A FUNCTION calling a PROGRAM or instantiating an FB."},
    DiagnosticCodeInfo{codes::kLocalTypeInInterface, Severity::Error, "local-type-in-interface",
                       "A POU-local TYPE used for a parameter, VAR_GLOBAL or VAR_EXTERNAL (other POUs cannot know it)."},
    DiagnosticCodeInfo{codes::kFunctionWithoutInput, Severity::Error, "function-without-input",
                       "A FUNCTION without VAR_INPUT (OpenPCS requires at least one input)."},
    DiagnosticCodeInfo{codes::kQualifierNotAllowed, Severity::Error, "qualifier-not-allowed",
                       "CONSTANT where this section or variable cannot have it (VAR_INPUT CONSTANT, RETAIN CONSTANT, ...)."},
    DiagnosticCodeInfo{codes::kEnoWithoutEn, Severity::Error, "eno-without-en",
                       "A POU declares the ENO output but no EN input."},
    DiagnosticCodeInfo{codes::kStepNameNotAllowed, Severity::Error, "step-name-not-allowed",
                       "An SFC step name the profile does not allow (OpenPCS: a letter first, at most 31 characters)."},
    DiagnosticCodeInfo{codes::kInitialStepCount, Severity::Error, "initial-step-count",
                       "An SFC network with no INITIAL_STEP, or with more than one."},
    DiagnosticCodeInfo{codes::kUnknownParameter, Severity::Error, "unknown-parameter",
                       "A formal parameter name the callee does not have."},
    DiagnosticCodeInfo{codes::kMissingParameter, Severity::Error, "missing-parameter",
                       "A function input/in-out without default not given."},
    DiagnosticCodeInfo{codes::kDuplicateParameter, Severity::Error, "duplicate-parameter",
                       "The same parameter given twice."},
    DiagnosticCodeInfo{codes::kTooManyArguments, Severity::Error, "too-many-arguments",
                       "More informal arguments than the callee has inputs."},
    DiagnosticCodeInfo{codes::kInOutNotAssignable, Severity::Error, "in-out-not-assignable",
                       "VAR_IN_OUT argument is not a variable."},
    DiagnosticCodeInfo{codes::kMixedArguments, Severity::Error, "mixed-arguments",
                       "Formal and informal arguments mixed in one call."},
    DiagnosticCodeInfo{codes::kNotCallable, Severity::Error, "not-callable",
                       "Calling something that is not a POU/FB instance/method/action."},
    DiagnosticCodeInfo{codes::kWrongArgumentDirection, Severity::Error, "wrong-argument-direction",
                       "'=>' on an input or ':=' on an output."},
    DiagnosticCodeInfo{codes::kArgumentOrder, Severity::Error, "argument-order",
                       "Formal arguments not in the callee's declaration order (openpcs)."},
    DiagnosticCodeInfo{codes::kAssignToConstant, Severity::Error, "assign-to-constant",
                       "Assignment to a CONSTANT."},
    DiagnosticCodeInfo{codes::kAssignToInput, Severity::Error, "assign-to-input",
                       "Writing an FB instance's output or a read-only (VAR_INPUT CONSTANT, property without SET)."},
    DiagnosticCodeInfo{codes::kNotAssignable, Severity::Error, "not-assignable",
                       "Left side of := is not a variable (C0018 \"'q' is not a valid assignment target\")."},
    DiagnosticCodeInfo{codes::kCaseLabelType, Severity::Error, "case-label-type",
                       "CASE label type does not match the selector."},
    DiagnosticCodeInfo{codes::kDuplicateCaseLabel, Severity::Error, "duplicate-case-label",
                       "The same value in two CASE labels (or overlapping ranges)."},
    DiagnosticCodeInfo{codes::kForVariableType, Severity::Error, "for-variable-type",
                       "FOR variable/bounds are not integers."},
    DiagnosticCodeInfo{codes::kForVariableModified, Severity::Warning, "for-variable-modified",
                       "The FOR variable is assigned in the loop body."},
    DiagnosticCodeInfo{codes::kExitOutsideLoop, Severity::Error, "exit-outside-loop",
                       "EXIT/CONTINUE outside a loop."},
    DiagnosticCodeInfo{codes::kUnreachableCode, Severity::Warning, "unreachable-code",
                       "Statements after RETURN/EXIT/CONTINUE/JMP in the same list."},
    DiagnosticCodeInfo{codes::kUnknownLabel, Severity::Error, "unknown-label",
                       "JMP to a label that does not exist; an SFC transition or step macro naming no step."},
    DiagnosticCodeInfo{codes::kDuplicateLabel, Severity::Error, "duplicate-label",
                       "A jump label declared twice."},
    DiagnosticCodeInfo{codes::kExternalWithoutGlobal, Severity::Error, "external-without-global",
                       "VAR_EXTERNAL without a matching VAR_GLOBAL."},
    DiagnosticCodeInfo{codes::kExternalTypeMismatch, Severity::Error, "external-type-mismatch",
                       "VAR_EXTERNAL type differs from the VAR_GLOBAL."},
    DiagnosticCodeInfo{codes::kAddressTypeMismatch, Severity::Error, "address-type-mismatch",
                       "AT address size does not fit the type (%IX on an INT)."},
    DiagnosticCodeInfo{codes::kAddressOverlap, Severity::Warning, "address-overlap",
                       "Two AT variables share bytes (%MW1 and %MB2)."},
    DiagnosticCodeInfo{codes::kInvalidAddress, Severity::Error, "invalid-address",
                       "Malformed direct address."},
    DiagnosticCodeInfo{codes::kUnknownProgramOrTask, Severity::Error, "unknown-program-or-task",
                       "PROGRAM WITH an unknown task, or an unknown program type in a RESOURCE."},
    DiagnosticCodeInfo{codes::kTaskWithoutTrigger, Severity::Error, "task-without-trigger",
                       "TASK without INTERVAL or SINGLE."},
    DiagnosticCodeInfo{codes::kVarConfigPath, Severity::Error, "var-config-path",
                       "VAR_CONFIG path does not resolve."},
    DiagnosticCodeInfo{codes::kInitialValueNotAllowed, Severity::Error, "initial-value-not-allowed",
                       "An initial value on a VAR_EXTERNAL (or, per profile, on an AT variable)."},
    DiagnosticCodeInfo{codes::kObsolete, Severity::Warning, "obsolete",
                       "Use of something marked {attribute 'obsolete'}."},
    DiagnosticCodeInfo{codes::kPragmaWarning, Severity::Warning, "pragma-warning",
                       "{warning 'text'}."},
    DiagnosticCodeInfo{codes::kPragmaError, Severity::Error, "pragma-error",
                       "{error 'text'}."},
    DiagnosticCodeInfo{codes::kUnknownPragma, Severity::Warning, "unknown-pragma",
                       "A pragma rung cannot interpret (not attribute/message/conditional)."},
    DiagnosticCodeInfo{codes::kPragmaInfo, Severity::Info, "pragma-info",
                       "{info 'text'} or {text 'text'}."},
    DiagnosticCodeInfo{codes::kConditionalPragma, Severity::Error, "conditional-pragma",
                       "Malformed conditional compilation: unbalanced {IF}/{END_IF} or a condition rung cannot read."},
    DiagnosticCodeInfo{codes::kNotConstant, Severity::Error, "not-constant",
                       "A constant expression is required (array bounds, CASE labels, STRING(n), CONSTANT init)."},
    DiagnosticCodeInfo{codes::kDivisionByZero, Severity::Error, "division-by-zero",
                       "Division or MOD by a constant zero."},
    DiagnosticCodeInfo{codes::kConstantOverflow, Severity::Warning, "constant-overflow",
                       "Constant arithmetic overflows its type."},
    DiagnosticCodeInfo{codes::kImplementationLimit, Severity::Error, "implementation-limit",
                       "Exceeds an implementation limit of the profile (identifier length, array subscripts, ...)."},
    DiagnosticCodeInfo{codes::kIlResultUndefined, Severity::Error, "il-result-undefined",
                       "IL instruction uses the current result where it is undefined (start, after a label, JMP, CAL)."},
    DiagnosticCodeInfo{codes::kIlNotInParentheses, Severity::Error, "il-not-in-parentheses",
                       "IL instruction not allowed inside a deferred operator's parentheses."},
    DiagnosticCodeInfo{codes::kIlOperandCount, Severity::Error, "il-operand-count",
                       "IL operator without the operand it needs, or with operands it does not take."},
};

}  // namespace

std::span<const DiagnosticCodeInfo> all_diagnostic_codes() {
  return kCodes;
}

Diagnostic make_diagnostic(std::string_view code, std::string message, TextRange range, std::string help,
                           std::vector<DiagnosticLabel> labels) {
  Diagnostic diagnostic;
  diagnostic.code = std::string(code);
  const DiagnosticCodeInfo* info = find_diagnostic_code(code);
  diagnostic.severity = info ? info->default_severity : Severity::Error;
  diagnostic.message = std::move(message);
  diagnostic.range = range;
  diagnostic.help = std::move(help);
  diagnostic.labels = std::move(labels);
  return diagnostic;
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
