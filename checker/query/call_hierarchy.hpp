// Call hierarchy: what a POU calls and where it is called from. A call is one written in a body
// (ST, IL, the code and conditions of SFC): of a FUNCTION, METHOD, ACTION or PROGRAM, or of a
// function block instance, which runs the block's body and so counts as a call of the block.
// Callees are found by the body checker's typing of the called expression (the choice the checker
// makes when it checks the call), so the hierarchy and the diagnostics agree on what is called.
#pragma once

#include <functional>
#include <vector>

#include "checker/check.hpp"
#include "checker/query/location.hpp"

namespace rung::check::query {

struct Call {
  const Symbol* caller = nullptr;  // the POU, method, action, property or transition the call is written in
  const Symbol* callee = nullptr;  // FUNCTION, METHOD, ACTION, PROGRAM, or the block of a called instance
  Location where;                  // the called name as written: `fbPump` in fbPump(...), `Start` in fbPump.Start()
};

// Whether `symbol` is an item of a call hierarchy: a PROGRAM, FUNCTION, FUNCTION_BLOCK, CLASS,
// METHOD, PROPERTY (its GET and SET together), ACTION or TRANSITION.
bool takes_part_in_calls(const Symbol& symbol);

// What the name at `file_offset` stands for in a call hierarchy: a POU or member named there (in
// its declaration or where it is used), the block of a function block instance, the property of
// a GET or SET. Nullptr elsewhere.
const Symbol* call_hierarchy_symbol_at(const Workspace& workspace, SourceId source, uint32_t file_offset);

// Every call in the body of `caller` (of a property: in its GET and SET), in text order.
std::vector<Call> outgoing_calls(const Workspace& workspace, const Symbol& caller);

// Every call of `callee` in the project files (and the stub libraries when it is declared in
// one), sorted by path and offset. A block's calls are the calls of its instances. `cancelled` is
// polled between candidates: a search it stops returns what it found so far.
std::vector<Call> incoming_calls(const Workspace& workspace, const Symbol& callee,
                                 const std::function<bool()>& cancelled = {});

}  // namespace rung::check::query
