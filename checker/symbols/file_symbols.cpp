#include "checker/symbols/file_symbols.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "parser/diagnostic_codes.hpp"

namespace rung::check {
namespace {

SymbolKind symbol_kind_of(ast::PouKind kind) {
  switch (kind) {
    case ast::PouKind::Program:
      return SymbolKind::Program;
    case ast::PouKind::Function:
      return SymbolKind::Function;
    case ast::PouKind::FunctionBlock:
      return SymbolKind::FunctionBlock;
    case ast::PouKind::Method:
    case ast::PouKind::PropertyAccessor:
      return SymbolKind::Method;
    case ast::PouKind::Property:
      return SymbolKind::Property;
    case ast::PouKind::Interface:
      return SymbolKind::Interface;
    case ast::PouKind::Action:
      return SymbolKind::Action;
    case ast::PouKind::Transition:
      return SymbolKind::Transition;
    case ast::PouKind::Class:
      return SymbolKind::Class;
  }
  return SymbolKind::Program;
}

// Whether a POU is closed by its END_PROGRAM / END_FUNCTION_BLOCK / ... keyword.
bool has_end_keyword(SyntaxNode pou) {
  const uint32_t count = pou.child_count();
  if (count == 0) return false;
  const SyntaxNode last = pou.child(count - 1);
  return !last.is_named() && last.kind().starts_with("END_");
}

uint32_t modifier_flags(const std::vector<std::string_view>& modifiers) {
  uint32_t flags = 0;
  for (std::string_view modifier : modifiers) {
    if (names_equal(modifier, "ABSTRACT")) flags |= kAbstract;
    if (names_equal(modifier, "FINAL")) flags |= kFinal;
    if (names_equal(modifier, "PRIVATE")) flags |= kPrivate;
    if (names_equal(modifier, "PROTECTED")) flags |= kProtected;
    if (names_equal(modifier, "INTERNAL")) flags |= kInternal;
    if (names_equal(modifier, "PUBLIC")) flags |= kPublic;
    if (names_equal(modifier, "OVERRIDE")) flags |= kOverride;
  }
  return flags;
}

uint32_t attribute_flags(const std::vector<Attribute>& attributes) {
  uint32_t flags = 0;
  for (const auto& attribute : attributes) {
    if (attribute.name == "qualified_only") flags |= kQualifiedOnly;
    if (attribute.name == "hide" || attribute.name == "hide_all_locals") flags |= kHide;
    if (attribute.name == "obsolete") flags |= kObsolete;
    if (attribute.name == "rung.extensible") flags |= kExtensible;
    if (attribute.name == "strict") flags |= kStrict;
  }
  return flags;
}

class Collector {
 public:
  Collector(FileSymbols& out, const Document& document, std::string_view gvl_name)
      : out_(out), document_(document), gvl_name_(gvl_name) {}

  void run(SyntaxNode root) {
    const ast::Outline outline = ast::outline(root);
    for (const ast::Pou& pou : outline.pous) {
      out_.top_level.push_back(add_pou(pou, nullptr));
      if (pou.kind() == ast::PouKind::Program) add_program_globals(pou, *out_.top_level.back());
    }
    for (const ast::TypeDeclaration& type : outline.types) out_.top_level.push_back(add_type(type, nullptr));
    for (const ast::VarBlock& block : outline.global_blocks) add_global_block(block);
    for (SyntaxNode configuration : outline.configurations) {
      Symbol& symbol = make(SymbolKind::Configuration, configuration.child_by_field("name"), configuration, nullptr);
      out_.top_level.push_back(&symbol);
      // VAR_GLOBAL of a configuration or resource: globals of the whole project (PLCopen, IEC).
      std::vector<SyntaxNode> stack{configuration};
      while (!stack.empty()) {
        SyntaxNode node = stack.back();
        stack.pop_back();
        for (uint32_t i = 0; i < node.named_child_count(); ++i) {
          SyntaxNode child = node.named_child(i);
          if (child.kind() == "var_block") {
            // VAR_CONFIG entries too: their paths and addresses are checked like declarations.
            const ast::VarSection section = ast::VarBlock(child).section();
            if (section == ast::VarSection::Global || section == ast::VarSection::Config) {
              add_global_block(ast::VarBlock(child));
            }
          } else if (child.kind() == "resource_declaration") {
            stack.push_back(child);
          }
        }
      }
    }
    add_snippet(root);
  }

