// Refactorings between the two ways to write a call: formal `F(a := 1, b := 2)` and informal
// `F(1, 2)`. Only offered where both mean the same call and the result is legal IEC 61131-3:
// - to formal: every argument is positional and binds to an input or in-out by its place (the
//   binding rung check uses); works for functions, methods, function block instances, programs;
// - to informal: only calls of FUNCTIONs and METHODs (IEC allows informal calls of nothing else:
//   a function block instance is always called with named parameters), every argument names an
//   input or in-out with ':=', and they are written in declaration order with none left out
//   before the last (informal arguments bind by position). Outputs (=>) and EN/ENO cannot be
//   written informally.
// The edits only add or remove the `name :=` parts, so comments and layout stay as written.
#pragma once

#include <optional>
#include <vector>

#include "checker/check.hpp"
#include "checker/lint/lint_rule.hpp"

namespace rung::check::query {

struct CallRewrite {
  std::string callee;                 // the called POU's name, for the action's title
  std::vector<lint::TextEdit> edits;  // FILE coordinates
};

// The call innermost around `file_offset` (FILE coordinates of `source`) rewritten; nullopt where
// there is no call or the rewrite would not be legal or certain.
std::optional<CallRewrite> to_formal_call(const Workspace& workspace, SourceId source, uint32_t file_offset);
std::optional<CallRewrite> to_informal_call(const Workspace& workspace, SourceId source, uint32_t file_offset);

}  // namespace rung::check::query
