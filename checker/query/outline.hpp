// The outline of one file, for an editor's document symbols: its POUs with their VAR blocks,
// variables, methods, properties, actions and SFC steps and transitions; its data types with
// their fields and enum values; its global variable lists; its configurations with their
// resources, tasks and program instances. Ranges are in FILE coordinates (a TwinCAT container's
// own lines), so a name TwinCAT keeps only in its XML (an action, a GET accessor) points there.
#pragma once

#include <string>
#include <vector>

#include "checker/project_model.hpp"

namespace rung::check::query {

enum class OutlineKind : uint8_t {
  Program,
  Function,
  FunctionBlock,
  Class,
  Interface,
  Method,
  Property,
  Accessor,  // GET or SET of a property
  Action,
  Transition,  // a TRANSITION object or an SFC transition
  Step,        // an SFC step
  Struct,
  Union,
  Enum,
  Alias,  // TYPE T : INT; subranges, arrays, references
  EnumValue,
  VarBlock,  // VAR_INPUT ... END_VAR
  Variable,
  Constant,  // a variable of a VAR CONSTANT block
  Field,     // a member of a STRUCT or UNION
  GlobalList,
  Configuration,
  Resource,
  Task,
  ProgramInstance,  // PROGRAM p WITH t : PRG_Main
};

struct OutlineItem {
  std::string name;  // never empty
  OutlineKind kind = OutlineKind::Variable;
  std::string detail;                 // a variable's or result type, EXTENDS / IMPLEMENTS, CONSTANT, ... as written
  TextRange range;                    // FILE coordinates: the whole declaration (covers the children)
  TextRange selection;                // FILE coordinates: the name, inside `range`
  std::vector<OutlineItem> children;  // in text order
};

// The outline of `source`, top-level items in text order. Empty for a file without a tree.
std::vector<OutlineItem> document_outline(const ProjectModel& model, SourceId source);

// How a declared symbol is shown (a variable of a CONSTANT block is a Constant, a struct's member
// a Field, a property's GET an Accessor, ...).
OutlineKind outline_kind_of(const Symbol& symbol);

// `text` cut to at most `limit` bytes (never inside a UTF-8 character), "..." added where cut.
std::string cut_text(std::string text, size_t limit);

// Where the editor shows the name of `symbol`: its name token in FILE coordinates, or, for a name
// a TwinCAT container holds only in its XML (an action, a transition, a property accessor, a
// global variable list), the value of that element's Name attribute. Empty at the declaration's
// start when there is neither.
TextRange name_range_in_file(const ProjectModel& model, const Symbol& symbol);

}  // namespace rung::check::query