 private:
  // Manuals, forum posts and scratch files show code without a POU header: VAR ... END_VAR and
  // statements at the top of the file. Such a snippet is checked as the body of an unnamed
  // PROGRAM, which no other file can name.
  void add_snippet(SyntaxNode root) {
    Symbol* snippet = nullptr;
    for (uint32_t i = 0; i < root.named_child_count(); ++i) {
      SyntaxNode child = root.named_child(i);
      const std::string_view kind = child.kind();
      const bool body = kind == "statement_list" || kind == "il_body" || kind == "sfc_network";
      const bool locals = kind == "var_block" && ast::VarBlock(child).section() != ast::VarSection::Global &&
                          ast::VarBlock(child).section() != ast::VarSection::Config;
      if (!body && !locals) continue;
      if (!snippet) {
        snippet = &make(SymbolKind::Program, SyntaxNode(), root, nullptr);
        out_.top_level.push_back(snippet);
      }
      if (locals) add_var_block(*snippet, ast::VarBlock(child));
    }
  }

  Symbol& make(SymbolKind kind, SyntaxNode name_node, SyntaxNode node, Symbol* owner) {
    Symbol& symbol = out_.storage.emplace_back();
    symbol.kind = kind;
    symbol.source = out_.source;
    symbol.node = node;
    symbol.owner = owner;
    if (name_node) {
      symbol.name = name_node.text();
      symbol.name_range = name_node.range();
    } else {
      symbol.name_range = {node.begin(), node.begin()};
    }
    if (out_.library) symbol.flags |= kLibrary;
    return symbol;
  }

  // `b : arrey[0..5] OF INT;` parses as a declaration of type INT after an error, and
  // `x, y : at%I0.0;` as one of type `at`: the type the recovery found is a guess, and checking against it would only add follow-on errors. Such a
  // variable gets the Unknown type.
  static bool type_is_reliable(const ast::VarDeclaration::Parts& parts) {
    return parts.type && !parts.type.has_error() && !parts.error_before_value;
  }

  // Adds `member` to `owner`'s scope; a second declaration of a name is E003 (first one wins).
  void add_member(Symbol& owner, Symbol& member) {
    owner.ordered.push_back(&member);
    if (member.name.empty()) return;
    auto [it, inserted] = owner.members.emplace(member.name, &member);
    if (!inserted && !conditional_between(*it->second, member)) duplicate(member, *it->second);
  }

  // {IF defined(X)} a : INT; {ELSE} a : DINT; {END_IF}: two branches, one declaration each.
  bool conditional_between(const Symbol& first, const Symbol& again) const {
    const std::string& text = document_.tree()->text();
    const uint32_t begin = std::min(first.name_range.end, again.name_range.begin);
    const uint32_t end = std::max(first.name_range.end, again.name_range.begin);
    for (size_t at = text.find('{', begin); at != std::string::npos && at < end; at = text.find('{', at + 1)) {
      size_t i = at + 1;
      while (i < text.size() && (text[i] == ' ' || text[i] == '\t')) ++i;
      const std::string_view word = std::string_view(text).substr(i, 5);
      if (names_equal(word.substr(0, 4), "ELSE") || names_equal(word.substr(0, 5), "ELSIF") ||
          names_equal(word.substr(0, 3), "IF ")) {
        return true;
      }
    }
    return false;
  }

  void duplicate(const Symbol& again, const Symbol& first) {
    out_.diagnostics.push_back(make_diagnostic(codes::kDuplicateDeclaration,
                                               fmt::format("'{}' is declared twice in the same scope", again.name),
                                               again.name_range, "rename or remove one of the declarations",
                                               {{first.name_range, "first declared here"}}));
  }

  Symbol* add_pou(const ast::Pou& pou, Symbol* owner) {
    SyntaxNode name = pou.name_node();
    Symbol& symbol = make(symbol_kind_of(pou.kind()), name, pou.node(), owner);
    if (pou.kind() == ast::PouKind::PropertyAccessor && !name) {
      // GET / SET: named by their keyword
      SyntaxNode keyword = pou.node().child(0);
      symbol.name = keyword ? keyword.text() : std::string_view{};
      symbol.name_range = keyword ? keyword.range() : TextRange{};
    }
    symbol.attributes = attributes_before(pou.node());
    symbol.flags |= modifier_flags(pou.modifiers()) | attribute_flags(symbol.attributes);
    symbol.type_node = pou.return_type();
    symbol.base_nodes = pou.extends();
    symbol.interface_nodes = pou.implements();
    for (const ast::VarBlock& block : pou.var_blocks()) {
      if (block.section() == ast::VarSection::Global && pou.kind() == ast::PouKind::Program && !owner) {
        continue;  // add_program_globals()
      }
      // No POU may declare VAR_CONFIG. After a POU without END_* it starts the next object of
      // text concatenated from CODESYS objects (a POU, then the GVL with the VAR_CONFIG).
      if (block.section() == ast::VarSection::Config && !has_end_keyword(pou.node())) {
        add_global_block(block);
      } else {
        add_var_block(symbol, block);
      }
    }
    for (const ast::Pou& member : pou.members()) {
      Symbol* child = add_pou(member, &symbol);
      add_member(symbol, *child);
    }
    // OpenPCS declares POU-local types among the variable blocks. They are members of the POU:
    // visible only inside it, and in the one namespace of its variables (a variable and a local
    // type of the same name are E003).
    for (const ast::TypeDeclaration& declared : ast::outline(pou.node()).types) {
      add_member(symbol, *add_type(declared, &symbol));
    }
    return &symbol;
  }

