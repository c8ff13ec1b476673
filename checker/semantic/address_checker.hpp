// AT addresses of declarations (`x AT %MW1 : WORD`): E505 for an address that cannot exist,
// E503 for a type that does not fit the address's size, E504 for variables that share memory.
// The address rules themselves live in direct_address.{hpp,cpp}; this file ties them to the
// declarations of a project and to the profile's addressing mode.
#pragma once

#include <vector>

#include "checker/project_model.hpp"
#include "checker/semantic/direct_address.hpp"

namespace rung::check {

// Every complete AT address declared in the project's own files (library stubs left out), and
// the pairs of them that share memory. An overlap can join declarations of two files, so the
// table is built once per ProjectModel::link() and only read while files are checked in parallel.
struct AddressTable {
  std::vector<const Symbol*> variables;  // project order: by source id, then by position
  std::vector<LocatedVariable> located;  // parallel to `variables`
  std::vector<AddressOverlap> overlaps;  // first < second; reported at the second declaration
};

AddressTable build_address_table(const ProjectModel& model);

// The address `variable` is declared AT, parsed in the profile's addressing mode; nullopt when
// it has no AT or the address is malformed.
std::optional<DirectAddress> declared_address(const ProjectModel& model, const Symbol& variable);

// Appends E503/E504/E505 for the AT declarations of `source` (tree coordinates).
void check_addresses(const ProjectModel& model, SourceId source, std::vector<Diagnostic>& out);

}  // namespace rung::check
