// What the lint rules of both the naming and the structure group ask about a POU: where its own
// body is, how a message names it, and whether its signature is its own or given by a base, an
// interface or the runtime (so a finding on it belongs where the signature is declared); and how
// a message quotes code.
#pragma once

#include <string>
#include <vector>

#include "checker/project_model.hpp"

namespace rung::lint {

// The statement lists, IL bodies and SFC networks of the POU's own body, not its members'
// (methods and actions are POUs of their own). A snippet without POU header has its runs of
// statements at the top of the file.
std::vector<SyntaxNode> bodies_of(const check::Symbol& pou);

// What kind of POU it is, for messages: "function block", "method", "property accessor".
std::string_view pou_kind_label(const check::Symbol& pou);
// How a message names the POU: "function block 'FB_Motor'", "method 'FB_Motor.Start'".
std::string pou_label(const check::Symbol& pou);

// Whether the name and parameters of a method or property are fixed elsewhere: it overrides a
// member of a base, implements a member of an interface, or is FB_init, FB_reinit or FB_exit,
// whose signature the runtime defines.
bool signature_is_given(const check::ProjectModel& model, const check::Symbol& pou);

// Code or comment text quoted in a message: its first line, blanks at the end dropped, cut to
// `limit` bytes with "..." (never inside a UTF-8 character).
std::string message_excerpt(std::string_view text, size_t limit);

}  // namespace rung::lint