  void add_var_block(Symbol& owner, const ast::VarBlock& block) {
    const ast::VarSection section = block.section();
    // One pass over the block's children (VarBlock::has_qualifier() would make one per word).
    uint32_t flags = 0;
    for (SyntaxNode qualifier : block.node().children_of_kind("var_qualifier")) {
      const std::string_view word = qualifier.text();
      if (names_equal(word, "CONSTANT")) flags |= kConstant;
      if (names_equal(word, "RETAIN")) flags |= kRetain;
      if (names_equal(word, "PERSISTENT")) flags |= kPersistent;
    }
    const std::vector<Attribute> block_attributes = attributes_before(block.node());
    const ChildAttributes declared = attributes_of_children(block.node());
    for (const ast::VarDeclaration& declaration : block.declarations()) {
      add_variables(owner, declaration, section, flags, block_attributes, declared);
    }
  }

  void add_variables(Symbol& owner, const ast::VarDeclaration& declaration, ast::VarSection section, uint32_t flags,
                     const std::vector<Attribute>& inherited, const ChildAttributes& declared) {
    const auto own = declared.find(declaration.node().begin());
    std::vector<Attribute> attributes = own == declared.end() ? std::vector<Attribute>{} : own->second;
    for (const auto& attribute : inherited) {
      if (attribute.name == "hide_all_locals") attributes.push_back(attribute);
    }
    const ast::VarDeclaration::Parts parts = declaration.parts();
    const SyntaxNode type = type_is_reliable(parts) ? parts.type : SyntaxNode();
    Symbol* first = nullptr;
    for (SyntaxNode name : parts.names) {
      Symbol& variable = make(SymbolKind::Variable, name, declaration.node(), &owner);
      variable.section = section;
      variable.type_node = type;
      variable.location_node = parts.location;
      variable.attributes = attributes;
      variable.flags |= flags | attribute_flags(attributes);
      if (parts.initial_value) variable.flags |= kHasInitializer;
      add_member(owner, variable);
      if (!first) first = &variable;
    }
    // An implicit enumeration (eState : (WAITING, RUNNING);): its values are members of the
    // first variable declared with it, which gives them their type (ProjectModel::
    // find_local_enum_value finds them from the POU's code).
    if (first && type && type.kind() == "enum_type") {
      // A value written twice is reported by the name checks (check_enumerators), not as E003.
      for (SyntaxNode value : type.children_of_kind("enum_value")) {
        Symbol& enumerator = make(SymbolKind::EnumValue, value.child_by_field("name"), value, first);
        first->ordered.push_back(&enumerator);
        if (!enumerator.name.empty()) first->members.emplace(enumerator.name, &enumerator);
      }
    }
  }

  Symbol* add_type(const ast::TypeDeclaration& type, Symbol* owner) {
    Symbol& symbol = make(SymbolKind::DataType, type.node().child_by_field("name"), type.node(), owner);
    // The attributes stand before TYPE, which holds this declaration.
    SyntaxNode holder = type.node().parent();
    symbol.attributes = attributes_before(holder && holder.kind() == "type_declaration" ? holder : type.node());
    for (const auto& attribute : attributes_before(type.node())) symbol.attributes.push_back(attribute);
    symbol.flags |= attribute_flags(symbol.attributes);
    symbol.type_node = type.aliased_type();
    if (SyntaxNode extends = type.node().first_child_of_kind("extends_clause")) {
      symbol.base_nodes = extends.children_of_kind("type_name");
    }
    const ChildAttributes declared = attributes_of_children(type.node());
    for (const ast::VarDeclaration& field : type.fields()) {
      add_variables(symbol, field, ast::VarSection::Unknown, 0, {}, declared);
    }
    for (SyntaxNode value : type.enum_values()) {
      Symbol& enumerator = make(SymbolKind::EnumValue, value.child_by_field("name"), value, &symbol);
      add_member(symbol, enumerator);
    }
    return &symbol;
  }

