// Document highlight: the names in one file that refer to a symbol, each marked with what the
// code does there — declares it, reads its value, or writes it (an assignment's target, a FOR
// variable, an output bound with `=>`, IL ST/S/R, an input given in a call). The read/write
// decision is the linter's usage analysis (lint/usage_analysis.hpp), so highlights and the unused-
// and unwritten-variable rules never disagree.
#pragma once

#include <vector>

#include "checker/check.hpp"
#include "checker/query/location.hpp"

namespace rung::check::query {

enum class Access : uint8_t {
  Declaration,  // the declaring name (also a VAR_EXTERNAL of a global)
  Read,         // the value is read, or the name is used otherwise (called, passed to VAR_IN_OUT, a type)
  Write,        // the value, or a part of it (a[i] :=, s.x :=), is written
};

struct Highlight {
  Location location;  // FILE coordinates
  Access access = Access::Read;
};

// The references of `symbol` in `source` (its declaration included when it is in that file), in
// text order.
std::vector<Highlight> highlights_in(const Workspace& workspace, const Symbol* symbol, SourceId source);

}  // namespace rung::check::query
