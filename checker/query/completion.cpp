#include "checker/query/completion.hpp"

#include <algorithm>
#include <array>
#include <unordered_set>

#include "checker/query/call_site.hpp"
#include "checker/query/members.hpp"
#include "checker/query/written_expression.hpp"

namespace rung::check::query {
namespace {

using namespace std::string_view_literals;

constexpr size_t kMaxInheritanceDepth = 32;  // EXTENDS may form a cycle in broken code

constexpr auto kElementaryTypes =
    std::to_array({"BOOL"sv, "BYTE"sv, "WORD"sv, "DWORD"sv, "LWORD"sv, "SINT"sv, "USINT"sv, "INT"sv, "UINT"sv,
                   "DINT"sv, "UDINT"sv, "LINT"sv, "ULINT"sv, "REAL"sv, "LREAL"sv, "TIME"sv, "LTIME"sv, "DATE"sv,
                   "LDATE"sv, "TIME_OF_DAY"sv, "TOD"sv, "LTOD"sv, "DATE_AND_TIME"sv, "DT"sv, "LDT"sv, "STRING"sv,
                   "WSTRING"sv, "CHAR"sv, "WCHAR"sv});
constexpr auto kStatementKeywords =
    std::to_array({"IF"sv, "CASE"sv, "FOR"sv, "WHILE"sv, "REPEAT"sv, "RETURN"sv, "EXIT"sv, "CONTINUE"sv, "JMP"sv});
constexpr auto kStatementSnippets = std::to_array({"IF"sv, "CASE"sv, "FOR"sv, "WHILE"sv, "REPEAT"sv});
constexpr auto kTopLevelKeywords = std::to_array({"PROGRAM"sv, "FUNCTION_BLOCK"sv, "FUNCTION"sv, "INTERFACE"sv,
                                                  "TYPE"sv, "VAR_GLOBAL"sv, "CONFIGURATION"sv});
constexpr auto kTopLevelSnippets = std::to_array({"PROGRAM"sv, "FUNCTION_BLOCK"sv, "FUNCTION"sv, "INTERFACE"sv,
                                                  "STRUCT"sv, "ENUM"sv, "VAR_GLOBAL"sv});
constexpr auto kOperatorKeywords = std::to_array({"AND"sv, "OR"sv, "XOR"sv, "MOD"sv});
constexpr auto kValueKeywords = std::to_array({"NOT"sv, "TRUE"sv, "FALSE"sv});
constexpr auto kVarQualifiers = std::to_array({"CONSTANT"sv, "RETAIN"sv, "PERSISTENT"sv});

// The VAR blocks a POU of each kind may declare, in the order they are usually written.
std::vector<std::string_view> var_blocks_of(std::string_view pou) {
  if (pou == "PROGRAM") return {"VAR", "VAR_INPUT", "VAR_OUTPUT", "VAR_IN_OUT", "VAR_TEMP", "VAR_EXTERNAL"};
  if (pou == "FUNCTION_BLOCK" || pou == "FUNCTIONBLOCK" || pou == "CLASS") {
    return {"VAR", "VAR_INPUT", "VAR_OUTPUT", "VAR_IN_OUT", "VAR_TEMP", "VAR_STAT", "VAR_EXTERNAL"};
  }
  if (pou == "FUNCTION") return {"VAR", "VAR_INPUT", "VAR_OUTPUT", "VAR_IN_OUT", "VAR_EXTERNAL"};
  if (pou == "METHOD") return {"VAR", "VAR_INPUT", "VAR_OUTPUT", "VAR_IN_OUT", "VAR_INST"};
  if (pou == "PROPERTY" || pou == "GET" || pou == "SET") return {"VAR"};
  if (pou == "CONFIGURATION" || pou == "RESOURCE") return {"VAR_GLOBAL", "VAR_ACCESS", "VAR_CONFIG"};
  return {};
}

std::string_view pou_closer(std::string_view pou) {
  static constexpr auto kClosers = std::to_array<std::pair<std::string_view, std::string_view>>({
      {"PROGRAM", "END_PROGRAM"},
      {"FUNCTION", "END_FUNCTION"},
      {"FUNCTION_BLOCK", "END_FUNCTION_BLOCK"},
      {"FUNCTIONBLOCK", "END_FUNCTION_BLOCK"},
      {"CLASS", "END_CLASS"},
      {"INTERFACE", "END_INTERFACE"},
      {"CONFIGURATION", "END_CONFIGURATION"},
      {"RESOURCE", "END_RESOURCE"},
      {"METHOD", "END_METHOD"},
      {"PROPERTY", "END_PROPERTY"},
      {"ACTION", "END_ACTION"},
      {"TRANSITION", "END_TRANSITION"},
      {"GET", "END_GET"},
      {"SET", "END_SET"},
  });
  for (const auto& [opener, closer] : kClosers) {
    if (opener == pou) return closer;
  }
  return {};
}

std::string_view block_closer(std::string_view block) {
  if (block == "STRUCT") return "END_STRUCT";
  if (block == "UNION") return "END_UNION";
  if (block == "TYPE") return "END_TYPE";
  return block.starts_with("VAR") ? "END_VAR"sv : std::string_view();
}

// What closes or continues each open control block at a statement's start.
std::vector<std::string_view> control_keywords(std::string_view block) {
  if (block == "IF") return {"ELSIF", "ELSE", "END_IF"};
  if (block == "CASE") return {"ELSE", "END_CASE"};
  if (block == "FOR") return {"END_FOR"};
  if (block == "WHILE") return {"END_WHILE"};
  if (block == "REPEAT") return {"UNTIL"};
  return {};
}

bool is_block(const Symbol& symbol) {
  return symbol.kind == SymbolKind::FunctionBlock || symbol.kind == SymbolKind::Class;
}

// Whether `symbol` is `declared` or extends it, directly or through its bases: `declared`
// EXTENDS such a block or interface would form a cycle.
bool is_or_extends(const Symbol& symbol, const Symbol* declared) {
  std::vector<const Symbol*> pending{&symbol};
  std::unordered_set<const Symbol*> seen;  // EXTENDS may form a cycle in broken code
  while (!pending.empty()) {
    const Symbol* next = pending.back();
    pending.pop_back();
    if (next == declared) return true;
    if (!next || !seen.insert(next).second) continue;
    pending.insert(pending.end(), next->bases.begin(), next->bases.end());
  }
  return false;
}

bool is_enum_type(const ProjectModel& model, const Symbol& symbol) {
  return symbol.kind == SymbolKind::DataType && underlying(model.type_of(&symbol))->kind == TypeKind::Enum;
}

bool is_type_symbol(const Symbol& symbol) {
  return symbol.kind == SymbolKind::DataType || symbol.kind == SymbolKind::FunctionBlock ||
         symbol.kind == SymbolKind::Class || symbol.kind == SymbolKind::Interface;
}

class Collector {
 public:
  Collector(std::string_view prefix) : prefix_(prefix) {}