  // IEC 61131-3 and OpenPCS let a PROGRAM declare VAR_GLOBAL; other POUs reach those variables
  // through VAR_EXTERNAL. They become a global list named after the program (added after it, so
  // the program keeps its name in the project index); CODESYS refuses them (declaration checks,
  // which recognise such a list by the program around its block).
  void add_program_globals(const ast::Pou& program, Symbol& program_symbol) {
    Symbol* list = nullptr;
    for (const ast::VarBlock& block : program.var_blocks()) {
      if (block.section() != ast::VarSection::Global) continue;
      if (!list) {
        // Owned by the program: its local types and constants are in scope for the declarations.
        list = &make(SymbolKind::GlobalList, SyntaxNode(), block.node(), &program_symbol);
        list->name = program_symbol.name;
        out_.global_lists.push_back(list);
        out_.top_level.push_back(list);
      }
      add_var_block(*list, block);
    }
  }

  void add_global_block(const ast::VarBlock& block) {
    const std::string_view list_name = global_list_name(block);
    Symbol* list = nullptr;
    for (Symbol* existing : out_.global_lists) {
      if (names_equal(existing->name, list_name)) list = existing;
    }
    if (!list) {
      list = &make(SymbolKind::GlobalList, SyntaxNode(), block.node(), nullptr);
      list->name = list_name;
      out_.global_lists.push_back(list);
      out_.top_level.push_back(list);
    }
    const std::vector<Attribute> attributes = attributes_before(block.node());
    list->attributes.insert(list->attributes.end(), attributes.begin(), attributes.end());
    list->flags |= attribute_flags(attributes);
    add_var_block(*list, block);
  }

  // TwinCAT and .EXP files name their lists; a plain file's lists are named after the file.
  std::string_view global_list_name(const ast::VarBlock& block) const {
    if (const containers::ContainerDocument* container = document_.container()) {
      const uint32_t offset = document_.file_offset_of(block.node().begin());
      const containers::ContainerObject* best = nullptr;
      for (const auto& object : container->objects) {
        if (object.file_offset <= offset && (object.kind == "GVL" || object.kind == "VAR_CONFIG")) best = &object;
      }
      if (best && !best->name.empty()) return best->name;
    }
    return gvl_name_;
  }

