#include "checker/project_model.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <filesystem>

#include "checker/constant/const_eval.hpp"
#include "checker/semantic/address_checker.hpp"
#include "checker/semantic/configuration_checker.hpp"
#include "checker/semantic/recursion_checker.hpp"
#include "parser/diagnostic_codes.hpp"

namespace rung::check {
namespace {

constexpr int kMaxInheritanceDepth = 32;  // cuts EXTENDS cycles (reported by the POU checks)

TypeKind named_kind_of(const Symbol& symbol) {
  if (symbol.kind != SymbolKind::DataType) return TypeKind::Pou;
  const std::string_view kind = symbol.node.kind();
  if (kind == "struct_type") return TypeKind::Struct;
  if (kind == "enum_type") return TypeKind::Enum;
  if (kind == "union_type") return TypeKind::Union;
  return TypeKind::Alias;
}

// The variable declared by the first name of `variable`'s declaration (`a` of `a, b : T`); the
// variable itself when it is the first, nullptr when its owner does not know the name.
Symbol* first_declared(const Symbol& variable) {
  const std::vector<SyntaxNode> names = variable.node.children_by_field("name");
  if (names.empty() || !variable.owner) return nullptr;
  Symbol* first = variable.owner->own_member(names.front().text());
  return first && first->node == variable.node ? first : nullptr;
}

// The generic parameters of the FUNCTION a name is used in: FUNCTION F<T : ANY_NUM>. Only a
// FUNCTION has them (grammar field type_parameters); asking other scopes would walk every child
// of every GVL, STRUCT and FB for each type name, which made linking quadratic.
SyntaxNode generic_parameters_of(const Symbol* scope) {
  for (const Symbol* s = scope; s; s = s->owner) {
    if (s->kind == SymbolKind::Function && s->node) return s->node.child_by_field("type_parameters");
  }
  return {};
}

// A plain file's global list is named after the file (CODESYS exports GVL.st for a list called
// GVL). A file name that cannot be an identifier (057_example.st, untitled-1) could never be
// written as a qualifier: such a list gets CODESYS's default name for a new list, GVL.
std::string gvl_name_for(const std::string& path) {
  std::string stem = std::filesystem::path(path).stem().string();
  const bool identifier = !stem.empty() && !std::isdigit(static_cast<unsigned char>(stem.front())) &&
                          std::all_of(stem.begin(), stem.end(),
                                      [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
  return identifier ? stem : std::string("GVL");
}

}  // namespace

// Two project files declaring the same POU, type or global name (GVLs may share a name: CODESYS
// merges lists of one name).
bool is_duplicate_global(const Symbol& first, const Symbol& again) {
  return !first.has(kLibrary) && !again.has(kLibrary) && first.source != again.source &&
         !(first.kind == SymbolKind::GlobalList && again.kind == SymbolKind::GlobalList);
}

Diagnostic duplicate_global_diagnostic(const Symbol& again, const Source& first_source) {
  return make_diagnostic(codes::kDuplicateDeclaration,
                         fmt::format("'{}' is already declared in {}", again.name, first_source.document->path()),
                         again.name_range, "POU, type and global list names must be unique in a project");
}

namespace {

thread_local int constant_depth = 0;  // guards CONSTANT a := b; b := a; cycles

}  // namespace

ProjectModel::ProjectModel(const Profile& profile)
    : profile_(profile),
      types_(std::make_unique<TypeArena>()),
      address_table_(std::make_unique<AddressTable>()),
      configuration_table_(std::make_unique<ConfigurationTable>()),
      recursion_index_(std::make_unique<RecursionIndex>()) {}
ProjectModel::~ProjectModel() = default;

namespace {

// Revisions of sources and links, unique in the process.
uint64_t next_source_revision() {
  static std::atomic<uint64_t> last{0};
  return ++last;
}

}  // namespace

SourceId ProjectModel::add_source(std::unique_ptr<Document> document, std::string library_name) {
  const SourceId id = static_cast<SourceId>(sources_.size());
  FileSymbols symbols = collect_file_symbols(id, *document, !library_name.empty(), "");
  return add_source(std::move(document), std::move(library_name), std::move(symbols));
}

SourceId ProjectModel::add_source(std::unique_ptr<Document> document, std::string library_name, FileSymbols symbols) {
  const SourceId id = static_cast<SourceId>(sources_.size());
  auto source = std::make_unique<Source>();
  source->revision = next_source_revision();
  source->library = !library_name.empty();
  source->library_name = std::move(library_name);
  const std::string stem = gvl_name_for(document->path());
  source->document = std::move(document);
  source->symbols = std::move(symbols);
  // A plain file's GVL is named after the file (CODESYS exports GVL.st for a list called GVL).
  // The name must outlive the symbols: keep it in the document-owned string below.
  sources_.push_back(std::move(source));
  Source& added = *sources_.back();
  if (!added.symbols.global_lists.empty()) {
    added.gvl_name_storage = stem;
    for (Symbol* list : added.symbols.global_lists) {
      if (list->name.empty()) list->name = added.gvl_name_storage;
    }
  }
  return id;
}

ProjectModel::SourceUpdate ProjectModel::update_source(SourceId id, std::unique_ptr<Document> document) {
  Source& source = *sources_[id];
  source.revision = next_source_revision();
  FileSymbols fresh = collect_file_symbols(id, *document, source.library, "");
  if (relink_bodies_only(source, document, fresh)) return {false, {id}};
  if (auto affected = relink_interface(source, document, fresh)) {
    link_revision_ = next_source_revision();  // other files' resolutions changed
    return {false, std::move(*affected)};
  }
  // The old symbols are gone: the caller must link() again (other files' types point at them).
  install_symbols(source, std::move(document), std::move(fresh));
  return {true, {}};
}

void ProjectModel::install_symbols(Source& source, std::unique_ptr<Document> document, FileSymbols fresh) {
  const std::string stem = gvl_name_for(document->path());
  source.document = std::move(document);
  source.symbols = std::move(fresh);
  // The name views this string: reassign it only when it changes (a retired GVL may still view it).
  if (source.gvl_name_storage != stem) source.gvl_name_storage = stem;
  for (Symbol* list : source.symbols.global_lists) {
    if (list->name.empty()) list->name = source.gvl_name_storage;
  }
}

std::optional<SourceId> ProjectModel::find_source(std::string_view path) const {
  for (SourceId id = 0; id < sources_.size(); ++id) {
    if (sources_[id]->document->path() == path) return id;
  }
  return std::nullopt;
}

void ProjectModel::link() {
  link_revision_ = next_source_revision();
  named_types_.clear();
  enum_numbers_.clear();
  types_ = std::make_unique<TypeArena>();
  for (auto& source : sources_) source->link_diagnostics.clear();
  index_all_sources(true);
  retired_.clear();  // nothing points at them any more: the indexes and types start over
  // A second link() (an editor change, conditional compilation) starts over: the types resolved by
  // the previous one live in the arena just replaced.
  for (auto& source : sources_) {
    for (Symbol& symbol : source->symbols.storage) {
      symbol.type = nullptr;
      symbol.result_type = nullptr;
    }
  }
  for (auto& source : sources_) {
    resolve_declarations(*source);
  }
  address_table_ = std::make_unique<AddressTable>(build_address_table(*this));
  configuration_table_ = std::make_unique<ConfigurationTable>(build_configuration_table(*this));
  recursion_current_.store(false, std::memory_order_release);  // rebuilt when first asked for
}

const RecursionIndex& ProjectModel::recursion_index() const {
  if (!recursion_current_.load(std::memory_order_acquire)) {
    std::lock_guard lock(recursion_mutex_);
    if (!recursion_current_.load(std::memory_order_relaxed)) {
      recursion_index_->rebuild(*this);
      recursion_current_.store(true, std::memory_order_release);
    }
  }
  return *recursion_index_;
}

void ProjectModel::index_all_sources(bool report_duplicates) {
  globals_.clear();
  global_variables_.clear();
  enum_values_.clear();
  global_lists_.clear();
  qualified_only_enums_.clear();
  libraries_.clear();
  // Project files first, so their declarations shadow library stubs of the same name.
  for (const bool library : {false, true}) {
    for (auto& source : sources_) {
      if (source->library == library) index_source(*source, report_duplicates);
    }
  }
}

void ProjectModel::index_source(Source& source, bool report_duplicates) {
  for (Symbol* symbol : source.symbols.top_level) {
    if (symbol->name.empty()) continue;
    if (source.library) libraries_[source.library_name].emplace(symbol->name, symbol);
    // A compiler namespace (__SYSTEM) is reached only through its prefix: __SYSTEM.TYPE_CLASS.
    if (source.library && source.library_name.starts_with("__")) continue;
    if (symbol->kind == SymbolKind::Configuration) continue;
    auto [it, inserted] = globals_.emplace(symbol->name, symbol);
    if (!inserted && it->second != symbol) {
      const Symbol* first = it->second;
      const bool first_library = first->has(kLibrary);
      if (first_library && !source.library) {
        it->second = symbol;  // project shadows library (re-indexing after an edit)
      } else if (report_duplicates && is_duplicate_global(*first, *symbol)) {
        source.link_diagnostics.push_back(duplicate_global_diagnostic(*symbol, *sources_[first->source]));
      }
    }
    if (symbol->kind == SymbolKind::GlobalList) {
      global_lists_.push_back(symbol);
      for (Symbol* variable : symbol->ordered) {
        if (!symbol->has(kQualifiedOnly) && !variable->name.empty())
          global_variables_.emplace(variable->name, variable);
      }
    }
    if (symbol->kind == SymbolKind::DataType && named_kind_of(*symbol) == TypeKind::Enum &&
        !symbol->has(kQualifiedOnly)) {
      for (Symbol* value : symbol->ordered) {
        if (value->kind == SymbolKind::EnumValue) enum_values_[value->name].push_back(value);
      }
    }
    if (symbol->kind == SymbolKind::DataType && named_kind_of(*symbol) == TypeKind::Enum &&
        symbol->has(kQualifiedOnly)) {
      qualified_only_enums_.push_back(symbol);
    }
  }
}

void ProjectModel::resolve_declarations(Source& source) {
  std::vector<Diagnostic>& diagnostics = source.link_diagnostics;
  std::vector<Diagnostic> discarded;
  std::vector<Diagnostic>& sink = source.library ? discarded : diagnostics;
  for (Symbol& symbol : source.symbols.storage) resolve_symbol(symbol, sink);
}

const Type* ProjectModel::named_type_of(const Symbol* symbol) const {
  auto found = named_types_.find(symbol);
  return found == named_types_.end() ? nullptr : found->second;
}

void ProjectModel::resolve_symbol(Symbol& symbol, std::vector<Diagnostic>& diagnostics) {
  switch (symbol.kind) {
    case SymbolKind::Variable:
      if (!symbol.type) {
        // `a, b : (X, Y)` declares one implicit enumeration: b takes a's type.
        Symbol* first = symbol.type_node && symbol.type_node.kind() == "enum_type" ? first_declared(symbol) : nullptr;
        if (first && first != &symbol) {
          if (!first->type) resolve_symbol(*first, diagnostics);
          symbol.type = first->type;
        } else {
          symbol.type =
              symbol.type_node ? resolve_type(symbol.type_node, symbol.owner, &diagnostics) : types_->unknown();
        }
      }
      if (!symbol.ordered.empty()) compute_enum_values(symbol);  // an implicit enumeration's values
      break;
    case SymbolKind::DataType: {
      const Type* type = type_of(&symbol);
      Type* mutable_type = const_cast<Type*>(type);  // filled once, here, before anyone reads it
      if (type->kind == TypeKind::Alias && !type->element && symbol.type_node) {
        mutable_type->element = resolve_type(symbol.type_node, &symbol, &diagnostics);
        mutable_type->bits = underlying(type)->bits;
      } else if (type->kind == TypeKind::Enum && !type->element) {
        SyntaxNode base = symbol.node.child_by_field("base");
        mutable_type->element = base ? resolve_type(base, &symbol, &diagnostics) : types_->elementary("INT");
        mutable_type->bits = mutable_type->element->bits;
        compute_enum_values(symbol);
      }
      resolve_bases(symbol, diagnostics);
      break;
    }
    case SymbolKind::EnumValue:
      // The owner (an enum type, or the variable of an implicit enumeration) is resolved first:
      // it was declared, and so created, before its values.
      symbol.type = symbol.owner ? type_of(symbol.owner) : types_->unknown();
      break;
    case SymbolKind::Program:
    case SymbolKind::Function:
    case SymbolKind::FunctionBlock:
    case SymbolKind::Class:
    case SymbolKind::Interface:
    case SymbolKind::Method:
    case SymbolKind::Property:
    case SymbolKind::Action:
      if (!symbol.result_type) {
        symbol.result_type = symbol.type_node ? resolve_type(symbol.type_node, &symbol, &diagnostics)
                             : symbol.kind == SymbolKind::Function && profile_.function_result_defaults_to_bool
                                 ? types_->elementary("BOOL")  // OpenPCS: a FUNCTION without result type is BOOL
                                 : types_->void_type();
      }
      symbol.type = type_of(&symbol);
      resolve_bases(symbol, diagnostics);
      break;
    default: break;
  }
}

void ProjectModel::resolve_bases(Symbol& symbol, std::vector<Diagnostic>& diagnostics) {
  symbol.bases.clear();
  symbol.interfaces.clear();
  symbol.base = nullptr;
  for (SyntaxNode node : symbol.base_nodes) {
    const Symbol* target = resolve_type_symbol(node, &symbol, &diagnostics);
    if (target && target != &symbol) symbol.bases.push_back(target);
  }
  if (!symbol.bases.empty()) symbol.base = symbol.bases.front();
  for (SyntaxNode node : symbol.interface_nodes) {
    if (const Symbol* target = resolve_type_symbol(node, &symbol, &diagnostics)) symbol.interfaces.push_back(target);
  }
}

const Symbol* ProjectModel::resolve_type_symbol(SyntaxNode name, const Symbol* scope,
                                                std::vector<Diagnostic>* diagnostics) const {
  const Type* type = resolve_type_name(name, scope, diagnostics);
  return type ? type->declaration : nullptr;
}

const Type* ProjectModel::type_of(const Symbol* symbol) const {
  if (!symbol) return types_->unknown();
  if (symbol->kind == SymbolKind::Variable || symbol->kind == SymbolKind::EnumValue) {
    return symbol->type ? symbol->type : types_->unknown();
  }
  if (symbol->kind != SymbolKind::DataType && (!is_pou_kind(symbol->kind) || symbol->kind == SymbolKind::Transition)) {
    return types_->unknown();
  }
  if (const Type* known = named_type_of(symbol)) return known;
  // Named types are created here during link() (resolve_symbol visits every data type and POU),
  // never later, so the parallel body checks only read named_types_.
  auto* self = const_cast<ProjectModel*>(this);
  Type* type = self->types_->make_named(named_kind_of(*symbol), std::string(symbol->name), symbol);
  self->named_types_.emplace(symbol, type);
  return type;
}

const Type* ProjectModel::resolve_type(SyntaxNode spec, const Symbol* scope, std::vector<Diagnostic>* diagnostics) {
  if (!spec) return types_->unknown();
  const std::string_view kind = spec.kind();
  if (kind == "type_name" || kind == "identifier" || kind == "qualified_name") {
    return resolve_type_name(spec, scope, diagnostics);
  }
  if (kind == "string_type") {
    const bool wide = names_equal(spec.text().substr(0, 7), "WSTRING");
    uint32_t length = profile_.default_string_length;
    if (SyntaxNode length_node = spec.child_by_field("length")) {
      auto value = constant_value(length_node, scope);
      if (value && value->is_integer() && value->integer > 0 && value->integer < (1 << 20)) {
        length = static_cast<uint32_t>(value->integer);
      } else if (diagnostics && !value && length_node.kind() != "member_expression" &&
                 !(length_node.kind() == "identifier" && !lookup(scope, length_node.text()))) {
        diagnostics->push_back(make_diagnostic(codes::kNotConstant,
                                               "the length of a STRING must be a constant expression",
                                               length_node.range(), "use a literal or a VAR CONSTANT"));
      }
    }
    return types_->string_type(wide, length);
  }
  if (kind == "array_type") {
    std::vector<ArrayDimension> dimensions;
    for (uint32_t i = 0; i < spec.named_child_count(); ++i) {
      SyntaxNode child = spec.named_child(i);
      if (child.kind() == "wildcard") {
        dimensions.push_back({.open = true});
      } else if (child.kind() == "range") {
        ArrayDimension dimension;
        auto lower = constant_value(child.child_by_field("lower"), scope);
        auto upper = constant_value(child.child_by_field("upper"), scope);
        if (lower && upper && lower->is_integer() && upper->is_integer()) {
          dimension.lower = static_cast<int64_t>(lower->integer);
          dimension.upper = static_cast<int64_t>(upper->integer);
        } else {
          dimension.known = false;
        }
        dimensions.push_back(dimension);
      }
    }
    const Type* element = resolve_type(spec.child_by_field("element"), scope, diagnostics);
    return types_->array_of(element, std::move(dimensions));
  }
  if (kind == "pointer_type") {
    SyntaxNode target = spec.child_by_field("type");
    return types_->pointer_to(target ? resolve_type(target, scope, diagnostics) : types_->unknown());
  }
  if (kind == "reference_type") {
    return types_->reference_to(resolve_type(spec.child_by_field("type"), scope, diagnostics));
  }
  if (kind == "subrange_type") {
    const Type* base = resolve_type(spec.child_by_field("base"), scope, diagnostics);
    SyntaxNode range = spec.child_by_field("range");
    auto lower = range ? constant_value(range.child_by_field("lower"), scope) : std::nullopt;
    auto upper = range ? constant_value(range.child_by_field("upper"), scope) : std::nullopt;
    if (!lower || !upper || !lower->is_integer() || !upper->is_integer()) return base;
    return types_->subrange(base, static_cast<int64_t>(lower->integer), static_cast<int64_t>(upper->integer));
  }
  if (kind == "struct_type" || kind == "enum_type") {
    // An inline STRUCT or implicit enum in a declaration: an anonymous named type.
    Type* type = types_->make_named(kind == "struct_type" ? TypeKind::Struct : TypeKind::Enum, "(anonymous)", nullptr);
    if (type->kind == TypeKind::Enum) {
      SyntaxNode base = spec.child_by_field("base");
      type->element = base ? resolve_type(base, scope, diagnostics) : types_->elementary("INT");
      type->bits = type->element->bits;
    }
    return type;
  }
  return types_->unknown();  // generic_type, variadic_type: not checked
}

const Type* ProjectModel::resolve_type_name(SyntaxNode name, const Symbol* scope,
                                            std::vector<Diagnostic>* diagnostics) const {
  const std::string_view text = name.text();
  // Dotted names: Library.Type, Namespace.Type, GVL-less qualified types (__SYSTEM.TYPE_CLASS).
  if (const size_t dot = text.rfind('.'); dot != std::string_view::npos) {
    const std::string_view qualifier = text.substr(0, text.find('.'));
    const std::string_view last = text.substr(dot + 1);
    if (is_library_namespace(qualifier)) {
      if (const Symbol* symbol = find_in_library(qualifier, last)) return type_of(symbol);
    }
    if (const Symbol* symbol = find_global(last); symbol && symbol->kind != SymbolKind::GlobalList)
      return type_of(symbol);
    if (diagnostics) {
      diagnostics->push_back(make_diagnostic(codes::kUnknownLibraryName, fmt::format("unknown type '{}'", text),
                                             name.range(),
                                             "if it comes from a vendor library, add that library's declarations as "
                                             "stubs (the 'libraries' list under [project] in rung.toml)"));
    }
    return types_->unknown();
  }
  if (SyntaxNode parameters = generic_parameters_of(scope)) {
    for (SyntaxNode parameter : parameters.children_of_kind("generic_parameter")) {
      SyntaxNode parameter_name = parameter.child_by_field("name");
      if (parameter_name && names_equal(parameter_name.text(), text)) {
        SyntaxNode constraint = parameter.child_by_field("constraint");
        const Type* generic = constraint ? types_->generic(constraint.text()) : nullptr;
        return generic ? generic : types_->generic(GenericKind::Any);
      }
    }
  }
  if (const Type* elementary = types_->elementary(text, false)) return elementary;
  if (const Type* generic = types_->generic(text)) return generic;
  if (const Symbol* local = find_local_type(scope, text)) return type_of(local);
  if (const Symbol* symbol = find_global(text); symbol && symbol->kind != SymbolKind::GlobalList) {
    return type_of(symbol);
  }
  if (const Type* vendor = types_->elementary(text, true)) return vendor;
  if (diagnostics) {
    std::vector<std::string_view> candidates = global_type_names();
    const std::string_view suggestion = closest_name(text, candidates);
    diagnostics->push_back(
        make_diagnostic(codes::kUnknownLibraryName, fmt::format("unknown type '{}'", text), name.range(),
                        suggestion.empty() ? "declare it, or if it comes from a vendor library, add that library's "
                                             "stubs (the 'libraries' list under [project] in rung.toml)"
                                           : fmt::format("did you mean '{}'?", suggestion)));
  }
  return types_->unknown();
}

std::vector<std::string_view> ProjectModel::global_type_names() const {
  std::vector<std::string_view> names;
  for (const auto& [name, symbol] : globals_) {
    if (symbol->kind == SymbolKind::DataType || symbol->kind == SymbolKind::FunctionBlock ||
        symbol->kind == SymbolKind::Interface || symbol->kind == SymbolKind::Class) {
      names.push_back(name);
    }
  }
  for (std::string_view name :
       {"BOOL",  "BYTE", "WORD",  "DWORD", "LWORD", "SINT", "INT", "DINT", "LINT",   "USINT",   "UINT", "UDINT",
        "ULINT", "REAL", "LREAL", "TIME",  "LTIME", "DATE", "TOD", "DT",   "STRING", "WSTRING", "CHAR", "WCHAR"}) {
    names.push_back(name);
  }
  std::sort(names.begin(), names.end());
  return names;
}

void ProjectModel::compute_enum_values(const Symbol& enum_symbol) {
  __int128 next = 0;
  for (const Symbol* value : enum_symbol.ordered) {
    if (value->kind != SymbolKind::EnumValue) continue;
    if (SyntaxNode written = value->node.child_by_field("value")) {
      auto constant = constant_value(written, &enum_symbol);
      if (constant && (constant->is_integer() || constant->kind == ConstValue::Kind::Bool)) next = constant->integer;
    }
    enum_numbers_[value] = next;
    ++next;
  }
}

std::optional<__int128> ProjectModel::enum_value(const Symbol* value) const {
  auto found = enum_numbers_.find(value);
  if (found == enum_numbers_.end()) return std::nullopt;
  return found->second;
}

std::optional<ConstValue> ProjectModel::constant_value(SyntaxNode expression, const Symbol* scope) const {
  if (constant_depth > 32) return std::nullopt;
  ++constant_depth;
  ConstEvaluator evaluator([this, scope](SyntaxNode name) -> std::optional<ConstValue> {
    const Symbol* symbol = nullptr;
    if (name.kind() == "member_expression") {
      SyntaxNode object = name.child_by_field("object");
      SyntaxNode member = name.child_by_field("member");
      if (!object || !member || object.kind() != "identifier") return std::nullopt;
      const Symbol* container = lookup(scope, object.text());
      if (!container) return std::nullopt;
      symbol = find_member(container, member.text());
    } else {
      symbol = lookup(scope, name.text());
    }
    if (!symbol) return std::nullopt;
    if (symbol->kind == SymbolKind::EnumValue) {
      if (auto number = enum_value(symbol)) return ConstValue::of_integer(*number);
      return std::nullopt;
    }
    if (symbol->kind == SymbolKind::Variable && symbol->has(kConstant)) {
      SyntaxNode initial = symbol->node.child_by_field("value");
      if (initial) return constant_value(initial, symbol->owner);
    }
    return std::nullopt;
  });
  auto value = evaluator.evaluate(expression);
  --constant_depth;
  return value;
}

const Symbol* ProjectModel::find_global(std::string_view name) const {
  auto found = globals_.find(name);
  return found == globals_.end() ? nullptr : found->second;
}

const Symbol* ProjectModel::find_global_variable(std::string_view name) const {
  auto found = global_variables_.find(name);
  return found == global_variables_.end() ? nullptr : found->second;
}

const std::vector<const Symbol*>* ProjectModel::find_enum_values(std::string_view name) const {
  auto found = enum_values_.find(name);
  return found == enum_values_.end() ? nullptr : &found->second;
}

const Symbol* ProjectModel::find_qualified_only(std::string_view name) const {
  // Only asked for names nothing else declares (the error path), so a scan is cheap enough.
  for (const std::vector<const Symbol*>* scopes : {&global_lists_, &qualified_only_enums_}) {
    for (const Symbol* scope : *scopes) {
      if (!scope->has(kQualifiedOnly)) continue;
      if (const Symbol* member = scope->own_member(name)) return member;
    }
  }
  return nullptr;
}

const Symbol* ProjectModel::find_linked_global(std::string_view name) const {
  if (const Symbol* variable = find_global_variable(name)) return variable;
  for (const Symbol* list : global_lists_) {
    if (const Symbol* variable = list->own_member(name); variable && variable->kind == SymbolKind::Variable) {
      return variable;
    }
  }
  return nullptr;
}

const Symbol* ProjectModel::find_in_global_lists(std::string_view list, std::string_view name) const {
  for (const Symbol* candidate : global_lists_) {
    if (!names_equal(candidate->name, list)) continue;
    if (const Symbol* variable = candidate->own_member(name)) return variable;
  }
  return nullptr;
}

bool ProjectModel::is_library_namespace(std::string_view name) const {
  return libraries_.contains(name);
}

const Symbol* ProjectModel::find_in_library(std::string_view library, std::string_view name) const {
  auto found = libraries_.find(library);
  if (found == libraries_.end()) return nullptr;
  auto symbol = found->second.find(name);
  return symbol == found->second.end() ? nullptr : symbol->second;
}

const Symbol* ProjectModel::find_member(const Symbol* container, std::string_view name) const {
  for (int depth = 0; container && depth < kMaxInheritanceDepth; ++depth) {
    if (const Symbol* member = container->own_member(name)) return member;
    if (container->bases.size() > 1) {
      for (const Symbol* base : container->bases) {
        if (const Symbol* member = find_member(base, name)) return member;
      }
      return nullptr;
    }
    container = container->base;
  }
  return nullptr;
}

const Symbol* ProjectModel::lookup(const Symbol* scope, std::string_view name) const {
  for (const Symbol* s = scope; s; s = s->owner) {
    if (names_equal(s->name, name) && is_pou_kind(s->kind)) return s;  // the function's own result
    if (const Symbol* member = find_member(s, name)) return member;
  }
  if (const Symbol* global = lookup_global(name)) return global;
  return find_local_enum_value(scope, name);
}

const Symbol* ProjectModel::lookup_global(std::string_view name) const {
  if (const Symbol* variable = find_global_variable(name)) return variable;
  if (const Symbol* global = find_global(name)) return global;
  if (const auto* values = find_enum_values(name); values && !values->empty()) return values->front();
  return nullptr;
}

const Symbol* ProjectModel::find_local_type(const Symbol* scope, std::string_view name) const {
  for (const Symbol* s = scope; s; s = s->owner) {
    if (!is_pou_kind(s->kind)) continue;
    if (const Symbol* member = s->own_member(name); member && member->kind == SymbolKind::DataType) return member;
  }
  return nullptr;
}

const Symbol* ProjectModel::find_local_enum_value(const Symbol* scope, std::string_view name) const {
  // Only reached when nothing else has the name: POU-local types are rare (OpenPCS), and this
  // walks every member of the enclosing POUs.
  for (const Symbol* s = scope; s; s = s->owner) {
    if (!is_pou_kind(s->kind)) continue;
    for (const Symbol* member : s->ordered) {
      // Local enum types, and variables declared with an implicit enumeration (their values).
      const bool enum_holder = (member->kind == SymbolKind::DataType && !member->has(kQualifiedOnly)) ||
                               (member->kind == SymbolKind::Variable && !member->members.empty());
      if (!enum_holder) continue;
      if (const Symbol* value = member->own_member(name); value && value->kind == SymbolKind::EnumValue) return value;
    }
  }
  return nullptr;
}

bool ProjectModel::has_unresolved_base(const Symbol* scope) const {
  for (const Symbol* s = scope; s; s = s->owner) {
    int depth = 0;
    for (const Symbol* c = s; c && depth < kMaxInheritanceDepth; c = c->base, ++depth) {
      if (c->bases.size() < c->base_nodes.size()) return true;
    }
  }
  return false;
}

std::vector<std::string_view> ProjectModel::visible_names(const Symbol* scope) const {
  std::vector<std::string_view> names;
  for (const Symbol* s = scope; s; s = s->owner) {
    int depth = 0;
    for (const Symbol* c = s; c && depth < kMaxInheritanceDepth; c = c->base, ++depth) {
      for (const Symbol* member : c->ordered) names.push_back(member->name);
    }
  }
  for (const auto& [name, symbol] : global_variables_) names.push_back(name);
  for (const auto& [name, symbol] : globals_) names.push_back(name);
  for (const auto& [name, values] : enum_values_) names.push_back(name);
  std::sort(names.begin(), names.end(),
            [](std::string_view a, std::string_view b) { return upper_name(a) < upper_name(b); });
  names.erase(
      std::unique(names.begin(), names.end(), [](std::string_view a, std::string_view b) { return names_equal(a, b); }),
      names.end());
  return names;
}

std::vector<const Symbol*> ProjectModel::top_level_symbols(SourceId id) const {
  const auto& top = sources_[id]->symbols.top_level;
  return {top.begin(), top.end()};
}

}  // namespace rung::check
