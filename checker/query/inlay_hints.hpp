// Inlay hints: what the code does without saying so — which parameter an informal argument
// gives (`LIMIT(MN: 0, IN: x, MX: 5)`), and where a value is converted implicitly (an INT stored
// into a DINT: the compiler applies INT_TO_DINT).
#pragma once

#include <vector>

#include "checker/check.hpp"

namespace rung::check::query {

struct ParameterHint {
  uint32_t offset = 0;  // FILE offset of the argument
  const Symbol* parameter = nullptr;
};

struct ConversionHint {
  uint32_t offset = 0;  // FILE offset of the converted value
  const Type* from = nullptr;
  const Type* to = nullptr;
};

// The informal arguments of ST calls that start inside `file_range`, in text order. Left out:
// arguments that are a name spelled like their parameter, and the nameless inputs of the
// standard functions (IN, IN1, IN2 ...), whose names say nothing.
std::vector<ParameterHint> parameter_hints(const Workspace& workspace, SourceId source, TextRange file_range);

// The values inside `file_range` that an assignment or a call's input widens to another
// elementary type (Convertibility::Implicit), in text order. Untyped literals adapt to their
// target and are no conversion; narrowing conversions are diagnostics, not hints.
std::vector<ConversionHint> conversion_hints(const Workspace& workspace, SourceId source, TextRange file_range);

}  // namespace rung::check::query