  FileSymbols& out_;
  const Document& document_;
  std::string_view gvl_name_;
};

uint64_t interface_hash(const Document& document, SyntaxNode root) {
  // Every byte outside POU bodies, so that an edit inside a body keeps the hash.
  std::vector<TextRange> bodies;
  std::vector<SyntaxNode> stack{root};
  while (!stack.empty()) {
    SyntaxNode node = stack.back();
    stack.pop_back();
    // A body reaches back over the comments and blank lines before its first statement: text
    // typed there is part of the body edit.
    uint32_t previous_end = node.begin();
    for (uint32_t i = 0; i < node.named_child_count(); ++i) {
      SyntaxNode child = node.named_child(i);
      const std::string_view kind = child.kind();
      if (kind == "statement_list" || kind == "il_body" || kind == "sfc_network") {
        bodies.push_back({std::min(previous_end, child.begin()), child.end()});
        continue;
      }
      if (kind == "comment" || kind == "pragma") continue;
      previous_end = child.end();
      if (kind.ends_with("_declaration") || kind == "source_file" || kind == "property_accessor" ||
          kind == "namespace_declaration") {
        stack.push_back(child);
      }
    }
  }
  std::sort(bodies.begin(), bodies.end(), [](TextRange a, TextRange b) { return a.begin < b.begin; });
  const std::string& text = document.tree()->text();
  uint64_t hash = 1469598103934665603ull;
  uint32_t position = 0;
  auto mix = [&](uint32_t end) {
    for (; position < end && position < text.size(); ++position) {
      hash ^= static_cast<unsigned char>(text[position]);
      hash *= 1099511628211ull;
    }
  };
  for (TextRange body : bodies) {
    if (body.begin < position) continue;
    mix(body.begin);
    position = body.end;
  }
  mix(static_cast<uint32_t>(text.size()));
  return hash;
}

}  // namespace

std::optional<Attribute> parse_attribute_pragma(std::string_view text) {
  // {attribute 'name'} or {attribute 'name' := 'value'}; spacing and quotes vary a little.
  auto skip_space = [&](size_t i) {
    while (i < text.size() && (text[i] == ' ' || text[i] == '\t' || text[i] == '\r' || text[i] == '\n')) ++i;
    return i;
  };
  size_t i = skip_space(text.starts_with("{") ? 1 : 0);
  if (text.size() - i < 9 || !names_equal(text.substr(i, 9), "attribute")) return std::nullopt;
  i = skip_space(i + 9);
  auto read_quoted = [&](size_t& at) -> std::optional<std::string> {
    if (at >= text.size() || (text[at] != '\'' && text[at] != '"')) return std::nullopt;
    const char quote = text[at];
    const size_t close = text.find(quote, at + 1);
    if (close == std::string_view::npos) return std::nullopt;
    std::string value(text.substr(at + 1, close - at - 1));
    at = close + 1;
    return value;
  };
  std::optional<std::string> name = read_quoted(i);
  if (!name) return std::nullopt;
  Attribute attribute;
  for (char c : *name) attribute.name += (c >= 'A' && c <= 'Z') ? static_cast<char>(c + 32) : c;
  i = skip_space(i);
  if (text.substr(i, 2) == ":=") {
    i = skip_space(i + 2);
    // The value ends at its last quote: it may hold apostrophes ('... we're ...').
    if (i < text.size() && (text[i] == '\'' || text[i] == '"')) {
      const size_t close = text.rfind(text[i]);
      if (close > i) attribute.value = std::string(text.substr(i + 1, close - i - 1));
    }
  }
  return attribute;
}

namespace {

// Whether the text just before `node` can end a pragma or a comment: only then can attribute
// pragmas stand before it. prev_sibling() walks from the parent's first child in tree-sitter
// 0.20, so asking it for every declaration of a long VAR block was quadratic.
bool may_follow_pragma(SyntaxNode node) {
  const std::string_view text = node.source();
  size_t at = std::min<size_t>(node.begin(), text.size());
  while (at > 0 && (text[at - 1] == ' ' || text[at - 1] == '\t' || text[at - 1] == '\r' || text[at - 1] == '\n')) --at;
  if (at == 0) return false;
  const char last = text[at - 1];
  if (last == '}' || last == ')' || last == '/') return true;  // {pragma}, (* comment *), /* comment */
  const size_t newline = text.rfind('\n', at - 1);
  const size_t line_begin = newline == std::string_view::npos ? 0 : newline + 1;
  return text.substr(line_begin, at - line_begin).find("//") != std::string_view::npos;  // a // comment
}

}  // namespace

ChildAttributes attributes_of_children(SyntaxNode parent) {
  ChildAttributes out;
  // Pragmas start with '{': without one in the node there is nothing to collect.
  if (parent.text().find('{') == std::string_view::npos) return out;
  std::vector<Attribute> pending;
  walk_preorder(parent, [&](SyntaxNode child) {
    if (child == parent) return true;
    const std::string_view kind = child.kind();
    if (kind == "pragma") {
      if (auto attribute = parse_attribute_pragma(child.text())) pending.push_back(std::move(*attribute));
    } else if (kind != "comment") {
      if (!pending.empty()) out.emplace(child.begin(), std::move(pending));
      pending.clear();
    }
    return false;
  });
  return out;
}

std::vector<Attribute> attributes_before(SyntaxNode node) {
  std::vector<Attribute> attributes;
  if (!may_follow_pragma(node)) return attributes;
  for (SyntaxNode sibling = node.prev_sibling(); sibling; sibling = sibling.prev_sibling()) {
    const std::string_view kind = sibling.kind();
    if (kind == "comment") continue;
    if (kind != "pragma") break;
    if (auto attribute = parse_attribute_pragma(sibling.text())) attributes.push_back(std::move(*attribute));
  }
  std::reverse(attributes.begin(), attributes.end());
  return attributes;
}

FileSymbols collect_file_symbols(SourceId source, const Document& document, bool library, std::string_view gvl_name) {
  FileSymbols out;
  out.source = source;
  out.library = library;
  const SyntaxTree* tree = document.tree();
  if (!tree || tree->aborted()) return out;
  Collector(out, document, gvl_name).run(tree->root());
  out.interface_hash = interface_hash(document, tree->root());
  return out;
}

void renumber(FileSymbols& symbols, SourceId source) {
  symbols.source = source;
  for (Symbol& symbol : symbols.storage) symbol.source = source;
}

namespace {
void collect_pous(const Symbol* symbol, std::vector<const Symbol*>& out) {
  if (!is_pou_kind(symbol->kind)) return;
  out.push_back(symbol);
  for (const Symbol* member : symbol->ordered) collect_pous(member, out);
}
}  // namespace

std::vector<const Symbol*> pous_of(const FileSymbols& symbols) {
  std::vector<const Symbol*> pous;
  for (const Symbol* top : symbols.top_level) collect_pous(top, pous);
  return pous;
}

}  // namespace rung::check
