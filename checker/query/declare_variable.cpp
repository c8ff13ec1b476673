#include "checker/query/declare_variable.hpp"

#include "checker/query/call_site.hpp"
#include "checker/query/position.hpp"
#include "checker/query/resolve.hpp"
#include "checker/query/source_edits.hpp"
#include "checker/semantic/body_checker.hpp"
#include "parser/keywords.hpp"

namespace rung::check::query {
namespace {

constexpr int kMaxDepth = 16;

bool is_comparison(std::string_view op) {
  return op == "=" || op == "<>" || op == "<" || op == ">" || op == "<=" || op == ">=";
}

// How a type is written in a declaration; "" for what cannot be declared (a generic ANY_NUM, a
// FUNCTION's "instance", a subrange only its declaration can spell).
std::string spelled(const Type* type) {
  if (!type) return {};
  switch (type->kind) {
    case TypeKind::Unknown:
    case TypeKind::Void:
    case TypeKind::Null:
    case TypeKind::Generic:
    case TypeKind::Subrange: return {};
    case TypeKind::Pou: {
      const Symbol* block = type->declaration;
      const bool instance = block && (block->kind == SymbolKind::FunctionBlock || block->kind == SymbolKind::Class ||
                                      block->kind == SymbolKind::Interface);
      return instance ? std::string(block->name) : std::string();
    }
    case TypeKind::String:
    case TypeKind::WString:
      if (type->length == TypeArena::kDefaultStringLength || type->length == 0) {
        return type->kind == TypeKind::String ? "STRING" : "WSTRING";
      }
      return type->name;
    default: return type->name;
  }
}

// The type an untyped literal gets in a declaration: the IEC defaults INT, REAL, STRING rather
// than the smallest type that holds the value (a literal 5 is no reason for a USINT).
std::string literal_default(const ExprInfo& info) {
  if (!info.value || info.based_literal) return spelled(info.type);
  switch (info.value->kind) {
    case ConstValue::Kind::Integer: {
      const __int128 v = info.value->integer;
      if (v >= -32768 && v <= 32767) return "INT";
      if (v >= -2147483648LL && v <= 2147483647LL) return "DINT";
      return "LINT";
    }
    case ConstValue::Kind::Real: return "REAL";
    case ConstValue::Kind::String: return underlying(info.type)->kind == TypeKind::WString ? "WSTRING" : "STRING";
    default: return spelled(info.type);
  }
}

class TypeGuess {
 public:
  TypeGuess(const ProjectModel& model, const Symbol& scope) : model_(model), checker_(model, scope, ignored_) {}

  // The type `expression` must have where it stands.
  std::string expected(SyntaxNode expression, int depth = 0) {
    SyntaxNode parent = expression.parent();
    while (parent && parent.kind() == "parenthesized_expression") {
      expression = parent;
      parent = parent.parent();
    }
    if (!parent || depth > kMaxDepth) return {};
    const std::string_view kind = parent.kind();
    if (kind == "assignment_statement" || kind == "assignment_expression") {
      SyntaxNode left = parent.child_by_field("left");
      SyntaxNode right = parent.child_by_field("right");
      if (expression == right) return of(left);
      while (right && right.kind() == "assignment_expression") right = right.child_by_field("right");
      return right ? of_operands(right) : std::string();
    }
    if (kind == "binary_expression") return from_operand(parent, expression, depth);
    if (kind == "unary_expression") {
      const std::string op = ast::operator_of(parent);
      if (op == "NOT") {
        const std::string outer = expected(parent, depth + 1);
        return outer.empty() ? "BOOL" : outer;
      }
      return op == "-" || op == "+" ? expected(parent, depth + 1) : std::string();
    }
    if (kind == "if_statement" || kind == "elsif_clause" || kind == "while_statement" || kind == "repeat_statement" ||
        kind == "return_statement") {
      return parent.child_by_field("condition") == expression ? "BOOL" : std::string();
    }
    if (kind == "for_statement") return in_for(parent, expression);
    if (kind == "case_statement" && parent.child_by_field("value") == expression) {
      const SyntaxNode element = parent.first_child_of_kind("case_element");
      const SyntaxNode label = element ? element.child_by_field("label") : SyntaxNode();
      return label && label.kind() != "range" ? of(label) : "INT";
    }
    if (kind == "index_expression" && parent.child_by_field("object") != expression) return "INT";
    if (kind == "argument" || kind == "output_argument") return parameter_type(parent, expression);
    return {};
  }

