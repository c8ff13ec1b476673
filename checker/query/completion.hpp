// Completion: what may be written at the cursor, from the place the cursor stands in
// (query::cursor_context) — the variables, parameters, POUs, types, members, named parameters,
// keywords and skeletons that fit there, best first.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "checker/check.hpp"
#include "checker/query/cursor_context.hpp"

namespace rung::check::query {

enum class CandidateKind : uint8_t {
  Symbol,           // a declaration: variable, POU, type, member, enum value, global list
  Parameter,        // a formal parameter of the call around the cursor: `name :=` / `name =>`
  Keyword,          // IF, END_VAR, AND ... (upper case)
  ElementaryType,   // INT, TIME ... (upper case)
  LibraryNamespace, // Standard, Util: a stub library's name, written before '.'
  Snippet,          // a skeleton, named by its keyword: IF, CASE, FOR, WHILE, REPEAT, PROGRAM,
                    // FUNCTION_BLOCK, FUNCTION, INTERFACE, METHOD, PROPERTY, STRUCT, ENUM,
                    // VAR, VAR_INPUT, VAR_OUTPUT, VAR_IN_OUT, VAR_TEMP, VAR_STAT, VAR_GLOBAL
};

// Candidates come in this order; within a group as declared (members, parameters) or by name.
enum class CandidateGroup : uint8_t {
  Expected,  // fits what the cursor needs: a named parameter, a value of the enumeration expected
  Local,     // declared in the POU, method or action around the cursor
  Member,    // of the block around a method or action, of the value before '.'
  Global,    // global variables and lists, enumerations
  Project,   // POUs and types of the project
  Keyword,
  Library,   // stub library POUs, types and namespaces
  Snippet,
};

struct CompletionCandidate {
  CandidateKind kind = CandidateKind::Symbol;
  CandidateGroup group = CandidateGroup::Global;
  const Symbol* symbol = nullptr;  // Symbol, Parameter
  std::string_view word;           // Keyword, ElementaryType, LibraryNamespace, Snippet
  std::string_view qualifier;      // Symbol: written before it with '.' (E_Color for E_Color.Red)

  std::string_view name() const { return symbol ? symbol->name : word; }
};

struct Completion {
  CursorPlace place = CursorPlace::None;
  TextRange word;       // FILE coordinates of the name being typed (empty range at the cursor if none)
  std::string prefix;   // its part before the cursor
  std::vector<CompletionCandidate> candidates;  // in display order
  bool incomplete = false;  // more matched than `limit`: ask again as the user types on
};

// Candidates at `file_offset` that match the typed prefix (matches_prefix), at most `limit`.
Completion complete_at(const Workspace& workspace, SourceId source, uint32_t file_offset, size_t limit = 1000);

// Whether `name` holds the letters of `prefix` in order, ignoring case, the first of them where
// the name or a part of it begins (`tim` matches fbTimer, `mv` MAX_VALUE): the loose match editors
// filter completion lists with.
bool matches_prefix(std::string_view name, std::string_view prefix);

}  // namespace rung::check::query
