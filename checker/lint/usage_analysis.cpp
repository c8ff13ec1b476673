#include "checker/lint/usage_analysis.hpp"

#include <algorithm>
#include <memory>

#include "checker/query/resolve.hpp"
#include "checker/semantic/body_checker.hpp"
#include "checker/semantic/builtins.hpp"

namespace rung::lint {
namespace {

using check::Symbol;
using check::SymbolKind;

// Expressions nest as deep as the code does; past this depth the rest of an expression is read
// name by name (every name a read), which keeps the stack bounded on generated code.
constexpr int kMaxDepth = 300;

bool is_expression_kind(std::string_view kind) {
  return kind == "identifier" || kind == "global_reference" || kind == "member_expression" ||
         kind == "index_expression" || kind == "dereference_expression" || kind == "call_expression" ||
         kind == "binary_expression" || kind == "unary_expression" || kind == "parenthesized_expression" ||
         kind == "typed_literal" || kind == "struct_initializer" || kind == "array_initializer" ||
         kind == "assignment_expression" || kind == "il_expression";
}

// The grammar's ids of the fields the collector asks about.
struct Fields {
  TSFieldId name = NodeList::field_id("name");
  TSFieldId from = NodeList::field_id("from");
  TSFieldId to = NodeList::field_id("to");
  TSFieldId qualifier = NodeList::field_id("qualifier");
  TSFieldId task = NodeList::field_id("task");
  TSFieldId variable = NodeList::field_id("variable");
  TSFieldId exception = NodeList::field_id("exception");
  TSFieldId target = NodeList::field_id("target");
  TSFieldId op = NodeList::field_id("operator");
  TSFieldId left = NodeList::field_id("left");
  TSFieldId right = NodeList::field_id("right");
  TSFieldId argument = NodeList::field_id("argument");
  TSFieldId operand = NodeList::field_id("operand");
  TSFieldId object = NodeList::field_id("object");
  TSFieldId index = NodeList::field_id("index");
  TSFieldId member = NodeList::field_id("member");
  TSFieldId function = NodeList::field_id("function");
  TSFieldId arguments = NodeList::field_id("arguments");
  TSFieldId value = NodeList::field_id("value");
};

const Fields& fields() {
  static const Fields ids;
  return ids;
}

// Fields whose identifier declares something rather than naming a declaration: declarations'
// names, SFC step lists and action qualifiers, a program's task. (Jumps and labels are skipped
// as a whole; CASE labels are expressions.)
bool is_naming_field(TSFieldId field) {
  const Fields& f = fields();
  return field != 0 && (field == f.name || field == f.from || field == f.to || field == f.qualifier || field == f.task);
}

// Kinds that open a scope of their own (the nodes of POU, member, type, list and configuration
// symbols); other nodes are looked up in the scope map only when their kind is one of these.
bool may_open_scope(std::string_view kind) {
  return kind.ends_with("_declaration") || kind == "property_accessor" || kind == "var_block" ||
         kind == "sfc_action_block" || kind == "source_file" || kind == "struct_type" || kind == "enum_type" ||
         kind == "union_type" || kind == "alias_type" || kind == "subrange_type";
}

// Library operators whose arguments are not read as values: ADR and friends take the address
// (the variable may be written through it later); SIZEOF and friends only look at the layout.
uint16_t operator_argument_use(std::string_view name) {
  static constexpr std::string_view kAddress[] = {
      "ADR", "ADRINST", "BITADR", "REF", "__QUERYPOINTER", "__QUERYINTERFACE", "__DELETE"};
  static constexpr std::string_view kMention[] = {"SIZEOF",      "XSIZEOF", "UPPER_BOUND",
                                                  "LOWER_BOUND", "INDEXOF", "__NEW"};
  for (std::string_view op : kAddress) {
    if (check::names_equal(op, name)) return kUseAddress;
  }
  for (std::string_view op : kMention) {
    if (check::names_equal(op, name)) return kUseMention;
  }
  return 0;
}

// IL operators by what they do to their operand (IEC 61131-3 table 52; the FB input operators
// of table 53 set one input of the instance named).
enum class IlOperand { Read, Write, SetInput, Call, Label, None };

IlOperand il_operand_use(std::string_view op) {
  const std::string upper = check::upper_name(op);
  if (upper == "ST" || upper == "STN" || upper == "S" || upper == "R") return IlOperand::Write;
  if (upper == "S1" || upper == "R1" || upper == "CLK" || upper == "CU" || upper == "CD" || upper == "PV" ||
      upper == "IN" || upper == "PT") {
    return IlOperand::SetInput;
  }
  if (upper == "CAL" || upper == "CALC" || upper == "CALCN") return IlOperand::Call;
  if (upper == "JMP" || upper == "JMPC" || upper == "JMPCN") return IlOperand::Label;
  if (upper == "RET" || upper == "RETC" || upper == "RETCN" || upper == "RETURN") return IlOperand::None;
  return IlOperand::Read;
}

bool has_in_out(const Symbol* callee) {
  int depth = 0;  // EXTENDS cycles are reported elsewhere
  for (const Symbol* c = callee; c && depth < 32; c = c->base, ++depth) {
    for (const Symbol* member : c->ordered) {
      if (member->kind == SymbolKind::Variable && member->section == ast::VarSection::InOut) return true;
    }
  }
  return false;
}

class UsageCollector {
 public:
  UsageCollector(const check::ProjectModel& model, check::SourceId source, const NodeList& nodes, FileUsage& out)
      : model_(model), source_(source), nodes_(nodes), out_(out) {}