 private:
  std::string of(SyntaxNode expression) {
    if (!expression) return {};
    const ExprInfo info = checker_.type_of(expression);
    if (info.untyped_literal) return literal_default(info);
    // A variable's type as its declaration writes it (ARRAY[1..N] OF ST_Point keeps its N).
    const Symbol* symbol = info.symbol;
    const std::string_view kind = expression.kind();
    if (symbol && symbol->kind == SymbolKind::Variable && symbol->type_node &&
        (kind == "identifier" || kind == "member_expression") && model_.type_of(symbol) == info.type &&
        symbol->type_node.text().find_first_of("(\r\n") == std::string_view::npos) {
      return std::string(symbol->type_node.text());
    }
    return spelled(info.type);
  }

  // The type of an expression, or when it cannot be typed (x + 1 with x undeclared) the type
  // of its first operand that has one: x := x + 1 makes x an INT.
  std::string of_operands(SyntaxNode expression, int depth = 0) {
    std::string type = of(expression);
    if (!type.empty() || !expression || depth > kMaxDepth) return type;
    const std::string_view kind = expression.kind();
    if (kind == "parenthesized_expression") return of_operands(expression.named_child(0), depth + 1);
    if (kind == "unary_expression") return of_operands(expression.child_by_field("operand"), depth + 1);
    if (kind != "binary_expression" || is_comparison(ast::operator_of(expression))) return {};
    type = of_operands(expression.child_by_field("left"), depth + 1);
    return type.empty() ? of_operands(expression.child_by_field("right"), depth + 1) : type;
  }

  // a + x, x = E_State.Idle, a AND x: the other operand's type; an untyped literal there only
  // when the whole expression's place tells nothing more (x + 1 assigned to a REAL is REAL).
  std::string from_operand(SyntaxNode binary, SyntaxNode expression, int depth) {
    const SyntaxNode left = binary.child_by_field("left");
    const SyntaxNode other = left == expression ? binary.child_by_field("right") : left;
    if (!other) return {};
    const ExprInfo info = checker_.type_of(other);
    if (is_comparison(ast::operator_of(binary)) || (!info.untyped_literal && !info.type->is_unknown())) return of(other);
    const std::string outer = expected(binary, depth + 1);
    return outer.empty() ? of(other) : outer;
  }

  std::string in_for(SyntaxNode loop, SyntaxNode expression) {
    const SyntaxNode variable = loop.child_by_field("variable");
    if (expression != variable) return of(variable);
    for (const char* bound : {"start", "end"}) {
      const SyntaxNode value = loop.child_by_field(bound);
      if (value && !checker_.type_of(value).untyped_literal) {
        std::string type = of(value);
        if (!type.empty()) return type;
      }
    }
    return "INT";
  }

