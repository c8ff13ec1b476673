// The declaration pass over one file: every POU, member, variable, type, enum value, global
// variable list and configuration it declares, as Symbols. Nothing here looks at other files;
// names are tied together later by the ProjectModel's link step.
#pragma once

#include <deque>
#include <string>
#include <unordered_map>
#include <vector>

#include "checker/symbols/symbol.hpp"
#include "parser/diagnostic.hpp"
#include "parser/document.hpp"

namespace rung::check {

struct FileSymbols {
  SourceId source = kNoSource;
  bool library = false;
  std::deque<Symbol> storage;        // owns every symbol of the file (stable addresses)
  std::vector<Symbol*> top_level;    // POUs, data types, GVLs, configurations in text order
  std::vector<Symbol*> global_lists; // GVLs (also listed in top_level)
  // Declaration-level findings of this file alone (duplicate names in one scope).
  std::vector<Diagnostic> diagnostics;
  // A fingerprint of everything other files can see (names, declarations, not bodies): when an
  // edit leaves it unchanged, other files need no re-check.
  uint64_t interface_hash = 0;
};

// `gvl_name` names the global variable lists of a plain text file (CODESYS exports a GVL as
// <name>.st); container files name their lists themselves.
FileSymbols collect_file_symbols(SourceId source, const Document& document, bool library, std::string_view gvl_name);
// Every POU of the file in text order, members (methods, actions, properties...) right after their
// owner: what the body checks and the linter visit.
std::vector<const Symbol*> pous_of(const FileSymbols& symbols);
// Gives symbols collected under one id another (a file loaded in parallel whose id shifted).
void renumber(FileSymbols& symbols, SourceId source);

// The attribute pragmas written right before a declaration node ({attribute 'hide'}).
std::vector<Attribute> attributes_before(SyntaxNode node);
// The attribute pragmas before each child of `parent`, by the child's start offset, in one pass
// (asking attributes_before() for every declaration of a long VAR block is quadratic).
using ChildAttributes = std::unordered_map<uint32_t, std::vector<Attribute>>;
ChildAttributes attributes_of_children(SyntaxNode parent);
// Parses one pragma's text: {attribute 'name' := 'value'} → {name, value}; nullopt otherwise.
std::optional<Attribute> parse_attribute_pragma(std::string_view text);

}  // namespace rung::check
