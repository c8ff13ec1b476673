// Names the compilers know without any declaration: operators written like functions
// (__NEW, __ISVALIDREF, UPPER_BOUND ...) and system namespaces (__SYSTEM, TwinCAT_SystemInfoVarList).
// The standard functions themselves are not here: they are declared in library/ stubs.
#pragma once

#include <string_view>

namespace rung::check {

struct Builtin {
  std::string_view name;
  const char* value_type;  // elementary result type name, nullptr when it depends on the arguments
  bool is_namespace;       // used as Qualifier.Member
  bool is_callable;
};

const Builtin* find_builtin(std::string_view name);

}  // namespace rung::check
