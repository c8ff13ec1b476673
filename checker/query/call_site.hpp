// Signature help and completion inside a call: which POU the call at the cursor goes to, its
// parameters, and which of them the argument at the cursor gives — by name (`IN := |`) or by
// position (`LIMIT(0, |`), the extensible inputs of standard functions (MAX, CONCAT ...) repeating.
#pragma once

#include <optional>
#include <vector>

#include "checker/check.hpp"
#include "checker/query/cursor_context.hpp"

namespace rung::check::query {

// The formal parameters of a call of `callee`: its inputs, in-outs and outputs (EN/ENO
// included), those of the blocks it extends first, each in declaration order — the order
// BodyChecker binds informal arguments in.
std::vector<const Symbol*> call_parameters(const Symbol* callee);

// The parameters an informal call binds by position: the inputs and in-outs without EN.
std::vector<const Symbol*> positional_parameters(const Symbol* callee);

// The parameter the informal argument number `index` (from 0) binds: the last input when it is
// extensible (IN2 of MAX also takes the 3rd, 4th ... argument); nullptr past the end.
const Symbol* positional_parameter(const std::vector<const Symbol*>& positional, size_t index);

// The parameter a formal argument names (also by a standard function's rung.alias name).
const Symbol* named_parameter(const std::vector<const Symbol*>& parameters, std::string_view name);

struct CallSite {
  const Symbol* callee = nullptr;  // FUNCTION, METHOD, ACTION, PROGRAM, or the block of an instance
  bool instance_call = false;      // fbTimer(...): a call of a FUNCTION_BLOCK instance
  CallContext call;
  const Symbol* active = nullptr;  // the parameter the argument at the cursor gives, if known
};

// The innermost call whose argument list holds `file_offset`; nullopt outside every call, or
// when what is called is unknown.
std::optional<CallSite> call_site_at(const Workspace& workspace, SourceId source, uint32_t file_offset);

// The same from a cursor context already read.
std::optional<CallSite> call_site_of(const ProjectModel& model, SourceId source, const CursorContext& context);

}  // namespace rung::check::query
