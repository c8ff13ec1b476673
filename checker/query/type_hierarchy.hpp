// Type hierarchy: one step up and one step down the EXTENDS and IMPLEMENTS relations of function
// blocks, classes, interfaces and structures, as the linker resolved them. (implementations.hpp
// answers the transitive questions: every block below a block, every implementation of an
// interface.)
#pragma once

#include <vector>

#include "checker/check.hpp"

namespace rung::check::query {

// Whether `symbol` is an item of a type hierarchy: a FUNCTION_BLOCK, CLASS, INTERFACE or STRUCT.
bool takes_part_in_types(const Symbol& symbol);

// What the name at `file_offset` stands for in a type hierarchy: such a type named there (in its
// declaration, a type name, EXTENDS / IMPLEMENTS), or the type of a variable named there.
// Nullptr elsewhere.
const Symbol* type_hierarchy_symbol_at(const Workspace& workspace, SourceId source, uint32_t file_offset);

// What `type` EXTENDS, then what it IMPLEMENTS, in the order written; each once.
std::vector<const Symbol*> supertypes_of(const Symbol& type);

// Every type that EXTENDS or IMPLEMENTS `type` directly, in source and declaration order (stub
// libraries included, which list before or after the project files as they were loaded).
std::vector<const Symbol*> subtypes_of(const ProjectModel& model, const Symbol& type);

}  // namespace rung::check::query
