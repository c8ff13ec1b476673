// SFC bodies: not compiled yet (see docs/commands/run.md); reported as a compile error.
#include "runner/compile/lowering.hpp"

namespace rung::run {

void BodyCompiler::sfc_body(SyntaxNode body) { fail(body, "rung cannot run SFC bodies yet"); }

}  // namespace rung::run
