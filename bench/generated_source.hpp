// Realistic generated ST for benchmarks: function blocks with VAR blocks, IF/CASE/FOR, calls,
// comments and pragmas, in the proportions of real TwinCAT/CODESYS code.
#pragma once

#include <string>

namespace rung::bench {

// About `lines` lines of ST (a little more: whole POUs are emitted).
std::string generate_st(size_t lines, unsigned seed = 1);

}  // namespace rung::bench
