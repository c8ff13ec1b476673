// "Declare variable": the fix of E001 (an undeclared name). The type is read from how the name is
// used, the way a reader would guess it: the other side of an assignment or comparison, the
// other operand of arithmetic, the parameter an argument is passed to, BOOL for a condition, the
// counter type of a FOR, an integer for an array index. Where no use tells the type, nothing is
// offered: a guessed type is worse than none.
//
// The declaration goes into the POU whose body uses the name (a method into the method, an
// action or transition into the POU it belongs to), at the end of its last plain VAR block of
// the chosen section (not CONSTANT, RETAIN, ...), or into a new block placed where PLC
// programmers put it: inputs, then outputs, then in-outs, then local variables.
#pragma once

#include <optional>
#include <string>

#include "checker/check.hpp"
#include "checker/lint/lint_rule.hpp"
#include "checker/project/format_settings.hpp"

namespace rung::check::query {

struct UndeclaredVariable {
  std::string name;             // as written
  std::string type;             // as it is declared: "INT", "ST_Point", "ARRAY[1..10] OF REAL"
  const Symbol* pou = nullptr;  // where the declaration goes
};

// The undeclared name at `file_offset` (FILE coordinates of `source`) with the type its use
// implies; nullopt when the name is declared, is no plain variable use (a call, obj.member) or no
// use tells its type.
std::optional<UndeclaredVariable> undeclared_variable_at(const Workspace& workspace, SourceId source,
                                                         uint32_t file_offset);

// The edit (FILE coordinates of the POU's file) that declares `variable` in a block of `section`
// (Var, Input, Output, InOut); nullopt when the place cannot be edited.
std::optional<lint::TextEdit> declare_variable(const Workspace& workspace, const UndeclaredVariable& variable,
                                               ast::VarSection section, const project::FormatSettings& settings);

}  // namespace rung::check::query
