// The language server's common case: an edit inside a body. The file's declarations read the
// same (its interface hash is unchanged), so every other file's links into it stay right: the
// file's Symbol objects are kept, and only what points into the old tree and text is moved to
// the new one. Then this file's declarations are resolved again. A full link() of a 2,000-file
// project takes the better part of a second; this takes about as long as parsing the one file.
#include <fmt/format.h>

#include "checker/project_model.hpp"
#include "checker/semantic/address_checker.hpp"
#include "checker/semantic/configuration_checker.hpp"
#include "checker/semantic/recursion_checker.hpp"

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
