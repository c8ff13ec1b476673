// `rung textconv FILE`: the ST text of a PLC source file (a vendor container's declarations and
// bodies without the XML), for git's textconv diff driver (`rung git setup`).
#pragma once

#include <cstdio>
#include <string>

namespace rung::cli {

// Exit code: 0 the text was written (a file that cannot be read as PLC source is written as it
// is, with a warning naming it on `err`, so that `git log -p` keeps working); 2 the file cannot
// be opened.
int run_textconv_command(const std::string& path, std::FILE* out, std::FILE* err);

}  // namespace rung::cli
