// How a declaration reads, for hover, completion details and signature help: the code as the
// user wrote it, without comments, whitespace runs collapsed.
#pragma once

#include <string>
#include <vector>

#include "checker/project_model.hpp"

namespace rung::check::query {

// - a variable, field or parameter: `counter : INT := 0;` (one name of `a, b : INT`; a long
//   initial value is cut with "...");
// - an enum value: `Red := 0` (its value, written or counted);
// - a POU: its header line and its VAR_INPUT / VAR_OUTPUT / VAR_IN_OUT blocks (an extensible
//   input marked `// IN3, IN4 ... may follow`); a method or property the same;
// - a data type: its TYPE declaration (cut after 30 lines);
// - a global variable list: `VAR_GLOBAL` and its name.
std::string declaration_text(const ProjectModel& model, const Symbol& symbol);

// The text of `range` of `node`'s tree without comments and pragmas, whitespace runs collapsed
// to one space.
std::string code_text(SyntaxNode root, TextRange range);

// The type of a variable or parameter as written (`ARRAY[1..3] OF INT`, `T`), or the type the
// linker gave it when nothing is written.
std::string written_type(const ProjectModel& model, const Symbol& symbol);

// A call's signature on one line: `LIMIT(MN : T, IN : T, MX : T) : T`, outputs written
// `Q => BOOL`, an extensible input followed by ", ...". `parameters` receives each parameter's
// [begin, end) in the label, in the order of call_parameters(callee) without EN/ENO.
struct Signature {
  std::string label;
  std::vector<const Symbol*> parameters;
  std::vector<std::pair<uint32_t, uint32_t>> ranges;
};
Signature signature_of(const ProjectModel& model, const Symbol& callee);

}  // namespace rung::check::query
