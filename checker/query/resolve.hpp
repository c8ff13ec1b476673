// What a name written in a file means: the one resolution every query uses (go to definition,
// hover, find references), so that a reference search finds exactly the names that "go to
// definition" would lead to the same declaration.
//
// Names inside bodies and initial values are resolved by the body checker's own expression typing
// (BodyChecker::type_of), never by a second implementation of the lookup rules; names in type
// positions by ProjectModel::resolve_type_symbol, like the linker does.
#pragma once

#include "checker/project_model.hpp"

namespace rung::check {
struct ExprInfo;  // semantic/body_checker.hpp
}

namespace rung::check::query {

// How a name is used where it stands, which decides how it is resolved.
enum class NameUse {
  Declaration,        // declares a symbol: a POU, variable, type, enum value, method ...
  TypeName,           // x : ST_Point, EXTENDS FB_Base, PROGRAM p WITH t : PRG_Main
  Expression,         // a name in a body or initial value; also obj.member, E_Color#Red, THIS^
  Parameter,          // fb(IN := ...), fb(Q => ...), PROGRAM p WITH t : PRG(a := 1), fb : FB(x := 1)
  InitializedMember,  // s : ST_Point := (x := 1)
  GlobalReference,    // CODESYS .x: the global x even where a local hides it
  IlOperator,         // an IL operator that names a function: LD a / MyFunction b
  Other,              // a label, task or resource name, a namespace qualifier: no symbol
};

struct NameSite {
  NameUse use = NameUse::Other;
  // For Expression: the smallest expression whose typing tells what the name is (the name itself,
  // `obj.name` when it is the member, `E#name`, `THIS^`). Also the expression type_at types.
  SyntaxNode expression;
  const Symbol* declared = nullptr;  // for Declaration
};

// How `name` (an identifier in the tree of `source`) is used.
NameSite name_site(const ProjectModel& model, SourceId source, SyntaxNode name);

// The symbol `name` refers to, read in `scope` (query::scope_at); nullptr for names that do not
// refer to a declaration (labels, builtins, undeclared names). A VAR_EXTERNAL is resolved to the
// global variable it stands for, so both count as the same symbol.
const Symbol* resolve_name(const ProjectModel& model, SourceId source, SyntaxNode name, const Symbol* scope);

// The declaration a symbol stands for in queries: a VAR_EXTERNAL is its global variable.
const Symbol* canonical_symbol(const ProjectModel& model, const Symbol* symbol);

// The POU a call goes to, from the typing of its `function` part: the FUNCTION, METHOD, ACTION or
// PROGRAM it names, or the block of the FB instance it names (the choice BodyChecker::type_call
// makes before it checks the arguments against the callee's parameters); nullptr otherwise.
const Symbol* callee_of(const ExprInfo& function);

// The symbol declared with exactly this name token in `source`, if any.
const Symbol* symbol_declared_at(const ProjectModel& model, SourceId source, TextRange name_range);

}  // namespace rung::check::query