  void run() {
    const SyntaxTree* tree = model_.source(source_).document->tree();
    if (!tree || tree->aborted() || nodes_.empty()) return;
    for (const Symbol& symbol : model_.source(source_).symbols.storage) {
      if (symbol.node && opens_scope(symbol.kind)) scopes_.emplace(symbol.node.begin(), &symbol);
    }
    visit(0, nullptr, 0);
    collect_inactive_names(model_.source(source_).document->source_text(), tree->text());
    std::stable_sort(out_.uses.begin(), out_.uses.end(),
                     [](const Use& a, const Use& b) { return a.range.begin < b.range.begin; });
    for (uint32_t i = 0; i < out_.uses.size(); ++i) out_.by_symbol[out_.uses[i].symbol].push_back(i);
  }

 private:
  static constexpr uint32_t kNone = NodeList::kNone;

  static bool opens_scope(SymbolKind kind) {
    return check::is_pou_kind(kind) || kind == SymbolKind::DataType || kind == SymbolKind::GlobalList ||
           kind == SymbolKind::Configuration;
  }

  // The symbol whose declaration is exactly node `i`, or `outer`.
  const Symbol* scope_for(uint32_t i, const Symbol* outer) const {
    if (!may_open_scope(nodes_.kind(i))) return outer;
    auto [first, last] = scopes_.equal_range(nodes_.begin(i));
    for (auto it = first; it != last; ++it) {
      if (it->second->node == nodes_.node(i)) return it->second;
    }
    return outer;
  }

  check::BodyChecker* checker(const Symbol* scope) {
    if (!scope) return nullptr;
    std::unique_ptr<check::BodyChecker>& slot = checkers_[scope];
    if (!slot) slot = std::make_unique<check::BodyChecker>(model_, *scope, scratch_);
    // Typing reports what `rung check` reports already; only the symbols matter here.
    if (scratch_.size() > 256) scratch_.clear();
    return slot.get();
  }

  void record(const Symbol* symbol, TextRange range, uint16_t flags, const Symbol* scope) {
    if (!symbol) return;
    out_.uses.push_back(Use{check::query::canonical_symbol(model_, symbol), scope, range, flags});
  }

  const Symbol* lookup(const Symbol* scope, std::string_view name) const {
    const Symbol* found = scope ? model_.lookup(scope, name) : model_.lookup_global(name);
    return found ? found : model_.find_qualified_only(name);
  }

  // The first named child of `i` (SyntaxNode::named_child(0)), or kNone.
  uint32_t first_named_child(uint32_t i) const {
    uint32_t found = kNone;
    nodes_.for_each_child(i, [&](uint32_t child) {
      if (found == kNone && nodes_.is_named(child)) found = child;
    });
    return found;
  }

