// Implementation limits of the profile's target (E704): code that IEC 61131-3 allows but the
// vendor's compiler does not take, such as OpenPCS's 64 significant identifier characters, 6
// array subscripts, 60 names per declaration, array bounds in -32767..32767 and no call as an
// argument of a call. The limits are Profile fields; a profile without limits checks nothing.
#pragma once

#include <vector>

#include "checker/project_model.hpp"

namespace rung::check {

// Appends E704 for the declarations and bodies of `source` (tree coordinates).
void check_limits(const ProjectModel& model, SourceId source, std::vector<Diagnostic>& out);

}  // namespace rung::check