  void symbol(const Symbol* symbol, CandidateGroup group, std::string_view qualifier = {}) {
    if (!symbol || symbol->name.empty() || symbol->has(kHide) || !matches_prefix(symbol->name, prefix_)) return;
    if (!names_.insert(qualifier.empty() ? std::string(symbol->name) : std::string(qualifier) + "." + std::string(symbol->name))
             .second) {
      return;
    }
    candidates_.push_back({.kind = CandidateKind::Symbol, .group = group, .symbol = symbol, .qualifier = qualifier});
  }
  void parameter(const Symbol* parameter) {
    if (!matches_prefix(parameter->name, prefix_)) return;
    candidates_.push_back({.kind = CandidateKind::Parameter, .group = CandidateGroup::Expected, .symbol = parameter});
  }
  void word(CandidateKind kind, std::string_view word, CandidateGroup group) {
    if (word.empty() || !matches_prefix(word, prefix_)) return;
    const std::string key = std::to_string(static_cast<int>(kind)) + std::string(word);
    if (!words_.insert(key).second) return;
    candidates_.push_back({.kind = kind, .group = group, .word = word});
  }
  void keyword(std::string_view word) { this->word(CandidateKind::Keyword, word, CandidateGroup::Keyword); }
  template <typename Words>
  void keywords(const Words& words) {
    for (std::string_view w : words) keyword(w);
  }
  template <typename Words>
  void snippets(const Words& words) {
    for (std::string_view w : words) word(CandidateKind::Snippet, w, CandidateGroup::Snippet);
  }