  // Whether typing `expression` can lead to a declaration: its innermost object resolves. Typing
  // an undeclared name makes the body checker look for a "did you mean" among every visible name,
  // which is the checker's job and far too slow to repeat for every use.
  bool root_resolves(uint32_t expression, const Symbol* scope) const {
    const Fields& f = fields();
    uint32_t node = expression;
    for (int depth = 0; node != kNone && depth < kMaxDepth; ++depth) {
      const std::string_view kind = nodes_.kind(node);
      if (kind == "identifier") {
        const std::string_view name = nodes_.text(node);
        return lookup(scope, name) || check::names_equal(name, "THIS") || check::names_equal(name, "SUPER") ||
               model_.is_library_namespace(name) || check::find_builtin(name);
      }
      if (kind == "global_reference") return true;
      if (kind == "member_expression" || kind == "index_expression") {
        node = nodes_.child_by_field(node, f.object);
      } else if (kind == "dereference_expression") {
        node = nodes_.child_by_field(node, f.operand);
      } else if (kind == "call_expression") {
        node = nodes_.child_by_field(node, f.function);
      } else if (kind == "parenthesized_expression") {
        node = first_named_child(node);
      } else {
        return false;
      }
    }
    return false;
  }

  check::ExprInfo type_of(uint32_t expression, const Symbol* scope) {
    check::BodyChecker* typer = checker(scope);
    if (!typer || !root_resolves(expression, scope)) return check::ExprInfo{};
    return typer->type_of(nodes_.node(expression));
  }

  // Conditional compilation blanks inactive branches in the tree text (same length, line ends
  // kept); the words of the original text where the two differ are the inactive code's names.
  void collect_inactive_names(std::string_view original, std::string_view blanked) {
    if (original.size() != blanked.size() || original == blanked) return;
    auto is_word = [](char c) {
      return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
             static_cast<unsigned char>(c) >= 0x80;
    };
    for (size_t at = 0; at < original.size();) {
      if (original[at] == blanked[at] || !is_word(original[at])) {
        ++at;
        continue;
      }
      size_t end = at;
      while (end < original.size() && is_word(original[end])) ++end;
      out_.inactive_names.insert(original.substr(at, end - at));
      at = end;
    }
  }

  // --- Declarations, statements and everything around them ----------------------------------

  void visit(uint32_t node, const Symbol* scope, int depth) {
    if (node == kNone || !nodes_.is_named(node)) return;
    const std::string_view kind = nodes_.kind(node);
    if (kind == "comment") return;
    if (kind == "pragma") return note_pragma(node, scope);
    if (depth > kMaxDepth) return read_every_name(node, scope);
    scope = scope_for(node, scope);
    if (is_expression_kind(kind)) return visit_expression(node, kUseRead, scope, depth);
    if (kind == "type_name") return record_type(node, scope);
    if (kind == "qualified_name" || kind == "access_path") return add_unresolved(node);
    if (kind == "task_association" || kind == "il_label" || kind == "label" || kind == "jmp_statement" ||
        kind == "sfc_step_macro" || kind == "generic_parameters") {
      return;
    }
    if (kind == "assignment_statement") return visit_assignment(node, scope, depth);
    if (kind == "il_instruction") return visit_il(node, scope, depth);
    if (kind == "sfc_action") return visit_sfc_action(node, scope, depth);
    const Fields& f = fields();
    nodes_.for_each_child(node, [&](uint32_t child) {
      if (!nodes_.is_named(child)) return;
      const TSFieldId field = nodes_.field(child);
      if (nodes_.kind(child) == "identifier" && is_naming_field(field)) return;
      if (field != 0 && kind == "for_statement" && field == f.variable) {
        return visit_expression(child, kUseRead | kUseWrite, scope, depth + 1);
      }
      if (field != 0 && kind == "catch_clause" && field == f.exception) {
        return visit_expression(child, kUseWrite, scope, depth + 1);
      }
      if (field != 0 && kind == "output_argument" && field == f.target) {
        return visit_expression(child, kUseWrite | kUseOutputTarget, scope, depth + 1);
      }
      visit(child, scope, depth + 1);
    });
  }

