// Which values convert to which types without an explicit conversion, per profile, and the
// result types of operators. One table for the checker (and later the runner's lowering).
#pragma once

#include <string>
#include <string_view>

#include "checker/profile.hpp"
#include "checker/types/type.hpp"

namespace rung::check {

enum class Convertibility {
  Same,       // identical or trivially the same (aliases, unknown types)
  Implicit,   // widening: always allowed
  Narrowing,  // may lose data: a warning (CODESYS, TwinCAT) or an error (IEC)
  Never,      // no implicit conversion: an error
};

Convertibility convertibility(const Type* from, const Type* to, const Profile& profile);

// The standard function that converts a `from` value into `to`, for help lines: INT_TO_REAL,
// STRING_TO_UINT for a STRING(43), TO_INT for an enum value. Empty when there is none (the same
// elementary type on both sides, or a type that is not elementary).
std::string conversion_function(const Type* from, const Type* to);

// Whether `type` is `base` or (transitively) extends / implements it.
bool derives_from(const Type* type, const Type* base);

// The type both operands of an arithmetic operator are brought to (INT + DINT → DINT,
// INT + REAL → REAL); nullptr if there is none.
const Type* common_numeric_type(const Type* a, const Type* b, const TypeArena& types);

}  // namespace rung::check
