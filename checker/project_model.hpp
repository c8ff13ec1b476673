// The semantic model of a whole project: every source file and library stub with its symbols,
// the global index that ties names together across files (in any order), and the types of all
// declarations. Built in two steps: add/update sources (per-file declaration pass), then link()
// (global index, types, inheritance). After link() the model is read-only, so bodies can be
// checked in parallel and the language server can ask it questions.
#pragma once

#include <atomic>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "checker/constant/const_value.hpp"
#include "checker/profile.hpp"
#include "checker/symbols/file_symbols.hpp"
#include "checker/types/type.hpp"
#include "parser/document.hpp"

namespace rung::check {

struct AddressTable;        // semantic/address_checker.hpp
struct ConfigurationTable;  // semantic/configuration_checker.hpp
class RecursionIndex;       // semantic/recursion_checker.hpp

struct Source {
  std::unique_ptr<Document> document;
  FileSymbols symbols;
  bool library = false;
  std::string library_name;  // the stub library's folder name (namespace), empty for project files
  // Findings of the link step that belong to this file (unknown types in declarations, ...).
  std::vector<Diagnostic> link_diagnostics;
  std::string gvl_name_storage;  // a plain file's GVL name (its file name), viewed by its symbols
  // Changes whenever the document is replaced, and is never the same in two models: analyses kept
  // across edits (lint::ProjectIndex) compare it to know which files to read again.
  uint64_t revision = 0;
  // Hashes of the words of the text (case-insensitive), sorted, for `revision` (words_revision):
  // which files an interface edit may touch. Built on the first such edit.
  std::vector<uint32_t> words;
  uint64_t words_revision = 0;
};

// A second project-wide declaration of a global name, and its E003 (shared by link() and the
// incremental re-link).
bool is_duplicate_global(const Symbol& first, const Symbol& again);
Diagnostic duplicate_global_diagnostic(const Symbol& again, const Source& first_source);

class ProjectModel {
 public:
  explicit ProjectModel(const Profile& profile);
  ~ProjectModel();
  ProjectModel(const ProjectModel&) = delete;
  ProjectModel& operator=(const ProjectModel&) = delete;

  const Profile& profile() const { return profile_; }

  // Adds a parsed file; `library_name` non-empty marks a stub library file. Call link() after.
  SourceId add_source(std::unique_ptr<Document> document, std::string library_name = {});
  // The same with the file's symbols collected already (on a loading thread): collect_file_symbols
  // with the id this call gives, source_count() at the time of the call.
  SourceId add_source(std::unique_ptr<Document> document, std::string library_name, FileSymbols symbols);
  // What an editor change leaves to do.
  struct SourceUpdate {
    bool link_all = false;           // link() must follow, and every file may have new diagnostics
    std::vector<SourceId> affected;  // otherwise: the model is linked again, and these files (the
                                     // edited one first) are the ones whose diagnostics may differ
  };
  // Replaces a file's text (an editor change). A body edit re-links this file alone; an edit of
  // declarations re-links the files that name what changed (incremental_link.cpp); a few edits
  // (addresses, configurations, stub libraries, or many interface edits in a row) ask for link().
  SourceUpdate update_source(SourceId id, std::unique_ptr<Document> document);

  // Ties names across files and resolves every declaration's type. Deterministic.
  void link();
  // Threads for the whole-project passes of link() (0: one per core; default 1).
  void set_threads(unsigned threads) { threads_ = threads; }
  unsigned threads() const { return threads_; }
  // Changes with every link(), and is never the same in two models: what a file resolves against
  // other files' declarations stays valid while it does (a body-only update keeps it).
  uint64_t link_revision() const { return link_revision_; }

  size_t source_count() const { return sources_.size(); }
  const Source& source(SourceId id) const { return *sources_[id]; }
  std::optional<SourceId> find_source(std::string_view path) const;

  // --- Name lookup -------------------------------------------------------------------------
  // A global POU, data type or GVL by name (project declarations shadow library stubs).
  const Symbol* find_global(std::string_view name) const;
  // A global variable visible without qualifier (not in a qualified_only list).
  const Symbol* find_global_variable(std::string_view name) const;
  // Enum values with this name in enums that allow unqualified access.
  const std::vector<const Symbol*>* find_enum_values(std::string_view name) const;
  // A variable of a {attribute 'qualified_only'} GVL or a value of such an enum: the name exists,
  // but only written with its list or type (GVL.x, E.value); nullptr if there is none.
  const Symbol* find_qualified_only(std::string_view name) const;
  // The VAR_GLOBAL a VAR_EXTERNAL of this name refers to, also in qualified_only lists.
  const Symbol* find_linked_global(std::string_view name) const;
  // A variable of any global list called `list` (lists of one name are merged, e.g. a TwinCAT GVL
  // split in several objects).
  const Symbol* find_in_global_lists(std::string_view list, std::string_view name) const;
  // A library namespace (the stub folder's name, e.g. Standard, Util).
  bool is_library_namespace(std::string_view name) const;
  const Symbol* find_in_library(std::string_view library, std::string_view name) const;
  // A member of a POU, struct or interface, also inherited (EXTENDS); nullptr if none.
  const Symbol* find_member(const Symbol* container, std::string_view name) const;
  // What a bare name means inside `scope` (a POU or member): locals, then the owner's members
  // and bases, then globals. Returns nullptr if nothing is visible by that name.
  const Symbol* lookup(const Symbol* scope, std::string_view name) const;
  // What a bare name means in the global scope only (CODESYS `.x`): a global variable, a POU,
  // type or GVL, an enum value.
  const Symbol* lookup_global(std::string_view name) const;
  // A TYPE declared inside `scope` or the POUs around it (OpenPCS POU-local types); nullptr if none.
  const Symbol* find_local_type(const Symbol* scope, std::string_view name) const;
  // A value of an enumeration declared inside `scope` or the POUs around it.
  const Symbol* find_local_enum_value(const Symbol* scope, std::string_view name) const;
  // Whether `scope`, its owners or their bases EXTEND something that could not be resolved: names
  // may come from there, so "not declared" would be a guess.
  bool has_unresolved_base(const Symbol* scope) const;
  // Every name visible in `scope` (for "did you mean" and completion), deduplicated.
  std::vector<std::string_view> visible_names(const Symbol* scope) const;
  std::vector<std::string_view> global_type_names() const;

