// What every name of a file is, for an editor's semantic highlighting: an input, an output, a
// local, a global, a constant, an FB instance, a type of some kind, an enum value, a function,
// a method. Each name is resolved by resolve_name (the resolution go to definition uses), so the
// colour of a name and the place "go to definition" leads to always agree.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "checker/project_model.hpp"

namespace rung::check::query {

enum class NameClass : uint8_t {
  Namespace,      // a library namespace, a global variable list used as qualifier (GVL.x)
  Program,        // PROGRAM
  FunctionBlock,  // FUNCTION_BLOCK, CLASS
  Interface,
  Function,
  Method,  // METHOD
  Action,
  Property,
  Struct,  // STRUCT, UNION
  Enum,
  Alias,  // TYPE T : INT; subrange and array types
  Input,  // VAR_INPUT
  Output,  // VAR_OUTPUT
  InOut,   // VAR_IN_OUT
  Local,   // VAR, VAR_TEMP, VAR_STAT, VAR_INST, a program instance of a configuration
  Global,  // VAR_GLOBAL, and a VAR_EXTERNAL (it stands for its global)
  Field,   // a member of a STRUCT or UNION
  EnumValue,
};

// What else is true of the name's symbol.
enum NameFlag : uint16_t {
  kNameDeclaration = 1u << 0,  // the name declares its symbol here
  kNameConstant = 1u << 1,     // VAR CONSTANT, VAR_GLOBAL CONSTANT, an enum value
  kNameInstance = 1u << 2,     // a variable of a function block, class, program or interface type
  kNameLibrary = 1u << 3,      // declared in a standard library stub
  kNameStatic = 1u << 4,       // VAR_STAT
  kNameDeprecated = 1u << 5,   // {attribute 'obsolete'}
  kNameAbstract = 1u << 6,     // ABSTRACT
};

struct ClassifiedName {
  TextRange range;  // FILE coordinates of the name
  NameClass name_class = NameClass::Local;
  uint16_t flags = 0;
};

// The class and flags of names that refer to `symbol`; nullopt for symbols an editor has no
// colour for (tasks, resources, configurations, SFC steps, transitions).
std::optional<ClassifiedName> classify_symbol(const ProjectModel& model, const Symbol& symbol);

// Every name of `source` that starts inside `file_range` (FILE coordinates) and refers to a
// declaration, in file order. Names the model cannot resolve (undeclared names, elementary type
// names, labels) and names a container reader inserted are left out. `cancelled` is polled now
// and then: once it returns true, the names found so far are returned.
std::vector<ClassifiedName> classify_names(const ProjectModel& model, SourceId source, TextRange file_range,
                                           const std::function<bool()>& cancelled = {});

}  // namespace rung::check::query
