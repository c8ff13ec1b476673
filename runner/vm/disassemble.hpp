// A readable listing of compiled code (`rung run --dump-ir`): for debugging the compiler and for
// seeing what a POU turns into.
#pragma once

#include <string>

#include "runner/vm/program.hpp"

namespace rung::run {

std::string disassemble(const Program& program);

}  // namespace rung::run
