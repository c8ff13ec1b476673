// Edits without a full link().
//
// The language server's common case: an edit inside a body. The file's declarations read the
// same (its interface hash is unchanged), so every other file's links into it stay right: the
// file's Symbol objects are kept, and only what points into the old tree and text is moved to
// the new one. Then this file's declarations are resolved again. A full link() of a 2,000-file
// project takes the better part of a second; this takes about as long as parsing the one file.
#include <fmt/format.h>

#include <algorithm>
#include <unordered_map>
#include <unordered_set>

#include "checker/project_model.hpp"
#include "checker/semantic/address_checker.hpp"
#include "checker/semantic/configuration_checker.hpp"
#include "checker/semantic/recursion_checker.hpp"
#include "checker/symbols/names.hpp"

namespace rung::check {
namespace {

// The same declarations in the same order: the body edit did not add or remove any symbol (an
// SFC step, a snippet's VAR block, ...).
bool same_shape(const FileSymbols& old_symbols, const FileSymbols& fresh) {
  if (old_symbols.storage.size() != fresh.storage.size()) return false;
  for (size_t i = 0; i < fresh.storage.size(); ++i) {
    const Symbol& before = old_symbols.storage[i];
    const Symbol& now = fresh.storage[i];
    if (before.kind != now.kind || before.ordered.size() != now.ordered.size()) return false;
    // A plain file's GVL gets its name (the file name) after collection.
    const bool named_later = now.kind == SymbolKind::GlobalList && now.name.empty();
    if (!named_later && before.name != now.name) return false;
  }
  return true;
}

bool points_into(std::string_view key, std::string_view text) {
  return !text.empty() && key.data() >= text.data() && key.data() < text.data() + text.size();
}

// FNV-1a over the upper-cased name: the case-insensitive identity of a word.
uint32_t word_hash(std::string_view word) {
  uint32_t hash = 2166136261u;
  for (const char c : word) hash = (hash ^ static_cast<unsigned char>(ascii_upper(c))) * 16777619u;
  return hash;
}

std::vector<uint32_t> words_of(std::string_view text) {
  std::vector<uint32_t> words;
  for (size_t at = 0; at < text.size();) {
    if (!is_identifier_char(text[at])) {
      ++at;
      continue;
    }
    const size_t begin = at;
    while (at < text.size() && is_identifier_char(text[at])) ++at;
    words.push_back(word_hash(text.substr(begin, at - begin)));
  }
  std::sort(words.begin(), words.end());
  words.erase(std::unique(words.begin(), words.end()), words.end());
  return words;
}

uint64_t mix(uint64_t hash, std::string_view bytes) {
  for (const char c : bytes) hash = (hash ^ static_cast<unsigned char>(c)) * 1099511628211ull;
  return (hash ^ 0xff) * 1099511628211ull;  // a separator, so that "ab","c" differs from "a","bc"
}

// What other files can see of one declaration, without its members (they have their own) or
// bodies: kind, flags, attributes, and the text of its declaration (for a POU: result type,
// EXTENDS, IMPLEMENTS).
uint64_t declaration_hash(const Symbol& symbol) {
  uint64_t hash = mix(14695981039346656037ull, symbol_kind_name(symbol.kind));
  hash = mix(hash, std::to_string(symbol.flags));
  for (const Attribute& attribute : symbol.attributes) hash = mix(mix(hash, attribute.name), attribute.value);
  if (is_pou_kind(symbol.kind)) {
    if (symbol.type_node) hash = mix(hash, symbol.type_node.text());
    for (const SyntaxNode& node : symbol.base_nodes) hash = mix(hash, node.text());
    for (const SyntaxNode& node : symbol.interface_nodes) hash = mix(hash, node.text());
  } else if (symbol.node) {
    hash = mix(hash, symbol.node.text());
  }
  return hash;
}

struct Declared {
  uint64_t hash = 0;
  std::string_view name;
  std::vector<std::string_view> owners;  // the declarations it is a member of, top-level first
  bool located = false;                  // AT %...: the address table's overlaps reach files that do not name it
  bool visible = false;                  // named without its owner: a top-level name, a GVL variable, an enum value
};

// Every declaration of a file by its path of upper-cased names and kinds (FB_A.METHOD:M.VARIABLE:X).
void collect_declared(const Symbol& symbol, const std::string& prefix, std::vector<std::string_view>& owners,
                      bool visible, std::unordered_map<std::string, Declared>& out) {
  std::string key = prefix + upper_name(symbol.name) + ':' + std::string(symbol_kind_name(symbol.kind));
  while (out.contains(key)) key += '\'';  // a duplicate in one scope (its own error) keeps both
  out.emplace(
      key, Declared{declaration_hash(symbol), symbol.name, owners, static_cast<bool>(symbol.location_node), visible});
  const bool members_visible = symbol.kind == SymbolKind::GlobalList || symbol.kind == SymbolKind::DataType;
  owners.push_back(symbol.name);
  for (const Symbol* member : symbol.ordered)
    collect_declared(*member, key + '.', owners, visible && members_visible, out);
  owners.pop_back();
}

std::unordered_map<std::string, Declared> declared_in(const FileSymbols& symbols) {
  std::unordered_map<std::string, Declared> out;
  std::vector<std::string_view> owners;
  for (const Symbol* top : symbols.top_level) collect_declared(*top, "", owners, true, out);
  return out;
}

// The names whose users an interface edit touches. Every symbol of the file is new (other files
// that resolved one of its names point at the old one), so: every name other files reach without
// an owner, old and new; and every member declaration added, removed or changed (reached through
// instances: its users name it). Empty optional: the edit touched an address.
std::optional<std::vector<std::string_view>> changed_names(const std::unordered_map<std::string, Declared>& before,
                                                           const std::unordered_map<std::string, Declared>& after) {
  std::vector<std::string_view> names;
  for (const auto* declared : {&before, &after}) {
    for (const auto& [key, entry] : *declared) {
      if (entry.visible) names.push_back(entry.name);
    }
  }
  // A changed method parameter: its users name the method (and reach it through instances of
  // the block): every owner counts.
  auto note = [&](const Declared& declared) {
    names.push_back(declared.name);
    names.insert(names.end(), declared.owners.begin(), declared.owners.end());
    return !declared.located;
  };
  for (const auto& [key, old_declared] : before) {
    auto found = after.find(key);
    if (found != after.end() && found->second.hash == old_declared.hash) continue;
    if (!note(old_declared)) return std::nullopt;
    if (found != after.end() && !note(found->second)) return std::nullopt;
  }
  for (const auto& [key, new_declared] : after) {
    if (!before.contains(key) && !note(new_declared)) return std::nullopt;
  }
  return names;
}

}  // namespace

bool ProjectModel::relink_bodies_only(Source& source, std::unique_ptr<Document>& document, FileSymbols& fresh) {
  if (source.library || !source.document || !source.document->tree() || !document->tree()) return false;
  if (fresh.interface_hash != source.symbols.interface_hash || !same_shape(source.symbols, fresh)) return false;
  const SourceId id = fresh.source;
  // The old text stays alive until the names that index it have moved to the new text.
  std::unique_ptr<Document> old_document = std::move(source.document);
  source.document = std::move(document);
  for (size_t i = 0; i < fresh.storage.size(); ++i) {
    Symbol& kept = source.symbols.storage[i];
    const Symbol& now = fresh.storage[i];
    if (!now.name.empty()) kept.name = now.name;
    kept.name_range = now.name_range;
    kept.node = now.node;
    kept.type_node = now.type_node;
    kept.location_node = now.location_node;
    kept.base_nodes = now.base_nodes;
    kept.interface_nodes = now.interface_nodes;
    kept.attributes = now.attributes;
    kept.flags = now.flags;
  }
  // Member maps are keyed by views of the names: build them again over the moved names.
  for (Symbol& kept : source.symbols.storage) {
    if (kept.members.empty()) continue;
    decltype(kept.members) members;
    members.reserve(kept.members.size());
    for (const auto& [name, member] : kept.members) members.emplace(member->name, member);
    kept.members = std::move(members);
  }
  source.symbols.diagnostics = std::move(fresh.diagnostics);
  rekey_names(id, old_document->tree()->text());
  old_document.reset();

  // This file's declarations again: same types (named types are per Symbol, derived ones
  // interned), new positions for its link diagnostics.
  source.link_diagnostics.clear();
  report_duplicate_globals(source);
  for (Symbol& symbol : source.symbols.storage) {
    symbol.type = nullptr;
    symbol.result_type = nullptr;
    if (symbol.kind == SymbolKind::DataType) {
      if (const Type* named = named_type_of(&symbol);
          named && (named->kind == TypeKind::Alias || named->kind == TypeKind::Enum)) {
        const_cast<Type*>(named)->element = nullptr;  // resolved again below, to the same type
      }
    }
  }
  resolve_declarations(source);
  address_table_ = std::make_unique<AddressTable>(build_address_table(*this));
  configuration_table_ = std::make_unique<ConfigurationTable>(build_configuration_table(*this));
  // A call graph not built yet is built whole when first asked for.
  if (recursion_current_.load(std::memory_order_acquire)) recursion_index_->rebuild_source(*this, id);
  return true;
}

// An edit of declarations (a VAR_INPUT added, a type changed, a POU renamed). Only a file that
// names a changed declaration can hold a pointer to it or a diagnostic about it (every use of a
// declaration, a member through any chain of instances, an inherited member, writes its name), so
// only those files are resolved again and returned for a re-check; the global indexes are rebuilt
// whole (cheap), and the old symbols retire (see retired_). Addresses and CONFIGURATIONs reach
// files without names (overlaps, task assignment): those edits still link everything.
std::optional<std::vector<SourceId>> ProjectModel::relink_interface(Source& source, std::unique_ptr<Document>& document,
                                                                    FileSymbols& fresh) {
  // Then one full link() frees them: a parsed document takes about 7 times its text (text and
  // node table), so at most ~30 MB wait, and a link of the whole project every few hundred
  // keystrokes in a VAR block costs little per keystroke.
  constexpr size_t kMaxRetired = 256;
  constexpr size_t kMaxRetiredText = 4u << 20;
  if (source.library || !source.document || !source.document->tree() || !document->tree()) return std::nullopt;
  size_t retired_text = 0;
  for (const auto& [symbols, old_document] : retired_) retired_text += old_document->source_text().size();
  if (retired_.size() >= kMaxRetired || retired_text + source.document->source_text().size() > kMaxRetiredText) {
    return std::nullopt;
  }
  const auto configuration = [](const FileSymbols& symbols) {
    return std::any_of(symbols.top_level.begin(), symbols.top_level.end(),
                       [](const Symbol* top) { return top->kind == SymbolKind::Configuration; });
  };
  if (configuration(source.symbols) || configuration(fresh)) return std::nullopt;
  const auto before = declared_in(source.symbols);
  const SourceId id = fresh.source;
  // A plain file's GVL takes its name from the file (the same path, so the same name) when
  // installed: compare it named.
  for (Symbol* list : fresh.global_lists) {
    if (list->name.empty()) list->name = source.gvl_name_storage;
  }
  const auto after = declared_in(fresh);
  const std::optional<std::vector<std::string_view>> names = changed_names(before, after);
  if (!names) return std::nullopt;

  // The files that name a changed declaration (their word lists are kept by revision).
  std::unordered_set<uint32_t> wanted;
  for (const std::string_view name : *names) {
    if (!name.empty()) wanted.insert(word_hash(name));
  }
  std::vector<SourceId> affected{id};
  for (SourceId other = 0; other < sources_.size(); ++other) {
    Source& candidate = *sources_[other];
    if (other == id || candidate.library || !candidate.document || !candidate.document->tree()) continue;
    if (candidate.words_revision != candidate.revision) {
      candidate.words = words_of(candidate.document->tree()->text());
      candidate.words_revision = candidate.revision;
    }
    const bool names_one = std::any_of(wanted.begin(), wanted.end(), [&](uint32_t word) {
      return std::binary_search(candidate.words.begin(), candidate.words.end(), word);
    });
    if (names_one) affected.push_back(other);
  }

  // The old symbols retire with their text; the new ones take their place in the indexes.
  for (const Symbol& old_symbol : source.symbols.storage) {
    named_types_.erase(&old_symbol);
    enum_numbers_.erase(&old_symbol);
  }
  retired_.emplace_back(std::move(source.symbols), std::move(source.document));
  install_symbols(source, std::move(document), std::move(fresh));
  index_all_sources(false);

  for (const SourceId target : affected) {
    Source& relinked = *sources_[target];
    relinked.link_diagnostics.clear();
    report_duplicate_globals(relinked);
    for (Symbol& symbol : relinked.symbols.storage) {
      symbol.type = nullptr;
      symbol.result_type = nullptr;
      if (symbol.kind != SymbolKind::DataType) continue;
      if (const Type* named = named_type_of(&symbol);
          named && (named->kind == TypeKind::Alias || named->kind == TypeKind::Enum)) {
        const_cast<Type*>(named)->element = nullptr;  // resolved again below, in place
      }
    }
  }
  for (const SourceId target : affected) resolve_declarations(*sources_[target]);
  address_table_ = std::make_unique<AddressTable>(build_address_table(*this));
  configuration_table_ = std::make_unique<ConfigurationTable>(build_configuration_table(*this));
  if (recursion_current_.load(std::memory_order_acquire)) recursion_index_->rebuild_sources(*this, affected);
  return affected;
}

// The project-wide name indexes hold views of this file's old text: point them at the new names.
void ProjectModel::rekey_names(SourceId id, std::string_view old_text) {
  auto rekey = [&](NameMap& map) {
    std::vector<std::string_view> stale;
    for (const auto& [name, symbol] : map) {
      if (points_into(name, old_text)) stale.push_back(name);
    }
    for (std::string_view name : stale) {
      auto entry = map.extract(name);
      entry.key() = entry.mapped()->name;
      map.insert(std::move(entry));
    }
  };
  rekey(globals_);
  rekey(global_variables_);
  std::vector<std::string_view> stale;
  for (const auto& [name, values] : enum_values_) {
    if (points_into(name, old_text)) stale.push_back(name);
  }
  for (std::string_view name : stale) {
    auto entry = enum_values_.extract(name);
    for (const Symbol* value : entry.mapped()) {
      if (value->source == id) entry.key() = value->name;
    }
    enum_values_.insert(std::move(entry));
  }
}

// What index_source() reported for this file: its global names another project file declared first.
void ProjectModel::report_duplicate_globals(Source& source) {
  for (const Symbol* symbol : source.symbols.top_level) {
    if (symbol->name.empty() || symbol->kind == SymbolKind::Configuration) continue;
    auto found = globals_.find(symbol->name);
    if (found == globals_.end() || found->second == symbol) continue;
    if (is_duplicate_global(*found->second, *symbol)) {
      source.link_diagnostics.push_back(duplicate_global_diagnostic(*symbol, *sources_[found->second->source]));
    }
  }
}

}  // namespace rung::check
