// rung_bench_project: writes the checker benchmark's generated project as .st files, so the CLI
// can be timed on exactly what BM_CheckProject measures (scripts/bench-check).
//   rung_bench_project DIR [FILES] [SEED]
#include <cstdio>
#include <cstdlib>
#include <string>

#include "bench/generated_project.hpp"

int main(int argc, char** argv) {
  if (argc < 2 || argc > 4) {
    std::fprintf(stderr, "usage: %s DIR [FILES (default 2000)] [SEED (default 1)]\n", argv[0]);
    return 2;
  }
  const size_t files = argc > 2 ? std::strtoull(argv[2], nullptr, 10) : 2000;
  const unsigned seed = argc > 3 ? static_cast<unsigned>(std::strtoul(argv[3], nullptr, 10)) : 1;
  if (files == 0) {
    std::fprintf(stderr, "error: FILES must be a positive number\n");
    return 2;
  }
  const rung::bench::GeneratedProject project = rung::bench::generate_project(files, seed);
  std::string error;
  if (!rung::bench::write_project(project, argv[1], error)) {
    std::fprintf(stderr, "error: %s\n", error.c_str());
    return 1;
  }
  std::printf("%zu files, %zu lines, %zu bytes in %s\n", project.files.size(), project.lines, project.bytes, argv[1]);
  return 0;
}
