#include "checker/query/name_classes.hpp"

#include <algorithm>
#include <string>
#include <unordered_map>

#include "checker/query/position.hpp"
#include "checker/query/resolve.hpp"

namespace rung::check::query {
namespace {

bool is_instance_type(const Type* type) {
  if (!type) return false;
  type = underlying(type);
  if (type->kind == TypeKind::Reference && type->element) type = underlying(type->element);
  if (type->kind != TypeKind::Pou || !type->declaration) return false;
  const SymbolKind kind = type->declaration->kind;
  return kind == SymbolKind::FunctionBlock || kind == SymbolKind::Class || kind == SymbolKind::Program ||
         kind == SymbolKind::Interface;
}

NameClass variable_class(const Symbol& variable) {
  if (variable.owner && variable.owner->kind == SymbolKind::DataType) return NameClass::Field;
  if (variable.owner && variable.owner->kind == SymbolKind::GlobalList) return NameClass::Global;
  switch (variable.section) {
    case ast::VarSection::Input: return NameClass::Input;
    case ast::VarSection::Output: return NameClass::Output;
    case ast::VarSection::InOut: return NameClass::InOut;
    case ast::VarSection::Global:
    case ast::VarSection::External: return NameClass::Global;
    default: return NameClass::Local;
  }
}

NameClass data_type_class(const ProjectModel& model, const Symbol& type_symbol) {
  const Type* type = model.type_of(&type_symbol);
  switch (type ? type->kind : TypeKind::Unknown) {
    case TypeKind::Struct:
    case TypeKind::Union: return NameClass::Struct;
    case TypeKind::Enum: return NameClass::Enum;
    default: return NameClass::Alias;
  }
}

std::optional<NameClass> class_of(const ProjectModel& model, const Symbol& symbol) {
  switch (symbol.kind) {
    case SymbolKind::Program: return NameClass::Program;
    case SymbolKind::FunctionBlock:
    case SymbolKind::Class: return NameClass::FunctionBlock;
    case SymbolKind::Interface: return NameClass::Interface;
    case SymbolKind::Function: return NameClass::Function;
    case SymbolKind::Method: return NameClass::Method;
    case SymbolKind::Action: return NameClass::Action;
    case SymbolKind::Property: return NameClass::Property;
    case SymbolKind::DataType: return data_type_class(model, symbol);
    case SymbolKind::Variable: return variable_class(symbol);
    case SymbolKind::EnumValue: return NameClass::EnumValue;
    case SymbolKind::GlobalList:
    case SymbolKind::Namespace: return NameClass::Namespace;
    case SymbolKind::ProgramInstance: return NameClass::Local;
    default: return std::nullopt;  // transitions, configurations, resources, tasks, steps
  }
}

uint16_t flags_of(const ProjectModel& model, const Symbol& symbol) {
  uint16_t flags = 0;
  if (symbol.has(kConstant) || symbol.kind == SymbolKind::EnumValue) flags |= kNameConstant;
  if (symbol.has(kLibrary) || (symbol.source < model.source_count() && model.source(symbol.source).library)) {
    flags |= kNameLibrary;
  }
  if (symbol.has(kObsolete)) flags |= kNameDeprecated;
  if (symbol.has(kAbstract)) flags |= kNameAbstract;
  if (symbol.kind == SymbolKind::Variable && symbol.section == ast::VarSection::Stat) flags |= kNameStatic;
  if (symbol.kind == SymbolKind::ProgramInstance ||
      (symbol.kind == SymbolKind::Variable && is_instance_type(model.type_of(&symbol)))) {
    flags |= kNameInstance;
  }
  return flags;
}

// Names inside these never refer to a declaration: not worth resolving.
bool holds_no_names(std::string_view kind) {
  return kind == "comment" || kind == "pragma" || kind == "string_literal" || kind == "integer_literal" ||
         kind == "real_literal" || kind == "time_literal" || kind == "date_literal" || kind == "time_of_day_literal" ||
         kind == "date_and_time_literal" || kind == "direct_variable";
}

// The file range of a name of the tree text; nullopt when a container reader inserted it (it has
// no place in the file the editor shows).
std::optional<TextRange> file_range_of(const Document& document, SyntaxNode name) {
  const TextRange range{document.file_offset_of(name.begin()), document.file_end_offset_of(name.end())};
  if (!document.container()) return range;
  const std::string_view file = document.file_text();
  if (range.end < range.begin || range.end > file.size()) return std::nullopt;
  if (file.substr(range.begin, range.end - range.begin) != name.text()) return std::nullopt;
  return range;
}

// Walks a file's tree once with a cursor, which knows each node's parent and field for free
// (SyntaxNode::parent() searches down from the root in tree-sitter 0.20), and resolves each name
// with resolve_name. A file names the same things over and over: answers that cannot differ are
// reused (see cache_key).
class NameWalker {
 public:
  NameWalker(const ProjectModel& model, SourceId source, TextRange file_range, const std::function<bool()>& cancelled)
      : model_(model),
        source_(source),
        document_(*model.source(source).document),
        file_range_(file_range),
        cancelled_(cancelled) {}

  std::vector<ClassifiedName> run() {
    const SyntaxTree* tree = document_.tree();
    if (!tree || tree->aborted()) return {};
    // A plain file's range is the tree's own; a container's tree text is in another order than
    // the file, so its whole tree is walked and the names filtered by their place in the file.
    tree_range_ = document_.container() ? TextRange{0, static_cast<uint32_t>(tree->text().size())} : file_range_;
    walk(tree->root());
    std::stable_sort(names_.begin(), names_.end(),
                     [](const ClassifiedName& a, const ClassifiedName& b) { return a.range.begin < b.range.begin; });
    return std::move(names_);
  }

