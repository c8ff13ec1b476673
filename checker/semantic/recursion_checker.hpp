// Recursion (E209): a POU that calls itself, directly or through others, and a function block
// that contains an instance of itself. All four manuals forbid both (CODESYS textbook L3178,
// AK800 L2726, MP300 L125, OpenPCS S3032/S4007/S6004): PLC code runs on a fixed stack and
// instances are laid out at compile time.
//
// CODESYS V3 and TwinCAT 3 do compile recursive METHODs (tree walks, parsers), so with those
// profiles a cycle that goes through a method is not reported.
//
// The call graph is project-wide: the index keeps each file's edges (built when the project is
// linked, rebuilt for one file after a body edit) and finds the cycles over all of them.
#pragma once

#include <vector>

#include "parser/diagnostic.hpp"

namespace rung::check {

class ProjectModel;
struct Symbol;
using SourceId = uint32_t;

struct CallEdge {
  const Symbol* from = nullptr;
  const Symbol* to = nullptr;
  TextRange where;        // the callee's name, or the instance's type, in `from`'s file
  bool instance = false;  // an FB instance declared in `from` (not a call)
};

class RecursionIndex {
 public:
  // Every project file's edges, then the cycles.
  void rebuild(const ProjectModel& model);
  // One file's bodies changed (its declarations did not): its edges, then the cycles.
  void rebuild_source(const ProjectModel& model, SourceId id);
  // Several files' declarations or bodies changed: their edges, then the cycles once.
  void rebuild_sources(const ProjectModel& model, const std::vector<SourceId>& ids);
  // E209 diagnostics of one file, in tree coordinates.
  const std::vector<Diagnostic>& diagnostics(SourceId id) const;
  // The call graph itself: the edges whose caller is declared in `id` (lint rules follow it from
  // the programs a task runs).
  const std::vector<CallEdge>& edges(SourceId id) const;

 private:
  void find_cycles(const ProjectModel& model);
  std::vector<std::vector<CallEdge>> edges_;    // by the source of `from`
  std::vector<std::vector<Diagnostic>> found_;  // by source
};

// Appends the E209 diagnostics of `source` (tree coordinates).
void check_recursion(const ProjectModel& model, SourceId source, std::vector<Diagnostic>& out);

}  // namespace rung::check
