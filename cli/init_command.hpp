// `rung init [DIR] [--force]`: writes a commented rung.toml into DIR (default: the current folder).
#pragma once

#include <cstdio>
#include <string>

namespace rung::cli {

int run_init_command(const std::string& directory, bool force, std::FILE* out, std::FILE* err);

}  // namespace rung::cli
