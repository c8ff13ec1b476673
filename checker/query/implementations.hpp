// Go to implementation, and the families of methods that must keep one name: which blocks extend
// or implement a block or interface, and which methods and properties implement or override a
// given one (EXTENDS and IMPLEMENTS as the linker resolved them).
#pragma once

#include <vector>

#include "checker/project_model.hpp"

namespace rung::check::query {

// Every FUNCTION_BLOCK, CLASS or INTERFACE that EXTENDS `block`, directly or through others, in
// source and declaration order.
std::vector<const Symbol*> derived_blocks(const ProjectModel& model, const Symbol& block);

// Whether the FUNCTION_BLOCK or CLASS `block` implements `interface`: it, or a block it extends,
// IMPLEMENTS `interface` or an interface that extends `interface`.
bool implements(const Symbol& block, const Symbol& interface);

// What "go to implementation" lists for `symbol`, in source and declaration order:
// - an INTERFACE: every FUNCTION_BLOCK and CLASS that implements it;
// - a FUNCTION_BLOCK or CLASS: itself and every block that extends it;
// - a METHOD or PROPERTY of an interface: the method or property of that name each implementing
//   block declares itself, unless ABSTRACT (it has no code to go to);
// - a METHOD or PROPERTY of a block: itself (unless ABSTRACT) and the overrides in the blocks
//   that extend it;
// - anything else: nothing.
std::vector<const Symbol*> implementations_of(const ProjectModel& model, const Symbol& symbol);

// The methods (or properties) that share one name through inheritance: `member`, the interface
// and base members it implements or overrides, and every member that implements or overrides
// one of these. Renaming one of them without the others breaks the code. Just `member` for any
// other kind of symbol.
std::vector<const Symbol*> member_family(const ProjectModel& model, const Symbol& member);

}  // namespace rung::check::query
