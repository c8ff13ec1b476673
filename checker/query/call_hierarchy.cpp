#include "checker/query/call_hierarchy.hpp"

#include <algorithm>
#include <set>
#include <unordered_set>

#include "checker/query/definition.hpp"
#include "checker/query/position.hpp"
#include "checker/query/references.hpp"
#include "checker/query/resolve.hpp"
#include "checker/semantic/body_checker.hpp"
#include "parser/keywords.hpp"

namespace rung::check::query {
namespace {

constexpr int kMaxDepth = 64;

bool is_block(const Symbol& symbol) {
  return symbol.kind == SymbolKind::FunctionBlock || symbol.kind == SymbolKind::Class;
}

bool is_accessor(const Symbol& symbol) {
  return symbol.kind == SymbolKind::Method && symbol.owner && symbol.owner->kind == SymbolKind::Property;
}

bool is_cal(SyntaxNode op) {
  if (!op) return false;
  const std::string word = keywords::upper(op.text());
  return word == "CAL" || word == "CALC" || word == "CALCN";
}

// The block a function block instance holds, through ARRAY OF, POINTER TO and REFERENCE TO.
const Symbol* block_of_instance(const ProjectModel& model, const Symbol& variable) {
  const Type* type = underlying(model.type_of(&variable));
  for (int depth = 0;
       depth < 16 && type && type->element &&
       (type->kind == TypeKind::Array || type->kind == TypeKind::Pointer || type->kind == TypeKind::Reference);
       ++depth) {
    type = underlying(type->element);
  }
  if (!type || type->kind != TypeKind::Pou || !type->declaration || !is_block(*type->declaration)) return nullptr;
  return type->declaration;
}

// The hierarchy item a scope stands for: a GET or SET is its property.
const Symbol* item_of(const Symbol* scope) {
  return scope && is_accessor(*scope) ? scope->owner : scope;
}

// The part of a called expression that names the callee: `fb` in fb(), `Start` in fb.Start(),
// `aFb` in aFb[i](), `p` in p^().
SyntaxNode called_name(SyntaxNode function) {
  for (int depth = 0; function && depth < kMaxDepth; ++depth) {
    const std::string_view kind = function.kind();
    SyntaxNode inner;
    if (kind == "member_expression") {
      inner = function.child_by_field("member");
      return inner ? inner : function;
    }
    if (kind == "index_expression") inner = function.child_by_field("object");
    if (kind == "dereference_expression") inner = function.child_by_field("operand");
    if (kind == "parenthesized_expression") inner = function.named_child(0);
    if (!inner) return function;
    function = inner;
  }
  return function;
}

// The called expression `name` is part of, when it names what a call calls: the function part of
// a call, the operand of IL CAL, an IL operator naming a function. Null otherwise.
SyntaxNode call_site_of(SyntaxNode name) {
  if (name.kind() == "il_operator") return keywords::is_il_operator(name.text()) ? SyntaxNode() : name;
  SyntaxNode node = name;
  for (int depth = 0; depth < kMaxDepth; ++depth) {
    SyntaxNode parent = node.parent();
    if (!parent) break;
    const std::string_view kind = parent.kind();
    const bool part_of_callee = (kind == "member_expression" && parent.child_by_field("member") == node) ||
                                (kind == "index_expression" && parent.child_by_field("object") == node) ||
                                kind == "dereference_expression" || kind == "parenthesized_expression";
    if (part_of_callee) {
      node = parent;
      continue;
    }
    if (kind == "call_expression" && parent.child_by_field("function") == node) return node;
    if (kind == "il_instruction" && parent.child_by_field("operand") == node &&
        is_cal(parent.child_by_field("operator"))) {
      return node;
    }
    break;
  }
  return {};
}

// What a call site calls, read in `scope`.
const Symbol* callee_at(const ProjectModel& model, SourceId source, const Symbol& scope, BodyChecker& checker,
                        SyntaxNode site) {
  if (site.kind() == "il_operator") {
    const Symbol* callee = resolve_name(model, source, site, &scope);
    return callee && is_callable_kind(callee->kind) ? callee : nullptr;
  }
  return callee_of(checker.type_of(site));
}

// The bodies written for `symbol`: its body, a snippet's statement runs, a property's GET and SET.
std::vector<std::pair<const Symbol*, SyntaxNode>> bodies_of(const Symbol& symbol) {
  std::vector<std::pair<const Symbol*, SyntaxNode>> bodies;
  if (symbol.kind == SymbolKind::Property) {
    for (const Symbol* accessor : symbol.ordered) {
      if (is_accessor(*accessor) && accessor->node)
        bodies.emplace_back(accessor, accessor->node.child_by_field("body"));
    }
  } else if (symbol.node && symbol.node.kind() == "source_file") {
    for (SyntaxNode child : symbol.node.named_children()) {
      const std::string_view kind = child.kind();
      if (kind == "statement_list" || kind == "il_body" || kind == "sfc_network") bodies.emplace_back(&symbol, child);
    }
  } else if (symbol.node) {
    bodies.emplace_back(&symbol, symbol.node.child_by_field("body"));
  }
  return bodies;
}

// The action an SFC step association (A1(N);) in `pou` names.
const Symbol* associated_action(const ProjectModel& model, const Symbol& pou, SyntaxNode association) {
  SyntaxNode name = association.child_by_field("name");
  const Symbol* action = name ? model.find_member(&pou, name.text()) : nullptr;
  return action && action->kind == SymbolKind::Action ? action : nullptr;
}

class OutgoingCollector {
 public:
  OutgoingCollector(const ProjectModel& model, const Symbol& caller, std::vector<Call>& out)
      : model_(model), caller_(caller), out_(out) {}

