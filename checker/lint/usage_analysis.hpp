// Where the names of one file are used and how: the analysis the usage rules (L070-L079) share.
// Every name in bodies, initial values, types and configurations is resolved the way the checker
// resolves it (ProjectModel::lookup, BodyChecker::type_of, resolve_type_symbol), never by its
// spelling, and recorded with what the code does with it there: reads, writes, passes it to a
// VAR_IN_OUT, takes its address, calls it, or names it as a type.
#pragma once

#include <span>
#include <string_view>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "checker/lint/node_list.hpp"
#include "checker/project_model.hpp"

namespace rung::lint {

enum UseFlag : uint16_t {
  kUseRead = 1u << 0,          // the value is read
  kUseWrite = 1u << 1,         // assigned: `:=`, S=/R=, `=> target`, IL ST/S/R, a boolean SFC action
  kUsePart = 1u << 2,          // the read or write reaches an element, member or bit only (a[i], s.x, w.3)
  kUseInOut = 1u << 3,         // passed to a VAR_IN_OUT: the callee may read and write it
  kUseAddress = 1u << 4,       // ADR(x), REF= x, __QUERYPOINTER: read and written later through the pointer
  kUseCall = 1u << 5,          // called: a POU, or an FB instance (whose state the call reads and writes)
  kUseOutputTarget = 1u << 6,  // the write is `=> x` of a call (some calls must bind every output)
  kUseMention = 1u << 7,       // named without touching the value: SIZEOF(x), a type name, UPPER_BOUND(a, 1)
};

// What the code may do to a variable's value, beyond reading it.
constexpr uint16_t kUseMayWrite = kUseWrite | kUseInOut | kUseAddress | kUseCall;
// What counts as looking at the value.
constexpr uint16_t kUseMayRead = kUseRead | kUseInOut | kUseAddress | kUseCall | kUseMention;

struct Use {
  const check::Symbol* symbol = nullptr;  // a VAR_EXTERNAL is recorded as its global variable
  const check::Symbol* scope = nullptr;   // the POU, member, type or global list the name stands in
  TextRange range;                        // the name (tree coordinates)
  uint16_t flags = 0;
};

struct FileUsage {
  std::vector<Use> uses;  // in text order
  // Names that resolve to nothing: undeclared names and members written after an object whose
  // type is unknown (a missing library). They may name any block's variable, so project-wide
  // questions treat these names as used. Also the names of VAR_CONFIG and VAR_ACCESS paths, which
  // the checker resolves on its own.
  std::unordered_set<std::string_view, check::NameHash, check::NameEqual> unresolved_names;

  // Names in code that conditional compilation left out ({IF defined(DEBUG)} ... {END_IF}): the
  // same file built with other defines uses them, so no rule may call them unused.
  std::unordered_set<std::string_view, check::NameHash, check::NameEqual> inactive_names;
  // POUs (and members) whose code holds a pragma that is not one of rung's kinds: Beremiz/MATIEC
  // embed C code as {{ ... }}, which reads and writes the variables where rung cannot see it.
  std::unordered_set<const check::Symbol*> embedding_scopes;

  // Whether `pou` or one of its members embeds such code.
  bool embeds_foreign_code(const check::Symbol& pou) const;
  // The uses of one symbol, in text order.
  std::span<const uint32_t> uses_of(const check::Symbol* symbol) const;
  // The uses whose name starts inside `range`, in text order.
  std::span<const Use> uses_in(TextRange range) const;

  std::unordered_map<const check::Symbol*, std::vector<uint32_t>> by_symbol;
};

FileUsage collect_usage(const check::ProjectModel& model, check::SourceId source);
// The same with the file's node list built already (`nodes`, of the file's tree).
FileUsage collect_usage(const check::ProjectModel& model, check::SourceId source, const NodeList& nodes);

// Whether `scope` is `pou` or one of its members (methods, actions, property accessors).
bool is_within(const check::Symbol* scope, const check::Symbol* pou);
// The same, or a POU that EXTENDS `pou` (directly or not), or a member of one: code that sees
// `pou`'s variables as its own.
bool is_within_or_derived(const check::Symbol* scope, const check::Symbol* pou);

}  // namespace rung::lint
