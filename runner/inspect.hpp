// Reading and writing PLC variables from outside the program: paths such as `PLC_PRG.motor.speed`
// or `GVL.arr[3]` resolved to an address and a type, values rendered as JSON or IEC literal text
// (rung run's output, --watch, --trace) and parsed from text (--set).
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>

#include "runner/compile/compile.hpp"
#include "runner/vm/machine.hpp"

namespace rung::run {

struct ValueRef {
  const check::Type* type = nullptr;
  uint64_t address = 0;
  int bit = -1;  // a BOOL at a bit of the process image
};

// `path`: an optional program instance or GVL name, then variables, members and [indexes]. A bare
// name is looked up in the programs (in order), then in the global lists. `error` says why not.
std::optional<ValueRef> resolve_path(const CompiledProject& project, const Machine& machine, std::string_view path,
                                     std::string* error);

// The value at `ref` as JSON (see docs/commands/run.md for the mapping).
nlohmann::ordered_json value_json(const CompiledProject& project, const Machine& machine, const ValueRef& ref);
// The value as IEC text: TRUE, 42, 1.5, T#1s500ms, 'text', [1, 2], (a := 1, b := 2).
std::string value_text(const CompiledProject& project, const Machine& machine, const ValueRef& ref);
// Writes a literal (TRUE, 42, -1.5, T#2s, 'text', 16#FF, an enum value name) into `ref`; false
// with `error` when the text does not fit the type.
bool write_value(const CompiledProject& project, Machine& machine, const ValueRef& ref, std::string_view text,
                 std::string* error);

// A program's or list's variable as a ValueRef (following VAR_IN_OUT addresses).
ValueRef variable_ref(const Machine& machine, const VariableView& variable);

}  // namespace rung::run
