// Spaces between two tokens on one line: the intra-line rules of `rung fmt` (one space around
// binary operators and ':=', none inside brackets, a.b, f(x), -x, one after ',' ...).
#pragma once

#include <string_view>

#include "checker/project/format_settings.hpp"
#include "formatter/layout_walk.hpp"

namespace rung::format {

// How many spaces go between `before` and `after` (both on the same output line). `text` holds
// the input, for the rare case where removing a space would glue two tokens into one.
uint32_t spaces_between(const Leaf& before, const Leaf& after, std::string_view text,
                        const project::FormatSettings& settings);

}  // namespace rung::format
