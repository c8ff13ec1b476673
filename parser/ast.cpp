#include "parser/ast.hpp"

#include <cctype>
#include <string>

#include "parser/keywords.hpp"

namespace rung::ast {
namespace {

using keywords::upper;

bool pou_kind_of(std::string_view node_kind, PouKind* out) {
  struct Row {
    std::string_view node;
    PouKind kind;
  };
  static constexpr Row kRows[] = {
      {"program_declaration", PouKind::Program},
      {"function_declaration", PouKind::Function},
      {"function_block_declaration", PouKind::FunctionBlock},
      {"method_declaration", PouKind::Method},
      {"property_declaration", PouKind::Property},
      {"property_accessor", PouKind::PropertyAccessor},
      {"interface_declaration", PouKind::Interface},
      {"action_declaration", PouKind::Action},
      {"transition_declaration", PouKind::Transition},
      {"class_declaration", PouKind::Class},
  };
  for (const auto& row : kRows) {
    if (row.node == node_kind) {
      *out = row.kind;
      return true;
    }
  }
  return false;
}

bool is_member_kind(PouKind k) {
  return k == PouKind::Method || k == PouKind::Property || k == PouKind::Action || k == PouKind::Transition ||
         k == PouKind::PropertyAccessor;
}

bool can_own_members(PouKind k) {
  return k == PouKind::Program || k == PouKind::FunctionBlock || k == PouKind::Class || k == PouKind::Interface ||
         k == PouKind::Function || k == PouKind::Property;
}

}  // namespace

std::string_view pou_kind_name(PouKind kind) {
  switch (kind) {
    case PouKind::Program: return "PROGRAM";
    case PouKind::Function: return "FUNCTION";
    case PouKind::FunctionBlock: return "FUNCTION_BLOCK";
    case PouKind::Method: return "METHOD";
    case PouKind::Property: return "PROPERTY";
    case PouKind::PropertyAccessor: return "PROPERTY ACCESSOR";
    case PouKind::Interface: return "INTERFACE";
    case PouKind::Action: return "ACTION";
    case PouKind::Transition: return "TRANSITION";
    case PouKind::Class: return "CLASS";
  }
  return "POU";
}

std::string_view var_section_name(VarSection section) {
  switch (section) {
    case VarSection::Var: return "VAR";
    case VarSection::Input: return "VAR_INPUT";
    case VarSection::Output: return "VAR_OUTPUT";
    case VarSection::InOut: return "VAR_IN_OUT";
    case VarSection::Global: return "VAR_GLOBAL";
    case VarSection::External: return "VAR_EXTERNAL";
    case VarSection::Temp: return "VAR_TEMP";
    case VarSection::Stat: return "VAR_STAT";
    case VarSection::Inst: return "VAR_INST";
    case VarSection::Config: return "VAR_CONFIG";
    case VarSection::Access: return "VAR_ACCESS";
    case VarSection::Unknown: return "VAR?";
  }
  return "VAR?";
}

VarSection VarBlock::section() const {
  SyntaxNode kw = node_.child_by_field("kind");
  std::string k = upper(kw ? kw.kind() : std::string_view());
  if (k == "VAR") return VarSection::Var;
  if (k == "VAR_INPUT") return VarSection::Input;
  if (k == "VAR_OUTPUT") return VarSection::Output;
  if (k == "VAR_IN_OUT") return VarSection::InOut;
  if (k == "VAR_GLOBAL") return VarSection::Global;
  if (k == "VAR_EXTERNAL") return VarSection::External;
  if (k == "VAR_TEMP") return VarSection::Temp;
  if (k == "VAR_STAT") return VarSection::Stat;
  if (k == "VAR_INST") return VarSection::Inst;
  if (k == "VAR_CONFIG") return VarSection::Config;
  if (k == "VAR_ACCESS") return VarSection::Access;
  return VarSection::Unknown;
}

bool VarBlock::has_qualifier(std::string_view qualifier) const {
  for (SyntaxNode q : node_.children_of_kind("var_qualifier")) {
    if (upper(q.text()) == upper(qualifier)) return true;
  }
  return false;
}

VarDeclaration::Parts VarDeclaration::parts() const {
  Parts parts;
  if (!node_) return parts;
  node_.for_each_child([&](SyntaxNode child) {
    const std::string_view name = NodeTable::field_name(child.field_id());
    if (name == "name") {
      parts.names.push_back(child);
    } else if (name == "type" && !parts.type) {
      parts.type = child;
    } else if (name == "value" && !parts.initial_value) {
      parts.initial_value = child;
    } else if (name == "location" && !parts.location) {
      parts.location = child;
    } else if (name == "arguments" && !parts.init_arguments) {
      parts.init_arguments = child;
    }
    if ((child.is_error() || child.is_missing()) && !parts.initial_value) parts.error_before_value = true;
  });
  return parts;
}

std::vector<VarDeclaration> VarBlock::declarations() const {
  std::vector<VarDeclaration> out;
  for (SyntaxNode d : node_.children_of_kind("var_declaration")) out.emplace_back(d);
  return out;
}

std::vector<VarBlock> Pou::var_blocks() const {
  std::vector<VarBlock> out;
  for (SyntaxNode b : node_.children_of_kind("var_block")) out.emplace_back(b);
  return out;
}

std::vector<std::string_view> Pou::modifiers() const {
  std::vector<std::string_view> out;
  for (SyntaxNode m : node_.children_of_kind("modifier")) out.push_back(m.text());
  return out;
}

std::vector<SyntaxNode> Pou::extends() const {
  SyntaxNode clause = node_.first_child_of_kind("extends_clause");
  return clause ? clause.children_of_kind("type_name") : std::vector<SyntaxNode>{};
}

std::vector<SyntaxNode> Pou::implements() const {
  SyntaxNode clause = node_.first_child_of_kind("implements_clause");
  return clause ? clause.children_of_kind("type_name") : std::vector<SyntaxNode>{};
}

std::vector<VarDeclaration> TypeDeclaration::fields() const {
  std::vector<VarDeclaration> out;
  for (SyntaxNode d : node_.children_of_kind("var_declaration")) out.emplace_back(d);
  return out;
}

std::vector<SyntaxNode> TypeDeclaration::enum_values() const {
  return node_.children_of_kind("enum_value");
}

struct OutlineBuilder {
  Outline out;

