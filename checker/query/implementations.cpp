#include "checker/query/implementations.hpp"

#include <algorithm>
#include <unordered_set>

namespace rung::check::query {
namespace {

using SymbolSet = std::unordered_set<const Symbol*>;

bool is_block(const Symbol& symbol) {
  return symbol.kind == SymbolKind::FunctionBlock || symbol.kind == SymbolKind::Class;
}

bool takes_part_in_inheritance(const Symbol& symbol) {
  return is_block(symbol) || symbol.kind == SymbolKind::Interface;
}

// Everything `start` inherits from: the blocks and interfaces it EXTENDS and, with
// `with_interfaces`, the interfaces it (or any of those) IMPLEMENTS and what they extend. A set
// with a visited check, because broken code may EXTEND in a cycle and interfaces may form diamonds.
SymbolSet ancestors(const Symbol& start, bool with_interfaces) {
  SymbolSet seen;
  std::vector<const Symbol*> pending{&start};
  while (!pending.empty()) {
    const Symbol* current = pending.back();
    pending.pop_back();
    auto visit = [&](const Symbol* next) {
      if (next && next != &start && seen.insert(next).second) pending.push_back(next);
    };
    for (const Symbol* base : current->bases) visit(base);
    if (with_interfaces) {
      for (const Symbol* interface : current->interfaces) visit(interface);
    }
  }
  return seen;
}

// Every block and interface of the project (stub libraries too), in source and declaration order.
template <typename Visit>
void for_each_inheriting(const ProjectModel& model, Visit&& visit) {
  for (SourceId id = 0; id < model.source_count(); ++id) {
    for (const Symbol* top : model.source(id).symbols.top_level) {
      if (takes_part_in_inheritance(*top)) visit(*top);
    }
  }
}

// The method or property `block` itself declares with the name and kind of `member`.
const Symbol* own_counterpart(const Symbol& block, const Symbol& member) {
  const Symbol* own = block.own_member(member.name);
  return own && own->kind == member.kind ? own : nullptr;
}

bool is_member_with_family(const Symbol& symbol) {
  return (symbol.kind == SymbolKind::Method || symbol.kind == SymbolKind::Property) && symbol.owner &&
         takes_part_in_inheritance(*symbol.owner);
}

}  // namespace

std::vector<const Symbol*> derived_blocks(const ProjectModel& model, const Symbol& block) {
  std::vector<const Symbol*> derived;
  for_each_inheriting(model, [&](const Symbol& candidate) {
    if (&candidate != &block && ancestors(candidate, false).contains(&block)) derived.push_back(&candidate);
  });
  return derived;
}

bool implements(const Symbol& block, const Symbol& interface) {
  return interface.kind == SymbolKind::Interface && is_block(block) && ancestors(block, true).contains(&interface);
}

std::vector<const Symbol*> implementations_of(const ProjectModel& model, const Symbol& symbol) {
  std::vector<const Symbol*> found;
  if (symbol.kind == SymbolKind::Interface) {
    for_each_inheriting(model, [&](const Symbol& candidate) {
      if (implements(candidate, symbol)) found.push_back(&candidate);
    });
  } else if (is_block(symbol)) {
    found.push_back(&symbol);
    for (const Symbol* derived : derived_blocks(model, symbol)) found.push_back(derived);
  } else if (is_member_with_family(symbol)) {
    const Symbol& owner = *symbol.owner;
    if (owner.kind == SymbolKind::Interface) {
      for_each_inheriting(model, [&](const Symbol& candidate) {
        if (!implements(candidate, owner)) return;
        const Symbol* own = own_counterpart(candidate, symbol);
        if (own && !own->has(kAbstract)) found.push_back(own);
      });
    } else {
      if (!symbol.has(kAbstract)) found.push_back(&symbol);
      for (const Symbol* derived : derived_blocks(model, owner)) {
        if (const Symbol* own = own_counterpart(*derived, symbol)) found.push_back(own);
      }
    }
  }
  return found;
}

std::vector<const Symbol*> member_family(const ProjectModel& model, const Symbol& member) {
  if (!is_member_with_family(member)) return {&member};
  // Every block or interface that declares a member of this name and kind, with what it inherits.
  struct Candidate {
    const Symbol* member;
    SymbolSet inherited;
  };
  std::vector<Candidate> candidates;
  for_each_inheriting(model, [&](const Symbol& owner) {
    if (const Symbol* own = own_counterpart(owner, member)) candidates.push_back({own, ancestors(owner, true)});
  });
  // Grow the family until it is closed: a member joins when its owner inherits from the owner of
  // a member of the family (it overrides or implements that one) or the other way round.
  std::vector<const Symbol*> family{&member};
  SymbolSet owners{member.owner};
  for (bool grew = true; grew;) {
    grew = false;
    for (const Candidate& candidate : candidates) {
      const Symbol* owner = candidate.member->owner;
      if (owners.contains(owner)) continue;
      const bool related = std::any_of(owners.begin(), owners.end(),
                                       [&](const Symbol* known) { return candidate.inherited.contains(known); }) ||
                           std::any_of(candidates.begin(), candidates.end(), [&](const Candidate& other) {
                             return owners.contains(other.member->owner) && other.inherited.contains(owner);
                           });
      if (!related) continue;
      owners.insert(owner);
      family.push_back(candidate.member);
      grew = true;
    }
  }
  return family;
}

}  // namespace rung::check::query
