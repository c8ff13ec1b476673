// The markdown that describes a declaration, shared by hover and completionItem/resolve: the
// declaration as written (a code block), what it is and where it belongs, its constant value,
// and its doc comment.
#pragma once

#include <string>

#include "checker/project_model.hpp"

namespace rung::lsp {

// "local variable of `Main`", "input of `FB_Motor`", "function (library `iec`)" ...
std::string symbol_role(const check::ProjectModel& model, const check::Symbol& symbol);

std::string symbol_markdown(const check::ProjectModel& model, const check::Symbol& symbol);

// A fenced code block of IEC 61131-3 text (the language name editors highlight it with).
std::string code_block(std::string_view code);

}  // namespace rung::lsp