  // --- Types --------------------------------------------------------------------------------
  TypeArena& types() const { return *types_; }
  // The type of a symbol: a variable's declared type, a POU's instance type, a data type.
  const Type* type_of(const Symbol* symbol) const;
  // Resolves a type written in `scope`; unknown names give E002 in `diagnostics` if given.
  const Type* resolve_type(SyntaxNode type_spec, const Symbol* scope, std::vector<Diagnostic>* diagnostics);
  // The POU or data type a type name written in `scope` names (EXTENDS FB_Base, x : ST_Point);
  // nullptr for elementary and unknown types. Read-only after link() (the language server asks).
  const Symbol* resolve_type_symbol(SyntaxNode name, const Symbol* scope, std::vector<Diagnostic>* diagnostics) const;
  // The constant value of an expression in `scope` (literals, CONSTANTs, enum values).
  std::optional<ConstValue> constant_value(SyntaxNode expression, const Symbol* scope) const;
  // An enum value's integer value.
  std::optional<__int128> enum_value(const Symbol* value) const;

  // --- Whole-project tables, built at the end of link() and read-only after it ----------------
  // Checks of one file that need every other file too (AT addresses that overlap across files,
  // VAR_CONFIG entries against the instances they complete) read them, so files checked in
  // parallel never build them twice.
  const AddressTable& address_table() const { return *address_table_; }
  const ConfigurationTable& configuration_table() const { return *configuration_table_; }
  // The call graph is built on first use after link() (thread-safe): `rung check` asks for it,
  // while `rung lint` on a project without CONFIGURATION and most editor requests never do.
  const RecursionIndex& recursion_index() const;

  // Everything in declaration order: for checks that walk all POUs.
  std::vector<const Symbol*> top_level_symbols(SourceId id) const;

 private:
  void index_source(Source& source, bool report_duplicates = true);
  // incremental_link.cpp: a body-only edit without a full link().
  bool relink_bodies_only(Source& source, std::unique_ptr<Document>& document, FileSymbols& fresh);
  // incremental_link.cpp: an edit of declarations; nullopt when it needs a full link().
  std::optional<std::vector<SourceId>> relink_interface(Source& source, std::unique_ptr<Document>& document,
                                                        FileSymbols& fresh);
  void install_symbols(Source& source, std::unique_ptr<Document> document, FileSymbols fresh);
  void index_all_sources(bool report_duplicates);
  void rekey_names(SourceId id, std::string_view old_text);
  void report_duplicate_globals(Source& source);
  void resolve_declarations(Source& source);
  void resolve_symbol(Symbol& symbol, std::vector<Diagnostic>& diagnostics);
  void resolve_bases(Symbol& symbol, std::vector<Diagnostic>& diagnostics);
  const Type* named_type_of(const Symbol* symbol) const;
  const Type* resolve_type_name(SyntaxNode name, const Symbol* scope, std::vector<Diagnostic>* diagnostics) const;
  void compute_enum_values(const Symbol& enum_symbol);

  Profile profile_;
  std::vector<std::unique_ptr<Source>> sources_;
  std::unique_ptr<TypeArena> types_;
  using NameMap = std::unordered_map<std::string_view, const Symbol*, NameHash, NameEqual>;
  NameMap globals_;           // POUs, data types and GVLs
  NameMap global_variables_;  // unqualified global variables
  std::unordered_map<std::string_view, std::vector<const Symbol*>, NameHash, NameEqual> enum_values_;
  // Every global list (qualified_only or not) and qualified_only enum. Pointers, not names, so a
  // body-only re-link keeps them without re-keying.
  std::vector<const Symbol*> global_lists_;
  std::vector<const Symbol*> qualified_only_enums_;
  std::unordered_map<std::string_view, NameMap, NameHash, NameEqual> libraries_;
  std::unordered_map<const Symbol*, const Type*> named_types_;  // data types and POUs
  std::unordered_map<const Symbol*, __int128> enum_numbers_;
  std::unique_ptr<AddressTable> address_table_;
  std::unique_ptr<ConfigurationTable> configuration_table_;
  std::unique_ptr<RecursionIndex> recursion_index_;
  mutable std::mutex recursion_mutex_;
  mutable std::atomic<bool> recursion_current_{false};  // recursion_index_ matches the linked model
  unsigned threads_ = 1;
  uint64_t link_revision_ = 0;
  // Symbols and texts an interface edit replaced. Only files that name a changed declaration are
  // resolved again, so the rest must never reach these; they are kept alive anyway (a wrong
  // answer beats a dangling pointer) and freed by the next link(); relink_interface() asks for
  // one when too many pile up.
  std::vector<std::pair<FileSymbols, std::unique_ptr<Document>>> retired_;
  mutable std::mutex types_mutex_;  // derived types may be created while bodies are checked
};

}  // namespace rung::check