  // The declared type of the parameter an argument is passed to.
  std::string parameter_type(SyntaxNode argument, SyntaxNode expression) {
    const bool output = argument.kind() == "output_argument";
    if (argument.child_by_field(output ? "target" : "value") != expression) return {};
    const SyntaxNode list = argument.parent();
    const SyntaxNode call = list ? list.parent() : SyntaxNode();
    if (!call || call.kind() != "call_expression") return {};
    const Symbol* callee = callee_of(checker_.type_of(call.child_by_field("function")));
    if (!callee) return {};
    const Symbol* parameter = nullptr;
    if (const SyntaxNode name = argument.child_by_field("name"); name) {
      parameter = named_parameter(call_parameters(callee), name.text());
    } else {
      const std::vector<CallArgument> arguments = call_arguments(list);
      const std::vector<const Symbol*> inputs = positional_parameters(callee);
      for (size_t i = 0; i < arguments.size() && i < inputs.size(); ++i) {
        if (arguments[i].node == argument) parameter = inputs[i];
      }
    }
    if (!parameter) return {};
    const Type* type = model_.type_of(parameter);
    if (spelled(type).empty()) return {};
    return parameter->type_node && parameter->type_node.text().find_first_of("(\r\n") == std::string_view::npos
               ? std::string(parameter->type_node.text())
               : spelled(type);
  }

