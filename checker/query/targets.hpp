// Go to declaration and go to type definition: the two jumps next to go to definition.
#pragma once

#include <optional>

#include "checker/check.hpp"
#include "checker/query/location.hpp"

namespace rung::check::query {

// Go to declaration. In IEC 61131-3 a name is declared where it is defined, so this is
// definition_at, with one difference: a global variable used by its bare name inside a POU that
// declares it VAR_EXTERNAL leads to that VAR_EXTERNAL (the declaration the POU itself holds),
// where definition_at leads to the VAR_GLOBAL.
std::optional<Location> declaration_at(const Workspace& workspace, SourceId source, uint32_t file_offset);

// Go to type definition: the declaration of the type of what is under the cursor — the STRUCT,
// enumeration, alias, FUNCTION_BLOCK, CLASS or INTERFACE a variable, member, expression or enum
// value has (through ARRAY OF, POINTER TO and REFERENCE TO), a function's or method's result
// type, or the type itself on a type name. Nullptr for elementary types and where there is no
// expression.
const Symbol* type_definition_at(const Workspace& workspace, SourceId source, uint32_t file_offset);

}  // namespace rung::check::query
