// The formatter's safety check, run on every result: the output must parse without errors, hold
// the same significant tokens as the input (keywords and elementary type names compared without
// letter case; the sanctioned rewrites of rewrites.hpp, each validated on the input's tree, applied
// to the input's tokens first), and the same comments and pragmas, byte for byte and in the same
// order. Without rewrites the two trees must also have the same shape (the named nodes in the
// same order), which catches a layout that makes the grammar read the same tokens differently.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "formatter/rewrites.hpp"
#include "formatter/token_stream.hpp"

namespace rung::format {

// nullopt when the output is safe; else "line N: ..." naming the first difference (N in the input).
std::optional<std::string> check_tokens(CheckInput input, CheckInput output, const std::vector<Rewrite>& rewrites);

}  // namespace rung::format
