// `rung explain [CODE]`: the docs page of a diagnostic code (what it means, a wrong example and
// its fix), or the list of all codes. Exit 0, or 2 for an unknown code.
#pragma once

#include <cstdio>
#include <string>

namespace rung::cli {

int run_explain_command(const std::string& code, std::FILE* out, std::FILE* err);

}  // namespace rung::cli