  void collect(const Symbol& scope, SyntaxNode body) {
    std::vector<Diagnostic> ignored;
    BodyChecker checker(model_, scope, ignored);
    walk_preorder(body, [&](SyntaxNode node) {
      if (!node.is_named()) return false;
      const std::string_view kind = node.kind();
      if (kind == "sfc_action_block" && node != body) return false;  // an action of its own
      if (kind == "call_expression") {
        add(scope.source, callee_of(checker.type_of(node.child_by_field("function"))), node.child_by_field("function"));
      } else if (kind == "il_instruction") {
        add_il(scope, checker, node);
      } else if (kind == "sfc_action") {
        add(scope.source, associated_action(model_, scope, node), node.child_by_field("name"));
      }
      return true;
    });
  }

 private:
  void add_il(const Symbol& scope, BodyChecker& checker, SyntaxNode instruction) {
    SyntaxNode op = instruction.child_by_field("operator");
    if (!op) return;
    if (is_cal(op)) {
      SyntaxNode operand = instruction.child_by_field("operand");
      // CAL fb(...) holds a call expression, which the walk visits itself.
      if (operand && operand.kind() != "call_expression")
        add(scope.source, callee_at(model_, scope.source, scope, checker, operand), operand);
    } else if (!keywords::is_il_operator(op.text())) {
      add(scope.source, callee_at(model_, scope.source, scope, checker, op), op);
    }
  }

  void add(SourceId source, const Symbol* callee, SyntaxNode function) {
    if (!callee || !function) return;
    out_.push_back({.caller = &caller_,
                    .callee = callee,
                    .where = location_in_file(model_, source, called_name(function).range())});
  }