 private:
  void walk(SyntaxNode root) {
    const NodeTable* table = root.table();
    const uint32_t stop = root.subtree_end();
    for (uint32_t i = root.index(); i < stop && !stop_;) {
      const SyntaxNode node(table, i);
      while (!ancestors_.empty() && ancestors_.back().subtree_end() <= i) ancestors_.pop_back();
      if (enter(node, NodeTable::field_name(node.field_id())) && node.subtree_end() > i + 1) {
        ancestors_.push_back(node);
        ++i;
      } else {
        i = node.subtree_end();
      }
    }
  }

  // Whether to walk the node's children.
  bool enter(SyntaxNode node, std::string_view field) {
    if (node.end() <= tree_range_.begin || node.begin() >= tree_range_.end) return false;
    const std::string_view kind = node.kind();
    if (holds_no_names(kind)) return false;
    if (kind != "identifier" && kind != "il_operator") return true;
    if (node.begin() >= tree_range_.begin) visit_name(node, field);
    return false;
  }

  void visit_name(SyntaxNode name, std::string_view field) {
    const SyntaxNode parent = ancestors_.empty() ? SyntaxNode() : ancestors_.back();
    const bool is_object = field == "object";
    const SyntaxNode object = last_object_parent_ == parent ? last_object_ : SyntaxNode();
    last_object_ = is_object ? name : SyntaxNode();
    last_object_parent_ = is_object ? parent : SyntaxNode();
    // THIS and SUPER are keywords to the reader, whatever they resolve to.
    if (names_equal(name.text(), "THIS") || names_equal(name.text(), "SUPER")) return;
    if (cancelled_ && ++visited_ % 256 == 0 && cancelled_()) {
      stop_ = true;
      return;
    }
    const std::optional<TextRange> range = file_range_of(document_, name);
    if (!range || range->begin < file_range_.begin || range->begin >= file_range_.end) return;

    const Symbol* scope = scope_of(name);
    const std::optional<std::string> key = cache_key(name, parent, field, object, scope);
    const Symbol* symbol = nullptr;
    if (const auto found = key ? resolved_.find(*key) : resolved_.end(); found != resolved_.end()) {
      symbol = found->second;
    } else {
      symbol = resolve_name(model_, source_, name, scope);
      if (key) resolved_.emplace(*key, symbol);
    }
    if (!symbol) return;
    std::optional<ClassifiedName> classified = classify_symbol(model_, *symbol);
    if (!classified) return;
    classified->range = *range;
    if (symbol->source == source_ && symbol->name_range.begin == name.begin() && symbol->name_range.end == name.end()) {
      classified->flags |= kNameDeclaration;
    }
    names_.push_back(*classified);
  }

  // The scope is the same for every name of one statement list or VAR block (no declaration
  // that opens a scope stands inside one), so scope_at runs once per list, not once per name.
  const Symbol* scope_of(SyntaxNode name) {
    for (auto it = ancestors_.rbegin(); it != ancestors_.rend(); ++it) {
      const std::string_view kind = it->kind();
      if (kind != "statement_list" && kind != "var_block") continue;
      if (*it != anchor_) {
        anchor_ = *it;
        anchor_scope_ = scope_at(model_, source_, name.begin());
      }
      return anchor_scope_;
    }
    return scope_at(model_, source_, name.begin());
  }

  // Names whose resolution depends only on the scope, where the name stands (its parent's kind,
  // its field) and its spelling, get a key; nullopt for the others: declarations and named
  // arguments (their place decides), typed literals, qualified type names, and members of
  // anything but a plain name (obj.member is keyed by both names).
  static std::optional<std::string> cache_key(SyntaxNode name, SyntaxNode parent, std::string_view field,
                                              SyntaxNode object, const Symbol* scope) {
    if (!parent || field == "name") return std::nullopt;
    const std::string_view parent_kind = parent.kind();
    if (parent_kind == "typed_literal") return std::nullopt;
    if (parent_kind == "type_name" && (parent.begin() != name.begin() || parent.end() != name.end())) {
      return std::nullopt;
    }
    if (field == "member" && (!object || object.kind() != "identifier")) return std::nullopt;
    std::string key = std::to_string(reinterpret_cast<uintptr_t>(scope));
    key += '|';
    key += parent_kind;
    key += '|';
    key += field;
    key += '|';
    if (field == "member") {
      key += upper_name(object.text());
      key += '.';
    }
    key += upper_name(name.text());
    return key;
  }

  const ProjectModel& model_;
  SourceId source_;
  const Document& document_;
  TextRange file_range_;
  TextRange tree_range_;
  const std::function<bool()>& cancelled_;
  std::vector<SyntaxNode> ancestors_;  // of the cursor's node, outermost first
  SyntaxNode anchor_;                  // the statement list or VAR block scope_of last looked at
  const Symbol* anchor_scope_ = nullptr;
  SyntaxNode last_object_;  // the `obj` of obj.member, while its member is next
  SyntaxNode last_object_parent_;
  std::unordered_map<std::string, const Symbol*> resolved_;
  std::vector<ClassifiedName> names_;
  size_t visited_ = 0;
  bool stop_ = false;
};

}  // namespace

std::optional<ClassifiedName> classify_symbol(const ProjectModel& model, const Symbol& symbol) {
  const std::optional<NameClass> name_class = class_of(model, symbol);
  if (!name_class) return std::nullopt;
  return ClassifiedName{.name_class = *name_class, .flags = flags_of(model, symbol)};
}

std::vector<ClassifiedName> classify_names(const ProjectModel& model, SourceId source, TextRange file_range,
                                           const std::function<bool()>& cancelled) {
  if (source >= model.source_count()) return {};
  return NameWalker(model, source, file_range, cancelled).run();
}

}  // namespace rung::check::query
