// Reading the loosely shaped JSON clients send: a missing or mistyped field is "absent", never
// an exception, because a client's small mistake must not fail a whole request.
#pragma once

#include <initializer_list>
#include <string>

#include "lsp/json_rpc.hpp"

namespace rung::lsp {

// Follows object keys from `root`; a null value when a step is missing or not an object.
const Json& json_at(const Json& root, std::initializer_list<const char*> keys);
// A string field of `object`, or "" when it is missing or not a string.
std::string json_string(const Json& object, const char* key);

}  // namespace rung::lsp
