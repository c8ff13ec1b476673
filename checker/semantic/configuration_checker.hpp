// CONFIGURATION / RESOURCE / TASK / PROGRAM ... WITH and VAR_CONFIG:
//   E506  PROGRAM inst WITH task : Type names a task the resource does not declare, or a Type
//         that is not a PROGRAM of the project;
//   E507  a TASK with neither INTERVAL (cyclic) nor SINGLE (event) never runs (IEC profiles;
//         CODESYS runs such a task freewheeling), E102 for a PRIORITY outside the manuals' range;
//   E508  a VAR_CONFIG entry whose instance path names no variable, or gives an address to a
//         variable without an incomplete address (%I* / %Q*) of the same kind and type; and an
//         incomplete address of an instance that no VAR_CONFIG entry completes, in projects that
//         complete them in VAR_CONFIG (MP300 manual L11596-11654: both are compile errors).
#pragma once

#include <map>
#include <string>
#include <vector>

#include "checker/project_model.hpp"

namespace rung::check {

// Incomplete addresses of the project's instances that no VAR_CONFIG entry completes, by the
// declaration (`xLocIn AT %I* : BOOL` in an FB) and the instance paths that miss it. Needs every
// instance and every VAR_CONFIG of the project, so it is built once per ProjectModel::link().
struct ConfigurationTable {
  std::map<const Symbol*, std::vector<std::string>> unconfigured;
};

ConfigurationTable build_configuration_table(const ProjectModel& model);

// Appends E506/E507/E508 (and E102, E301 for task arguments) for `source` (tree coordinates).
void check_configurations(const ProjectModel& model, SourceId source, std::vector<Diagnostic>& out);

}  // namespace rung::check