  // Builds a POU with the members nested inside it (IEC text shape).
  static Pou build(SyntaxNode node, PouKind kind) {
    Pou pou(node, kind);
    uint32_t n = node.named_child_count();
    for (uint32_t i = 0; i < n; ++i) {
      SyntaxNode c = node.named_child(i);
      PouKind ck;
      if (pou_kind_of(c.kind(), &ck) && is_member_kind(ck)) pou.members_.push_back(build(c, ck));
    }
    // IEC textual SFC keeps its ACTION blocks inside the network of the body.
    SyntaxNode body = node.child_by_field("body");
    if (body && body.kind() == "sfc_network") {
      for (SyntaxNode block : body.children_of_kind("sfc_action_block"))
        pou.members_.emplace_back(block, PouKind::Action);
    }
    return pou;
  }

  void visit_container(SyntaxNode container) {
    constexpr size_t kNone = static_cast<size_t>(-1);
    size_t owner = kNone;  // index of the POU that object-shape members which follow belong to
    uint32_t n = container.named_child_count();
    for (uint32_t i = 0; i < n; ++i) {
      SyntaxNode c = container.named_child(i);
      std::string_view k = c.kind();
      PouKind kind;
      if (pou_kind_of(k, &kind)) {
        Pou pou = build(c, kind);
        if (is_member_kind(kind) && owner != kNone) {
          out.pous[owner].members_.push_back(std::move(pou));
          continue;
        }
        out.pous.push_back(std::move(pou));
        owner = can_own_members(kind) ? out.pous.size() - 1 : kNone;
        continue;
      }
      if (k == "type_declaration") {
        add_types(c);
      } else if (k == "var_block") {
        VarBlock block(c);
        if (block.section() == VarSection::Global || block.section() == VarSection::Config)
          out.global_blocks.push_back(block);
      } else if (k == "namespace_declaration") {
        visit_container(c);
        owner = kNone;
      } else if (k == "configuration_declaration" || k == "resource_declaration") {
        out.configurations.push_back(c);
      }
    }
  }

