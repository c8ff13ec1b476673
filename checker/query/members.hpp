// Completion after '.': what may follow a value of some type, or a qualifier (a global variable
// list, an enumeration's name, a POU).
#pragma once

#include <vector>

#include "checker/project_model.hpp"

namespace rung::check::query {

// The members of `container`, inherited ones (EXTENDS) included and hidden by a redeclaration of
// the same name, in declaration order, own members first; {attribute 'hide'} members left out:
// - a STRUCT or UNION: its fields; an enumeration: its values; a global variable list: its variables;
// - a FUNCTION_BLOCK, CLASS or INTERFACE: inputs, outputs, in-outs, methods, properties, actions;
// - a PROGRAM: its variables except VAR_TEMP (CODESYS reads a program's variables as PRG.x), actions.
std::vector<const Symbol*> members_of(const Symbol* container);

// The members of a value of `type` (instance.member): a REFERENCE TO is looked through, a value of
// an enumeration or elementary type has none.
std::vector<const Symbol*> members_of(const Type* type);

}  // namespace rung::check::query