  const ProjectModel& model_;
  const Symbol& caller_;
  std::vector<Call>& out_;
};

// The tree node of a reference's name.
SyntaxNode name_node_of(const ProjectModel& model, const Location& location) {
  const Document& document = *model.source(location.source).document;
  const std::optional<uint32_t> at = document.tree_offset_of(location.range.begin);
  return at && document.tree() ? name_at(document.tree()->root(), *at) : SyntaxNode();
}

// The function block instances declared with `block` as their type (through ARRAY OF and
// references too): the variables whose calls are calls of the block.
std::vector<const Symbol*> instances_of(const Workspace& workspace, const Symbol& block) {
  const ProjectModel& model = workspace.model();
  std::vector<const Symbol*> instances;
  for (const Location& use : find_references(workspace, &block, false)) {
    SyntaxNode node = name_node_of(model, use);
    for (int depth = 0; node && node.kind() != "var_declaration" && depth < 8; ++depth) node = node.parent();
    if (!node || node.kind() != "var_declaration") continue;
    for (SyntaxNode name : ast::VarDeclaration(node).names()) {
      const Symbol* variable = canonical_symbol(model, symbol_declared_at(model, use.source, name.range()));
      if (variable && variable->kind == SymbolKind::Variable && block_of_instance(model, *variable) == &block &&
          std::find(instances.begin(), instances.end(), variable) == instances.end()) {
        instances.push_back(variable);
      }
    }
  }
  return instances;
}

// The blocks some other block EXTENDS: a derived block may use its base's variables.
std::unordered_set<const Symbol*> extended_blocks(const ProjectModel& model) {
  std::unordered_set<const Symbol*> extended;
  for (SourceId id = 0; id < model.source_count(); ++id) {
    for (const Symbol* top : model.source(id).symbols.top_level) {
      if (is_block(*top)) extended.insert(top->bases.begin(), top->bases.end());
    }
  }
  return extended;
}

// Whether only `variable`'s own file can name it: a local of a FUNCTION or METHOD, or a VAR of a
// block no other block extends. Its calls are then searched in that file alone.
bool named_in_own_file_only(const Symbol& variable, const std::unordered_set<const Symbol*>& extended) {
  const Symbol* owner = variable.owner;
  if (!owner) return false;
  if (owner->kind == SymbolKind::Function || owner->kind == SymbolKind::Method) return true;
  const ast::VarSection section = variable.section;
  const bool private_section = section == ast::VarSection::Var || section == ast::VarSection::Temp ||
                               section == ast::VarSection::Stat || section == ast::VarSection::Inst;
  return is_block(*owner) && private_section && !extended.contains(owner);
}

// Step associations A1(N); naming `action` in the SFC body of its POU.
void add_step_associations(const ProjectModel& model, const Symbol& action, std::vector<Call>& out) {
  const Symbol* pou = action.owner;
  SyntaxNode body = pou && pou->node ? pou->node.child_by_field("body") : SyntaxNode();
  if (!body || body.kind() != "sfc_network") return;
  for (SyntaxNode step : body.children_of_kind("sfc_step")) {
    for (SyntaxNode association : step.children_of_kind("sfc_action")) {
      if (associated_action(model, *pou, association) != &action) continue;
      out.push_back({.caller = pou,
                     .callee = &action,
                     .where = location_in_file(model, pou->source, association.child_by_field("name").range())});
    }
  }
}

}  // namespace

bool takes_part_in_calls(const Symbol& symbol) {
  switch (symbol.kind) {
    case SymbolKind::Program:
    case SymbolKind::Function:
    case SymbolKind::FunctionBlock:
    case SymbolKind::Class:
    case SymbolKind::Property:
    case SymbolKind::Action:
    case SymbolKind::Transition: return true;
    case SymbolKind::Method: return !is_accessor(symbol);
    default: return false;
  }
}

const Symbol* call_hierarchy_symbol_at(const Workspace& workspace, SourceId source, uint32_t file_offset) {
  const ProjectModel& model = workspace.model();
  const std::optional<QueryPoint> point = query_point(workspace, source, file_offset);
  if (!point) return nullptr;
  // Not on a name: the POU the cursor is in.
  const Symbol* symbol = point->name ? symbol_at(workspace, source, file_offset) : item_of(point->scope);
  if (symbol && symbol->kind == SymbolKind::Variable) symbol = block_of_instance(model, *symbol);
  symbol = item_of(symbol);
  return symbol && takes_part_in_calls(*symbol) ? symbol : nullptr;
}

std::vector<Call> outgoing_calls(const Workspace& workspace, const Symbol& caller) {
  std::vector<Call> calls;
  OutgoingCollector collector(workspace.model(), caller, calls);
  for (const auto& [scope, body] : bodies_of(caller)) {
    if (body) collector.collect(*scope, body);
  }
  std::stable_sort(calls.begin(), calls.end(),
                   [](const Call& a, const Call& b) { return a.where.range.begin < b.where.range.begin; });
  return calls;
}

std::vector<Call> incoming_calls(const Workspace& workspace, const Symbol& callee,
                                 const std::function<bool()>& cancelled) {
  const ProjectModel& model = workspace.model();
  std::vector<Call> calls;
  // The names a call of `callee` is written with: its own, or its instances'.
  std::vector<const Symbol*> names{&callee};
  std::unordered_set<const Symbol*> extended;
  if (is_block(callee)) {
    names = instances_of(workspace, callee);
    extended = extended_blocks(model);
  }
  std::set<std::pair<SourceId, uint32_t>> seen;
  for (const Symbol* name : names) {
    if (cancelled && cancelled()) return calls;
    const std::vector<Location> uses = name != &callee && named_in_own_file_only(*name, extended)
                                           ? find_references_in(workspace, name, name->source, false)
                                           : find_references(workspace, name, false);
    for (const Location& use : uses) {
      if (cancelled && cancelled()) return calls;
      const SyntaxNode node = name_node_of(model, use);
      const SyntaxNode site = node ? call_site_of(node) : SyntaxNode();
      if (!site || !seen.emplace(use.source, site.begin()).second) continue;
      const Symbol* scope = scope_at(model, use.source, site.begin());
      if (!scope) continue;
      std::vector<Diagnostic> ignored;
      BodyChecker checker(model, *scope, ignored);
      if (callee_at(model, use.source, *scope, checker, site) != &callee) continue;
      calls.push_back({.caller = item_of(scope),
                       .callee = &callee,
                       .where = location_in_file(model, use.source, called_name(site).range())});
    }
  }
  if (callee.kind == SymbolKind::Action) add_step_associations(model, callee, calls);
  std::sort(calls.begin(), calls.end(), [](const Call& a, const Call& b) {
    return a.where.path != b.where.path ? a.where.path < b.where.path : a.where.range.begin < b.where.range.begin;
  });
  return calls;
}

}  // namespace rung::check::query