  void add_types(SyntaxNode type_block) {
    uint32_t n = type_block.named_child_count();
    for (uint32_t i = 0; i < n; ++i) {
      SyntaxNode t = type_block.named_child(i);
      std::string_view k = t.kind();
      if (k == "struct_type")
        out.types.emplace_back(t, TypeKind::Struct);
      else if (k == "enum_type")
        out.types.emplace_back(t, TypeKind::Enum);
      else if (k == "union_type")
        out.types.emplace_back(t, TypeKind::Union);
      else if (k == "alias_type")
        out.types.emplace_back(t, TypeKind::Alias);
    }
  }
};

Outline outline(SyntaxNode root) {
  OutlineBuilder builder;
  builder.visit_container(root);
  return std::move(builder.out);
}

StatementKind statement_kind(SyntaxNode s) {
  std::string_view k = s.kind();
  if (k == "assignment_statement") return StatementKind::Assignment;
  if (k == "call_statement") return StatementKind::Call;
  if (k == "if_statement") return StatementKind::If;
  if (k == "case_statement") return StatementKind::Case;
  if (k == "for_statement") return StatementKind::For;
  if (k == "while_statement") return StatementKind::While;
  if (k == "repeat_statement") return StatementKind::Repeat;
  if (k == "exit_statement") return StatementKind::Exit;
  if (k == "continue_statement") return StatementKind::Continue;
  if (k == "return_statement") return StatementKind::Return;
  if (k == "jmp_statement") return StatementKind::Jump;
  if (k == "label") return StatementKind::Label;
  if (k == "empty_statement") return StatementKind::Empty;
  if (k == "try_statement") return StatementKind::Try;
  return StatementKind::Unknown;
}

std::vector<SyntaxNode> statements(SyntaxNode list) {
  std::vector<SyntaxNode> out;
  uint32_t n = list.named_child_count();
  for (uint32_t i = 0; i < n; ++i) {
    SyntaxNode c = list.named_child(i);
    if (!c.is_extra()) out.push_back(c);
  }
  return out;
}

ExpressionKind expression_kind(SyntaxNode e) {
  std::string_view k = e.kind();
  if (k == "binary_expression") return ExpressionKind::Binary;
  if (k == "unary_expression") return ExpressionKind::Unary;
  if (k == "parenthesized_expression") return ExpressionKind::Parenthesized;
  if (k == "call_expression") return ExpressionKind::Call;
  if (k == "member_expression") return ExpressionKind::Member;
  if (k == "index_expression") return ExpressionKind::Index;
  if (k == "dereference_expression") return ExpressionKind::Dereference;
  if (k == "identifier" || k == "qualified_name") return ExpressionKind::Identifier;
  if (k == "direct_variable") return ExpressionKind::DirectAddress;
  if (k == "array_initializer" || k == "struct_initializer") return ExpressionKind::Initializer;
  if (k.size() > 8 && k.substr(k.size() - 8) == "_literal") return ExpressionKind::Literal;
  return ExpressionKind::Unknown;
}

std::string operator_of(SyntaxNode e) {
  SyntaxNode op = e.child_by_field("operator");
  if (op) return upper(op.text());
  // Unary expressions: the first anonymous child is the operator.
  uint32_t n = e.child_count();
  for (uint32_t i = 0; i < n; ++i) {
    SyntaxNode c = e.child(i);
    if (!c.is_named() && !c.is_extra()) return upper(c.text());
  }
  return {};
}

}  // namespace rung::ast
