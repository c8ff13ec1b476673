// IL bodies: not compiled yet (see docs/commands/run.md); reported as a compile error.
#include "runner/compile/lowering.hpp"

namespace rung::run {

void BodyCompiler::il_body(SyntaxNode body) { fail(body, "rung cannot run IL bodies yet"); }

}  // namespace rung::run
