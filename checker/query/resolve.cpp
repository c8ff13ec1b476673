#include "checker/query/resolve.hpp"

#include "checker/semantic/body_checker.hpp"

namespace rung::check::query {
namespace {

// Names standing directly in these nodes name no declaration a query can lead to: jump labels,
// tasks, resources, SFC steps and action associations, namespace paths. Expressions below them
// (a transition's condition, an action's arguments) are fields of their own and stay expressions.
bool names_no_symbol(std::string_view parent_kind) {
  return parent_kind == "label" || parent_kind == "jmp_statement" || parent_kind == "il_label" ||
         parent_kind == "task_configuration" || parent_kind == "resource_declaration" ||
         parent_kind == "program_configuration" || parent_kind == "sfc_step" || parent_kind == "sfc_transition" ||
         parent_kind == "sfc_action_block" || parent_kind == "sfc_action" || parent_kind == "qualified_name" ||
         parent_kind == "namespace_declaration" || parent_kind == "using_directive" ||
         parent_kind == "task_association";
}

bool is_field(SyntaxNode parent, std::string_view field, SyntaxNode child) {
  for (SyntaxNode node : parent.children_by_field(field)) {
    if (node == child) return true;
  }
  return false;
}

// The expression part of a node `names_no_symbol` lists: conditions, priorities, arguments.
bool is_expression_field(SyntaxNode parent, SyntaxNode child) {
  return is_field(parent, "condition", child) || is_field(parent, "priority", child) ||
         is_field(parent, "argument", child);
}

// Types an expression of `scope` with the body checker; its findings are not wanted here.
ExprInfo type_in_scope(const ProjectModel& model, const Symbol& scope, SyntaxNode expression) {
  std::vector<Diagnostic> ignored;
  return BodyChecker(model, scope, ignored).type_of(expression);
}

// The POU a call goes to: a FUNCTION, METHOD, ACTION or PROGRAM named by `function`, or the type
// of the FB instance it names (the choice BodyChecker::type_call makes before it checks the
// arguments against the callee's parameters).
const Symbol* callee_of(const ProjectModel& model, const Symbol& scope, SyntaxNode function) {
  return query::callee_of(type_in_scope(model, scope, function));
}

// The declared variable a var_declaration node declares first (its type is every name's type).
const Symbol* first_declared(const ProjectModel& model, SourceId source, SyntaxNode declaration) {
  SyntaxNode name = declaration.child_by_field("name");
  return name ? symbol_declared_at(model, source, name.range()) : nullptr;
}

// What an argument list passes its named arguments to.
const Symbol* parameters_owner(const ProjectModel& model, SourceId source, const Symbol* scope,
                               SyntaxNode argument_list) {
  SyntaxNode owner = argument_list.parent();
  if (owner && owner.kind() == "argument_lists") owner = owner.parent();  // aFb : ARRAY .. OF FB[(..), (..)]
  if (!owner || !scope) return nullptr;
  const std::string_view kind = owner.kind();
  if (kind == "call_expression") return callee_of(model, *scope, owner.child_by_field("function"));
  if (kind == "program_configuration") {
    SyntaxNode type = owner.child_by_field("type");
    return type ? model.resolve_type_symbol(type, scope, nullptr) : nullptr;
  }
  if (kind == "var_declaration") {
    // fb : FB_X(a := 1): the arguments of FB_init (CODESYS), else the FB's inputs.
    const Symbol* variable = first_declared(model, source, owner);
    const Type* type = underlying(model.type_of(variable));
    if (type->kind == TypeKind::Array && type->element) type = underlying(type->element);
    if (type->kind != TypeKind::Pou || !type->declaration) return nullptr;
    const Symbol* init = model.find_member(type->declaration, "FB_init");
    return init ? init : type->declaration;
  }
  return nullptr;  // TASK t(INTERVAL := ...): task properties, no declarations
}

// The type an initial value, or one element or member value inside it, initialises.
const Type* initialized_type(const ProjectModel& model, SourceId source, SyntaxNode value, int depth) {
  SyntaxNode parent = value.parent();
  if (!parent || depth > 64) return nullptr;
  const std::string_view kind = parent.kind();
  if (kind == "var_declaration") return model.type_of(first_declared(model, source, parent));
  if (kind == "field_initializer") {
    // (member := value): the member's type, in the type the structure value initialises.
    SyntaxNode name = parent.child_by_field("name");
    const Type* outer = initialized_type(model, source, parent.parent(), depth + 1);
    const Symbol* container = outer ? underlying(outer)->declaration : nullptr;
    const Symbol* member = container && name ? model.find_member(container, name.text()) : nullptr;
    return member ? model.type_of(member) : nullptr;
  }
  if (kind == "repeated_initializer") return initialized_type(model, source, parent, depth + 1);  // 3(v): same level
  if (kind == "array_initializer") {
    const Type* array = initialized_type(model, source, parent, depth + 1);
    array = array ? underlying(array) : nullptr;
    return array && array->kind == TypeKind::Array ? array->element : nullptr;
  }
  // TYPE ST : STRUCT ... END_STRUCT := (a := 1); TYPE T : INT := 5;
  if (SyntaxNode name = parent.child_by_field("name"); name && parent.child_by_field("value") == value) {
    if (const Symbol* type = symbol_declared_at(model, source, name.range())) return model.type_of(type);
  }
  return nullptr;
}

}  // namespace

const Symbol* callee_of(const ExprInfo& info) {
  if (const Symbol* symbol = info.symbol) {
    if (symbol->kind == SymbolKind::Function || symbol->kind == SymbolKind::Method ||
        symbol->kind == SymbolKind::Action || symbol->kind == SymbolKind::Program) {
      return symbol;
    }
  }
  if (!info.type) return nullptr;
  const Type* type = underlying(info.type);
  if (type->kind == TypeKind::Reference && type->element) type = underlying(type->element);
  if (type->kind == TypeKind::Pou && !info.names_type) return type->declaration;
  return nullptr;
}

const Symbol* symbol_declared_at(const ProjectModel& model, SourceId source, TextRange name_range) {
  for (const Symbol& symbol : model.source(source).symbols.storage) {
    if (!symbol.name.empty() && symbol.name_range.begin == name_range.begin &&
        symbol.name_range.end == name_range.end) {
      return &symbol;
    }
  }
  return nullptr;
}

const Symbol* canonical_symbol(const ProjectModel& model, const Symbol* symbol) {
  if (symbol && symbol->kind == SymbolKind::Variable && symbol->section == ast::VarSection::External) {
    if (const Symbol* global = model.find_global_variable(symbol->name)) return global;
  }
  return symbol;
}

NameSite name_site(const ProjectModel& model, SourceId source, SyntaxNode name) {
  if (name.kind() == "il_operator") return {.use = NameUse::IlOperator};
  SyntaxNode parent = name.parent();
  if (!parent) return {};
  const std::string_view kind = parent.kind();
  if (kind == "type_name") {
    // Lib.T: only the last part names the type; the qualifier is a library namespace.
    return {.use = name.end() == parent.end() ? NameUse::TypeName : NameUse::Other};
  }
  if (kind == "member_expression") {
    // obj.member: typing the member expression resolves the member in the object's type.
    return {.use = NameUse::Expression, .expression = parent.child_by_field("member") == name ? parent : name};
  }
  if (kind == "typed_literal") return {.use = NameUse::Expression, .expression = parent};  // E_Color#Red
  if (kind == "dereference_expression" && (names_equal(name.text(), "THIS") || names_equal(name.text(), "SUPER"))) {
    return {.use = NameUse::Expression, .expression = parent};
  }
  if (kind == "global_reference") return {.use = NameUse::GlobalReference};
  const bool is_name_field = parent.child_by_field("name") == name;
  if (is_name_field && (kind == "argument" || kind == "output_argument")) return {.use = NameUse::Parameter};
  if (is_name_field && kind == "field_initializer") return {.use = NameUse::InitializedMember};
  if (is_name_field) {
    // Every other `name` field declares something; names without a symbol (an inline STRUCT's
    // fields, an implicit enum's values, labels, tasks) lead nowhere.
    const Symbol* declared = symbol_declared_at(model, source, name.range());
    return {.use = declared ? NameUse::Declaration : NameUse::Other, .declared = declared};
  }
  if (names_no_symbol(kind) && !is_expression_field(parent, name)) return {};
  return {.use = NameUse::Expression, .expression = name};
}

const Symbol* resolve_name(const ProjectModel& model, SourceId source, SyntaxNode name, const Symbol* scope) {
  const NameSite site = name_site(model, source, name);
  const Symbol* found = nullptr;
  switch (site.use) {
    case NameUse::Declaration: found = site.declared; break;
    case NameUse::TypeName: found = scope ? model.resolve_type_symbol(name.parent(), scope, nullptr) : nullptr; break;
    case NameUse::Expression: {
      if (!scope) return nullptr;
      const ExprInfo info = type_in_scope(model, *scope, site.expression);
      const SyntaxNode literal = site.expression.kind() == "typed_literal" ? site.expression : SyntaxNode();
      if (literal && literal.child_by_field("type") == name) {
        // E_Color#Red with the cursor on E_Color: the enumeration, not its value.
        found = underlying(info.type)->kind == TypeKind::Enum ? info.type->declaration : nullptr;
      } else {
        found = info.symbol;
      }
      break;
    }
    case NameUse::Parameter: {
      const Symbol* owner = parameters_owner(model, source, scope, name.parent().parent());
      found = owner ? model.find_member(owner, name.text()) : nullptr;
      break;
    }
    case NameUse::InitializedMember: {
      // The structure value around the member: what it initialises holds the member.
      const Type* type = initialized_type(model, source, name.parent().parent(), 0);
      const Symbol* container = type ? underlying(type)->declaration : nullptr;
      found = container ? model.find_member(container, name.text()) : nullptr;
      break;
    }
    case NameUse::GlobalReference: found = model.find_global_variable(name.text()); break;
    case NameUse::IlOperator: {
      const Symbol* callee = scope ? model.lookup(scope, name.text()) : nullptr;
      found = callee && is_callable_kind(callee->kind) ? callee : nullptr;
      break;
    }
    case NameUse::Other: return nullptr;
  }
  return canonical_symbol(model, found);
}

}  // namespace rung::check::query
