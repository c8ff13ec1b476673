// Read before write (L075): a forward "definitely assigned" analysis over the statement tree of
// one POU's ST body. A variable counts as assigned after `:=`, S=/R=, `=> x`, passing it to a
// VAR_IN_OUT and ADR(x); IF without ELSE and CASE without ELSE may assign on one path only, a
// WHILE or FOR loop may run zero times (a FOR with constant bounds runs at least once, REPEAT
// always does). A read inside a loop of a variable the loop writes is not reported: the write may
// come from the previous iteration. Element and member writes count as writes of the whole.
#pragma once

#include <span>
#include <vector>

#include "checker/lint/usage_analysis.hpp"

namespace rung::lint {

struct EarlyRead {
  const check::Symbol* variable = nullptr;
  TextRange where;  // the first read that may come before every write
};

// The first early read of each of `candidates` (variables of `pou`) in `pou`'s body, in text
// order. Bodies the analysis cannot follow (IL, SFC, jumps, syntax errors) give none.
std::vector<EarlyRead> reads_before_write(const check::ProjectModel& model, const check::Symbol& pou,
                                          const FileUsage& usage, std::span<const check::Symbol* const> candidates);

}  // namespace rung::lint