  // {attribute}, {IF}, {warning}, {region} are rung's; anything else may be code of another
  // language that uses the variables around it.
  void note_pragma(uint32_t pragma, const Symbol* scope) {
    if (!scope) return;
    nodes_.for_each_child(pragma, [&](uint32_t content) {
      if (nodes_.is_named(content) && nodes_.kind(content) == "generic_pragma") out_.embedding_scopes.insert(scope);
    });
  }

  void visit_assignment(uint32_t node, const Symbol* scope, int depth) {
    const Fields& f = fields();
    const uint32_t op = nodes_.child_by_field(node, f.op);
    const bool reference = op != kNone && check::names_equal(nodes_.text(op), "REF=");
    visit_expression(nodes_.child_by_field(node, f.right), reference ? kUseAddress : kUseRead, scope, depth + 1);
    visit_expression(nodes_.child_by_field(node, f.left), kUseWrite, scope, depth + 1);
  }

  // A boolean SFC action is a variable the step sets; a named one is an action the step runs.
  void visit_sfc_action(uint32_t node, const Symbol* scope, int depth) {
    const Fields& f = fields();
    nodes_.for_each_child(node, [&](uint32_t child) {
      if (!nodes_.is_named(child) || nodes_.field(child) == 0) return;
      if (nodes_.field(child) == f.name) {
        const Symbol* target = lookup(scope, nodes_.text(child));
        if (target) {
          record(target, nodes_.range(child), target->kind == SymbolKind::Variable ? kUseWrite : kUseCall, scope);
        }
      } else if (nodes_.field(child) == f.argument) {
        visit_expression(child, kUseRead, scope, depth + 1);
      }
    });
  }

  void visit_il(uint32_t node, const Symbol* scope, int depth) {
    const Fields& f = fields();
    IlOperand use = IlOperand::Read;
    nodes_.for_each_child(node, [&](uint32_t child) {
      if (!nodes_.is_named(child)) return;
      const TSFieldId field = nodes_.field(child);
      if (field != 0 && field == f.op) {
        const std::string_view op = nodes_.text(child);
        use = il_operand_use(op);
        // Any other word names a function (LD a / MyFunction b).
        if (const Symbol* callee = lookup(scope, op); callee && check::is_callable_kind(callee->kind)) {
          record(callee, nodes_.range(child), kUseCall, scope);
        }
        return;
      }
      if (field == 0 || field != f.operand) return visit(child, scope, depth + 1);  // deferred instructions, labels
      switch (use) {
        case IlOperand::Read: return visit_expression(child, kUseRead, scope, depth + 1);
        case IlOperand::Write: return visit_expression(child, kUseWrite, scope, depth + 1);
        case IlOperand::SetInput: return visit_expression(child, kUseWrite | kUsePart, scope, depth + 1);
        case IlOperand::Call: return visit_expression(child, kUseCall, scope, depth + 1);
        case IlOperand::Label:
        case IlOperand::None: return;
      }
    });
  }

  void record_type(uint32_t type_name, const Symbol* scope) {
    if (const Symbol* type = model_.resolve_type_symbol(nodes_.node(type_name), scope, nullptr)) {
      record(type, nodes_.range(type_name), kUseMention, scope);
    } else if (nodes_.text(type_name).find('.') != std::string_view::npos) {
      add_unresolved(type_name);
    }
  }

  void add_unresolved(uint32_t node) {
    nodes_.walk(node, [&](uint32_t inner) {
      if (nodes_.kind(inner) == "identifier") out_.unresolved_names.insert(nodes_.text(inner));
      return true;
    });
  }

  // Past the depth limit: every name is a read (more "used" never invents a finding).
  void read_every_name(uint32_t node, const Symbol* scope) {
    nodes_.walk(node, [&](uint32_t inner) {
      if (nodes_.kind(inner) == "identifier") {
        const std::string_view name = nodes_.text(inner);
        if (const Symbol* symbol = lookup(scope, name)) record(symbol, nodes_.range(inner), kUseRead, scope);
        out_.unresolved_names.insert(name);
      }
      return true;
    });
  }