  const ProjectModel& model_;
  std::vector<Diagnostic> ignored_;
  BodyChecker checker_;
};

// A name that stands for a variable where it is written: not a called POU, not obj in obj.x
// (an unknown qualifier is more often a missing library than a missing variable).
bool is_variable_use(SyntaxNode name) {
  const SyntaxNode parent = name.parent();
  if (!parent) return false;
  const std::string_view kind = parent.kind();
  if (kind == "call_expression" || kind == "global_reference") return false;
  if (kind == "member_expression") return false;
  return kind != "call_statement";
}

// Where a variable used in `scope` is declared: actions and transitions have no VAR blocks.
const Symbol* declaring_pou(const Symbol* scope) {
  while (scope && (scope->kind == SymbolKind::Action || scope->kind == SymbolKind::Transition)) scope = scope->owner;
  if (!scope || !is_pou_kind(scope->kind) || scope->kind == SymbolKind::Interface || !scope->node) return nullptr;
  return scope;
}

int section_rank(ast::VarSection section) {
  switch (section) {
    case ast::VarSection::Input: return 0;
    case ast::VarSection::Output: return 1;
    case ast::VarSection::InOut: return 2;
    default: return 3;
  }
}

bool starts_line(std::string_view text, uint32_t offset) { return is_blank(text, line_start_at(text, offset), offset); }

// How far a declaration is indented past its VAR keyword in this file: as in the POU's own blocks,
// else as in any block of the file, else one indentation unit of [format].
std::string declaration_step(std::string_view text, SyntaxNode pou, const project::FormatSettings& settings) {
  std::vector<SyntaxNode> blocks = pou.children_of_kind("var_block");
  for (SyntaxNode top = pou.parent() ? pou.parent().named_child(0) : SyntaxNode(); top; top = top.next_named_sibling()) {
    for (const SyntaxNode block : top.children_of_kind("var_block")) blocks.push_back(block);
  }
  for (const SyntaxNode block : blocks) {
    for (const ast::VarDeclaration& declaration : ast::VarBlock(block).declarations()) {
      const uint32_t at = declaration.node().begin();
      if (!starts_line(text, at) || !starts_line(text, block.begin())) continue;
      const std::string_view outer = indentation_at(text, block.begin());
      const std::string_view inner = indentation_at(text, at);
      if (inner.size() > outer.size() && inner.starts_with(outer)) return std::string(inner.substr(outer.size()));
    }
  }
  return indent_unit(settings);
}

SyntaxNode last_keyword(SyntaxNode node, std::string_view keyword) {
  for (uint32_t i = node.child_count(); i-- > 0;) {
    if (!node.child(i).is_named() && keywords::upper(node.child(i).text()) == keyword) return node.child(i);
  }
  return {};
}

// The end of a POU's header: its name, result type, modifiers, EXTENDS and IMPLEMENTS.
uint32_t header_end(SyntaxNode pou) {
  uint32_t end = pou.begin();
  for (uint32_t i = 0; i < pou.child_count(); ++i) {
    const SyntaxNode child = pou.child(i);
    if (child.is_extra()) continue;
    const std::string_view kind = child.kind();
    if (kind == "var_block" || pou.field_name_of_child(i) == "body" || kind.ends_with("_declaration") ||
        keywords::upper(kind).starts_with("END_")) {
      break;
    }
    end = child.end();
  }
  return end;
}

}  // namespace

std::optional<UndeclaredVariable> undeclared_variable_at(const Workspace& workspace, SourceId source,
                                                         uint32_t file_offset) {
  const ProjectModel& model = workspace.model();
  const std::optional<QueryPoint> point = query_point(workspace, source, file_offset);
  if (!point || !point->scope || !point->name || point->name.kind() != "identifier") return std::nullopt;
  const SyntaxNode name = point->name;
  if (!is_variable_use(name) || name_site(model, source, name).use != NameUse::Expression) return std::nullopt;
  if (model.lookup(point->scope, name.text()) || model.has_unresolved_base(point->scope)) return std::nullopt;
  const Symbol* pou = declaring_pou(point->scope);
  if (!pou) return std::nullopt;
  std::string type = TypeGuess(model, *point->scope).expected(name);
  if (type.empty()) return std::nullopt;
  return UndeclaredVariable{std::string(name.text()), std::move(type), pou};
}

std::optional<lint::TextEdit> declare_variable(const Workspace& workspace, const UndeclaredVariable& variable,
                                               ast::VarSection section, const project::FormatSettings& settings) {
  const Document& document = *workspace.model().source(variable.pou->source).document;
  if (!document.tree()) return std::nullopt;
  const std::string_view text = document.tree()->text();
  const SyntaxNode pou = variable.pou->node;
  const std::string unit = declaration_step(text, pou, settings);
  const std::string declaration = variable.name + " : " + variable.type + ";";
  const std::string newline(line_end_at(text, pou.begin()));
  const std::vector<SyntaxNode> blocks = pou.children_of_kind("var_block");
  const SyntaxNode pou_keyword = pou.child(0);

  lint::TextEdit edit;
  SyntaxNode target;
  for (const SyntaxNode block : blocks) {
    if (ast::VarBlock(block).section() == section && block.children_of_kind("var_qualifier").empty() &&
        !block.has_error()) {
      target = block;
    }
  }
  if (target) {
    const SyntaxNode end_var = last_keyword(target, "END_VAR");
    if (!end_var) return std::nullopt;
    const std::vector<ast::VarDeclaration> declarations = ast::VarBlock(target).declarations();
    std::string indentation = std::string(indentation_at(text, target.begin())) + unit;
    if (!declarations.empty() && starts_line(text, declarations.back().node().begin())) {
      indentation = indentation_at(text, declarations.back().node().begin());
    }
    if (starts_line(text, end_var.begin())) {
      const uint32_t at = line_start_at(text, end_var.begin());
      edit = {{at, at}, indentation + declaration + newline};
    } else {
      edit = {{end_var.begin(), end_var.begin()}, declaration + " "};
    }
  } else {
    const std::string indentation(indentation_at(text, pou.begin()));
    const std::string block = indentation + keyword_in_case(ast::var_section_name(section), settings, pou_keyword.text()) +
                              newline + indentation + unit + declaration + newline + indentation +
                              keyword_in_case("END_VAR", settings, pou_keyword.text());
    const SyntaxNode* later = nullptr;
    for (const SyntaxNode& b : blocks) {
      if (section_rank(ast::VarBlock(b).section()) > section_rank(section)) {
        later = &b;
        break;
      }
    }
    if (later && starts_line(text, later->begin())) {
      const uint32_t at = line_start_at(text, later->begin());
      edit = {{at, at}, block + newline};
    } else {
      const uint32_t after = blocks.empty() ? header_end(pou) : blocks.back().end();
      const uint32_t at = line_end_offset_at(text, after);
      edit = {{at, at}, newline + block};
    }
  }
  const std::optional<std::vector<lint::TextEdit>> mapped = file_edits_of(document, {edit});
  if (!mapped) return std::nullopt;
  return mapped->front();
}

}  // namespace rung::check::query