  std::vector<CompletionCandidate> take(size_t limit, bool* incomplete) {
    // Members and parameters keep their declaration order; every other group is sorted by name,
    // names that start with what is typed first (`LIM`: LIMIT before ADD_LTIME), since clients
    // such as Neovim's omnifunc show the list in this order.
    auto keeps_order = [](CandidateGroup group) {
      return group == CandidateGroup::Expected || group == CandidateGroup::Member;
    };
    const std::string typed = upper_name(prefix_);
    std::vector<std::pair<std::string, size_t>> keys;
    keys.reserve(candidates_.size());
    for (size_t i = 0; i < candidates_.size(); ++i) {
      if (keeps_order(candidates_[i].group)) {
        keys.emplace_back(std::string(), i);
        continue;
      }
      std::string name = upper_name(candidates_[i].name());
      keys.emplace_back((name.starts_with(typed) ? "0" : "1") + name, i);
    }
    std::stable_sort(keys.begin(), keys.end(), [&](const auto& a, const auto& b) {
      const CandidateGroup ga = candidates_[a.second].group, gb = candidates_[b.second].group;
      if (ga != gb) return ga < gb;
      return a.first < b.first;
    });
    *incomplete = keys.size() > limit;
    std::vector<CompletionCandidate> sorted;
    sorted.reserve(std::min(limit, keys.size()));
    for (size_t i = 0; i < keys.size() && i < limit; ++i) sorted.push_back(candidates_[keys[i].second]);
    return sorted;
  }

