// How `rung diff` prints a vcs::DiffReport: `git diff`-like text for people (colours only when
// `color`), one line per object (--stat), or JSON (docs/commands/diff.md has the schema).
#pragma once

#include <string>

#include "vcs/semantic_diff.hpp"

namespace rung::cli {

std::string render_human(const vcs::DiffReport& report, bool color);
std::string render_stat(const vcs::DiffReport& report, bool color);
std::string render_json(const vcs::DiffReport& report);

}  // namespace rung::cli