  // --- Expressions -------------------------------------------------------------------------

  // `access` is what the code around does with the value `expression` stands for.
  void visit_expression(uint32_t expression, uint16_t access, const Symbol* scope, int depth) {
    if (expression == kNone) return;
    if (depth > kMaxDepth) return read_every_name(expression, scope);
    const Fields& f = fields();
    const std::string_view kind = nodes_.kind(expression);
    if (kind == "identifier") {
      const std::string_view name = nodes_.text(expression);
      const Symbol* symbol = lookup(scope, name);
      record(symbol, nodes_.range(expression), access, scope);
      // An undeclared name (code the checker rejects, e.g. a method file it could not attach to
      // its block) may be meant for any block's variable.
      if (!symbol) out_.unresolved_names.insert(name);
    } else if (kind == "global_reference") {
      const uint32_t name = nodes_.child_by_field(expression, f.name);
      if (name != kNone) record(model_.lookup_global(nodes_.text(name)), nodes_.range(name), access, scope);
    } else if (kind == "member_expression") {
      visit_member(expression, access, scope, depth);
    } else if (kind == "index_expression") {
      nodes_.for_each_child(expression, [&](uint32_t child) {
        const TSFieldId field = nodes_.field(child);
        if (field == 0) return;
        if (field == f.object) visit_expression(child, access | kUsePart, scope, depth + 1);
        if (field == f.index) visit_expression(child, kUseRead, scope, depth + 1);
      });
    } else if (kind == "dereference_expression") {
      // p^ := x writes what p points to; p itself is only read.
      visit_expression(nodes_.child_by_field(expression, f.operand), kUseRead, scope, depth + 1);
    } else if (kind == "call_expression") {
      visit_call(expression, scope, depth);
    } else if (kind == "binary_expression") {
      // Long chains (a OR b OR c ...) nest to the left: walk the spine without recursion.
      std::vector<uint32_t> rights;
      uint32_t left = expression;
      while (left != kNone && nodes_.kind(left) == "binary_expression" && rights.size() < 100000) {
        rights.push_back(nodes_.child_by_field(left, f.right));
        left = nodes_.child_by_field(left, f.left);
      }
      visit_expression(left, kUseRead, scope, depth + 1);
      for (auto it = rights.rbegin(); it != rights.rend(); ++it) visit_expression(*it, kUseRead, scope, depth + 1);
    } else if (kind == "typed_literal") {
      // E_Color#Red: the value (and through it its enumeration).
      if (check::BodyChecker* typer = checker(scope)) {
        record(typer->type_of(nodes_.node(expression)).symbol, nodes_.range(expression), kUseRead, scope);
      }
    } else if (kind == "assignment_expression") {
      visit_assignment(expression, scope, depth);
    } else if (kind == "field_initializer") {
      visit_expression(nodes_.child_by_field(expression, f.value), kUseRead, scope, depth + 1);
    } else if (kind == "il_instruction") {
      visit_il(expression, scope, depth);
    } else if (nodes_.is_named(expression)) {
      // Parentheses, unary operators, initializers, IL expressions, error recovery: every part
      // is read.
      nodes_.for_each_child(expression, [&](uint32_t child) {
        if (!nodes_.is_named(child)) return;
        const std::string_view child_kind = nodes_.kind(child);
        if (child_kind == "identifier" && is_naming_field(nodes_.field(child))) return;
        if (child_kind == "comment" || child_kind == "pragma") return;
        visit_expression(child, kUseRead, scope, depth + 1);
      });
    }
  }

  void visit_member(uint32_t expression, uint16_t access, const Symbol* scope, int depth) {
    const Fields& f = fields();
    // obj.x := 1 writes a part of obj; obj.x read reads a part; obj.M() calls through obj.
    visit_expression(nodes_.child_by_field(expression, f.object), access | kUsePart, scope, depth + 1);
    const uint32_t member = nodes_.child_by_field(expression, f.member);
    if (member == kNone || nodes_.kind(member) != "identifier") return;  // w.3, a bit of a word
    const check::ExprInfo info = type_of(expression, scope);
    if (info.symbol) {
      record(info.symbol, nodes_.range(member), access, scope);
    } else {
      out_.unresolved_names.insert(nodes_.text(member));
    }
  }