 private:
  std::string_view prefix_;
  std::vector<CompletionCandidate> candidates_;
  std::unordered_set<std::string, NameHash, NameEqual> names_;
  std::unordered_set<std::string> words_;
};

template <typename Visit>
void for_each_top_level(const ProjectModel& model, Visit&& visit) {
  for (SourceId id = 0; id < model.source_count(); ++id) {
    for (const Symbol* symbol : model.source(id).symbols.top_level) visit(*symbol, model.source(id));
  }
}

CandidateGroup global_group(const Symbol& symbol) {
  return symbol.has(kLibrary) ? CandidateGroup::Library : CandidateGroup::Project;
}

void add_library_namespaces(const ProjectModel& model, Collector& out) {
  for (SourceId id = 0; id < model.source_count(); ++id) {
    const Source& source = model.source(id);
    if (source.library && !source.library_name.empty()) {
      out.word(CandidateKind::LibraryNamespace, source.library_name, CandidateGroup::Library);
    }
  }
}

// The variables, members and POUs a body may name at `scope`.
void add_values(const ProjectModel& model, const Symbol* scope, Collector& out) {
  for (const Symbol* s = scope; s; s = s->owner) {
    if (s->kind == SymbolKind::DataType) continue;  // a structure's fields are no names in its initial values
    const CandidateGroup group = s == scope ? CandidateGroup::Local : CandidateGroup::Member;
    size_t depth = 0;
    for (const Symbol* c = s; c && depth < kMaxInheritanceDepth; c = c->base, ++depth) {
      for (const Symbol* member : c->ordered) {
        if (member->kind == SymbolKind::Variable || member->kind == SymbolKind::Method ||
            member->kind == SymbolKind::Property || member->kind == SymbolKind::Action) {
          if (c != s && member->has(kPrivate)) continue;
          out.symbol(member, group);
        }
      }
    }
  }
  for_each_top_level(model, [&](const Symbol& symbol, const Source&) {
    if (symbol.kind == SymbolKind::GlobalList) {
      if (model.find_global(symbol.name) == &symbol || !model.find_global(symbol.name)) {
        out.symbol(&symbol, CandidateGroup::Global);
      }
      for (const Symbol* variable : symbol.ordered) {
        if (model.find_global_variable(variable->name) == variable) out.symbol(variable, CandidateGroup::Global);
      }
      return;
    }
    if (model.find_global(symbol.name) != &symbol) return;  // hidden by a project declaration of that name
    if (symbol.kind == SymbolKind::Function || symbol.kind == SymbolKind::Program) {
      out.symbol(&symbol, global_group(symbol));
    } else if (is_enum_type(model, symbol)) {
      out.symbol(&symbol, symbol.has(kLibrary) ? CandidateGroup::Library : CandidateGroup::Global);
    }
  });
  add_library_namespaces(model, out);
}

// The block whose instance THIS^ is, around `scope`.
const Symbol* enclosing_block(const Symbol* scope) {
  for (const Symbol* s = scope; s; s = s->owner) {
    if (is_block(*s)) return s;
  }
  return nullptr;
}

// Everything THIS^. and SUPER^. reach: the block's variables (not VAR_TEMP), methods, properties
// and actions, its bases' too.
void add_inner_members(const Symbol* block, Collector& out) {
  size_t depth = 0;
  for (const Symbol* c = block; c && depth < kMaxInheritanceDepth; c = c->base, ++depth) {
    for (const Symbol* member : c->ordered) {
      const bool variable = member->kind == SymbolKind::Variable && member->section != ast::VarSection::Temp;
      if (variable || member->kind == SymbolKind::Method || member->kind == SymbolKind::Property ||
          member->kind == SymbolKind::Action) {
        out.symbol(member, CandidateGroup::Member);
      }
    }
  }
}

void add_values_of_enum(const Type* type, CandidateGroup group, Collector& out, bool qualified) {
  if (!type) return;
  type = underlying(type);
  if (type->kind != TypeKind::Enum || !type->declaration) return;
  const Symbol* enumeration = type->declaration;
  for (const Symbol* value : members_of(enumeration)) {
    out.symbol(value, group, qualified ? enumeration->name : std::string_view());
  }
}

std::string_view tree_text(const ProjectModel& model, SourceId source, TextRange range) {
  const std::string_view text = model.source(source).document->tree()->text();
  return text.substr(range.begin, range.end - range.begin);
}

bool spells(std::string_view written, std::string_view word) {
  std::string compact;
  for (char c : written) {
    if (c != ' ' && c != '\t' && c != '\r' && c != '\n') compact += c;
  }
  return names_equal(compact, word);
}

void add_members(const ProjectModel& model, SourceId source, const CursorContext& context, Collector& out) {
  const std::string_view written = tree_text(model, source, context.qualifier);
  if (spells(written, "THIS^") || spells(written, "SUPER^")) {
    const Symbol* block = enclosing_block(context.scope);
    if (block && spells(written, "SUPER^")) block = block->base;
    add_inner_members(block, out);
    return;
  }
  ExprInfo info{.type = model.types().unknown()};
  if (context.scope) {
    info = type_written_expression(model, source, *context.scope, context.qualifier);
  } else if (const Symbol* global = model.find_global(written)) {
    info = ExprInfo{.type = model.type_of(global),
                    .symbol = global,
                    .names_type = global->kind != SymbolKind::Program && global->kind != SymbolKind::GlobalList,
                    .names_namespace = global->kind == SymbolKind::GlobalList};
  } else {
    info.names_namespace = model.is_library_namespace(written);
  }
  if (info.symbol && info.symbol->kind == SymbolKind::GlobalList) {
    // Lists of one name are one list (a TwinCAT GVL split over objects).
    for_each_top_level(model, [&](const Symbol& symbol, const Source&) {
      if (symbol.kind != SymbolKind::GlobalList || !names_equal(symbol.name, info.symbol->name)) return;
      for (const Symbol* member : members_of(&symbol)) out.symbol(member, CandidateGroup::Member);
    });
    return;
  }
  if (info.names_namespace && model.is_library_namespace(written)) {
    for_each_top_level(model, [&](const Symbol& symbol, const Source& file) {
      if (!file.library || !names_equal(file.library_name, written)) return;
      if (context.type_qualifier ? is_type_symbol(symbol) : symbol.kind != SymbolKind::GlobalList) {
        out.symbol(&symbol, CandidateGroup::Member);
      }
    });
    return;
  }
  if (info.names_type) {
    add_values_of_enum(info.type, CandidateGroup::Member, out, false);
    return;
  }
  for (const Symbol* member : members_of(info.type)) out.symbol(member, CandidateGroup::Member);
}

void add_types(const ProjectModel& model, const CursorContext& context, Collector& out) {
  const TypeFilter filter = context.types;
  if (filter == TypeFilter::Any) {
    for (std::string_view type : kElementaryTypes) out.word(CandidateKind::ElementaryType, type, CandidateGroup::Keyword);
    if (context.type_constructors) out.keywords(std::to_array({"ARRAY"sv, "POINTER"sv, "REFERENCE"sv}));
    if (context.structured_types) out.keywords(std::to_array({"STRUCT"sv, "UNION"sv}));
    // POU-local types (OpenPCS).
    for (const Symbol* s = context.scope; s; s = s->owner) {
      for (const Symbol* member : s->ordered) {
        if (member->kind == SymbolKind::DataType) out.symbol(member, CandidateGroup::Local);
      }
    }
  }
  for_each_top_level(model, [&](const Symbol& symbol, const Source&) {
    if (model.find_global(symbol.name) != &symbol) return;
    const bool fits = filter == TypeFilter::Any        ? is_type_symbol(symbol)
                      : filter == TypeFilter::Blocks ? is_block(symbol)
                                                     : symbol.kind == SymbolKind::Interface;
    // After EXTENDS and IMPLEMENTS the block or interface being declared is the scope.
    const bool cycle = filter != TypeFilter::Any && context.scope && is_or_extends(symbol, context.scope);
    if (fits && !cycle) out.symbol(&symbol, global_group(symbol));
  });
  if (filter == TypeFilter::Any) add_library_namespaces(model, out);
}

// The type the value at the cursor is for: the target of `x := |`, the parameter of `IN := |`.
const Type* expected_type(const ProjectModel& model, SourceId source, const CursorContext& context,
                          const std::optional<CallSite>& site) {
  if (site && !site->call.named.empty() && !site->call.output && site->active) return model.type_of(site->active);
  if (context.assigned.end > context.assigned.begin && context.scope) {
    return type_written_expression(model, source, *context.scope, context.assigned).type;
  }
  return nullptr;
}

void add_pou_keywords(const CursorContext& context, Collector& out) {
  out.keyword(pou_closer(context.pou_keyword));
}

void add_statement_keywords(const CursorContext& context, Collector& out) {
  out.keywords(kStatementKeywords);
  if (!context.open_blocks.empty()) out.keywords(control_keywords(context.open_blocks.front()));
  add_pou_keywords(context, out);
  out.snippets(kStatementSnippets);
}

void add_self_keywords(const CursorContext& context, Collector& out) {
  if (enclosing_block(context.scope)) out.keywords(std::to_array({"THIS"sv, "SUPER"sv}));
}

}  // namespace

bool matches_prefix(std::string_view name, std::string_view prefix) {
  if (prefix.empty()) return true;
  // The first letter starts the name or a part of it (fbTimer, MAX_VALUE), the rest follow in order.
  auto starts_part = [&](size_t at) {
    if (at == 0) return true;
    const char c = name[at], before = name[at - 1];
    return before == '_' || (c >= 'A' && c <= 'Z' && before >= 'a' && before <= 'z');
  };
  for (size_t first = 0; first < name.size(); ++first) {
    if (ascii_upper(name[first]) != ascii_upper(prefix[0]) || !starts_part(first)) continue;
    size_t at = first + 1;
    bool all = true;
    for (char c : prefix.substr(1)) {
      while (at < name.size() && ascii_upper(name[at]) != ascii_upper(c)) ++at;
      if (at == name.size()) {
        all = false;
        break;
      }
      ++at;
    }
    if (all) return true;
  }
  return false;
}

Completion complete_at(const Workspace& workspace, SourceId source, uint32_t file_offset, size_t limit) {
  Completion completion;
  const ProjectModel& model = workspace.model();
  if (source >= model.source_count()) return completion;
  const Document& document = *model.source(source).document;
  const std::optional<uint32_t> tree_offset = document.tree_offset_of(file_offset);
  completion.word = {file_offset, file_offset};
  if (!tree_offset) return completion;
  const CursorContext context = cursor_context(model, source, *tree_offset);
  completion.place = context.place;
  completion.prefix = std::string(context.prefix);
  completion.word = {document.file_offset_of(context.word.begin), document.file_end_offset_of(context.word.end)};
  if (context.word.begin == context.word.end) completion.word = {file_offset, file_offset};

  Collector out(context.prefix);
  const std::optional<CallSite> site = call_site_of(model, source, context);
  switch (context.place) {
    case CursorPlace::None: break;
    case CursorPlace::TopLevel:
      out.keywords(kTopLevelKeywords);
      out.snippets(kTopLevelSnippets);
      break;
    case CursorPlace::PouHeader:
      if (context.pou_keyword == "FUNCTION_BLOCK" || context.pou_keyword == "FUNCTIONBLOCK" ||
          context.pou_keyword == "CLASS") {
        out.keywords(std::to_array({"EXTENDS"sv, "IMPLEMENTS"sv}));
      } else if (context.pou_keyword == "INTERFACE") {
        out.keyword("EXTENDS");
      }
      break;
    case CursorPlace::PouDeclarations: {
      const std::vector<std::string_view> blocks = var_blocks_of(context.pou_keyword);
      out.keywords(blocks);
      out.snippets(blocks);
      const bool block = context.pou_keyword == "FUNCTION_BLOCK" || context.pou_keyword == "FUNCTIONBLOCK" ||
                         context.pou_keyword == "CLASS" || context.pou_keyword == "INTERFACE";
      if (block) {
        out.keywords(std::to_array({"METHOD"sv, "PROPERTY"sv}));
        out.snippets(std::to_array({"METHOD"sv, "PROPERTY"sv}));
      }
      if (context.pou_keyword == "INTERFACE") {
        add_pou_keywords(context, out);
        break;
      }
      if (block || context.pou_keyword == "PROGRAM") out.keyword("ACTION");
      add_statement_keywords(context, out);
      add_self_keywords(context, out);
      add_values(model, context.scope, out);
      break;
    }
    case CursorPlace::VarName:
      out.keyword(block_closer(context.block_keyword));
      if (context.var_qualifiers) out.keywords(kVarQualifiers);
      break;
    case CursorPlace::TypeName: add_types(model, context, out); break;
    case CursorPlace::Statement:
      add_statement_keywords(context, out);
      add_self_keywords(context, out);
      add_values(model, context.scope, out);
      break;
    case CursorPlace::Expression:
      if (site && site->call.argument_start) {
        for (const Symbol* parameter : call_parameters(site->callee)) {
          const bool given = std::any_of(site->call.given.begin(), site->call.given.end(),
                                         [&](std::string_view name) { return names_equal(name, parameter->name); });
          if (!given && !names_equal(parameter->name, "EN") && !names_equal(parameter->name, "ENO")) out.parameter(parameter);
        }
      }
      // A function block is called with formal arguments only: the names first, values after them.
      if (site && site->call.argument_start && site->instance_call) break;
      add_values_of_enum(expected_type(model, source, context, site), CandidateGroup::Expected, out, true);
      out.keywords(kValueKeywords);
      add_self_keywords(context, out);
      add_values(model, context.scope, out);
      break;
    case CursorPlace::Operator:
      for (std::string_view word : context.continuations) out.word(CandidateKind::Keyword, word, CandidateGroup::Expected);
      out.keywords(kOperatorKeywords);
      break;
    case CursorPlace::Member: add_members(model, source, context, out); break;
    case CursorPlace::TypedLiteral: {
      const std::string_view written = tree_text(model, source, context.qualifier);
      const Symbol* type = context.scope ? model.find_local_type(context.scope, written) : nullptr;
      if (!type) type = model.find_global(written);
      if (type && is_enum_type(model, *type)) add_values_of_enum(model.type_of(type), CandidateGroup::Member, out, false);
      break;
    }
  }
  completion.candidates = out.take(limit, &completion.incomplete);
  return completion;
}

}  // namespace rung::check::query
