// Code lens: the number of references above each POU, method, property, action and data type.
#pragma once

#include "lsp/router.hpp"

namespace rung::lsp {

void register_code_lens(Router& router);

}  // namespace rung::lsp