  void visit_call(uint32_t call, const Symbol* scope, int depth) {
    const Fields& f = fields();
    const uint32_t function = nodes_.child_by_field(call, f.function);
    visit_expression(function, kUseCall, scope, depth + 1);
    const Symbol* callee = function != kNone ? check::query::callee_of(type_of(function, scope)) : nullptr;
    uint16_t operator_use = 0;
    if (callee && callee->has(check::kLibrary)) {
      operator_use = operator_argument_use(callee->name);
    } else if (!callee && function != kNone && nodes_.kind(function) == "identifier" &&
               check::find_builtin(nodes_.text(function))) {
      operator_use = operator_argument_use(nodes_.text(function));
    }
    const bool positional_may_be_in_out = callee && has_in_out(callee);
    const uint32_t arguments = nodes_.child_by_field(call, f.arguments);
    if (arguments == kNone) return;
    for (const check::CallArgument& argument : check::call_arguments(nodes_.node(arguments))) {
      const uint32_t value = nodes_.index_of(argument.value);
      if (argument.output) {
        visit_expression(value, kUseWrite | kUseOutputTarget, scope, depth + 1);
        continue;
      }
      uint16_t use = kUseRead;
      if (operator_use) {
        use = operator_use;
      } else if (argument.name && callee) {
        const Symbol* parameter = model_.find_member(callee, argument.name.text());
        if (parameter && parameter->section == ast::VarSection::InOut) use = kUseInOut;
      } else if (!argument.name && positional_may_be_in_out) {
        use = kUseRead | kUseInOut;  // which parameter it binds is the call checker's business
      }
      visit_expression(value, use, scope, depth + 1);
    }
  }

  const check::ProjectModel& model_;
  check::SourceId source_;
  const NodeList& nodes_;
  FileUsage& out_;
  std::unordered_multimap<uint32_t, const Symbol*> scopes_;  // by the start of the declaring node
  std::unordered_map<const Symbol*, std::unique_ptr<check::BodyChecker>> checkers_;
  std::vector<Diagnostic> scratch_;
};

}  // namespace

bool FileUsage::embeds_foreign_code(const check::Symbol& pou) const {
  return std::any_of(embedding_scopes.begin(), embedding_scopes.end(),
                     [&](const check::Symbol* scope) { return is_within(scope, &pou); });
}

std::span<const uint32_t> FileUsage::uses_of(const check::Symbol* symbol) const {
  auto found = by_symbol.find(symbol);
  if (found == by_symbol.end()) return {};
  return found->second;
}

std::span<const Use> FileUsage::uses_in(TextRange range) const {
  auto first = std::lower_bound(uses.begin(), uses.end(), range.begin,
                                [](const Use& use, uint32_t at) { return use.range.begin < at; });
  auto last =
      std::lower_bound(first, uses.end(), range.end, [](const Use& use, uint32_t at) { return use.range.begin < at; });
  return {first, last};
}

FileUsage collect_usage(const check::ProjectModel& model, check::SourceId source) {
  const SyntaxTree* tree = model.source(source).document->tree();
  return collect_usage(model, source, NodeList(tree ? tree->root() : SyntaxNode()));
}

FileUsage collect_usage(const check::ProjectModel& model, check::SourceId source, const NodeList& nodes) {
  FileUsage usage;
  UsageCollector(model, source, nodes, usage).run();
  return usage;
}

bool is_within(const check::Symbol* scope, const check::Symbol* pou) {
  for (int depth = 0; scope && depth < 64; scope = scope->owner, ++depth) {
    if (scope == pou) return true;
  }
  return false;
}

bool is_within_or_derived(const check::Symbol* scope, const check::Symbol* pou) {
  for (int depth = 0; scope && depth < 64; scope = scope->owner, ++depth) {
    int chain = 0;
    for (const check::Symbol* base = scope; base && chain < 32; base = base->base, ++chain) {
      if (base == pou) return true;
    }
  }
  return false;
}

}  // namespace rung::lint
