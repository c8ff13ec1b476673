#include "lsp/features/hover_markdown.hpp"

#include <fmt/format.h>

#include "checker/query/declaration_text.hpp"
#include "checker/query/doc_comment.hpp"

namespace rung::lsp {
namespace {

using check::Symbol;
using check::SymbolKind;

std::string variable_role(const Symbol& symbol) {
  const Symbol* owner = symbol.owner;
  if (owner && owner->kind == SymbolKind::DataType) return "field";
  if (owner && owner->kind == SymbolKind::GlobalList) return "global variable";
  switch (symbol.section) {
    case ast::VarSection::Input: return "input";
    case ast::VarSection::Output: return "output";
    case ast::VarSection::InOut: return "in-out (VAR_IN_OUT)";
    case ast::VarSection::Global: return "global variable";
    case ast::VarSection::External: return "external variable (VAR_EXTERNAL)";
    case ast::VarSection::Temp: return "temporary variable";
    case ast::VarSection::Stat: return "static variable (VAR_STAT)";
    case ast::VarSection::Inst: return "instance variable (VAR_INST)";
    default: return "local variable";
  }
}

std::string type_role(const check::ProjectModel& model, const Symbol& symbol) {
  switch (check::underlying(model.type_of(&symbol))->kind) {
    case check::TypeKind::Struct: return "structure";
    case check::TypeKind::Union: return "union";
    case check::TypeKind::Enum: return "enumeration";
    default: return "type";
  }
}

// The value a CONSTANT has, when its initial value is more than a literal (`N * 2` = 10).
std::string constant_value_line(const check::ProjectModel& model, const Symbol& symbol) {
  if (symbol.kind != SymbolKind::Variable || !symbol.has(check::kConstant) || symbol.node.kind() != "var_declaration") {
    return {};
  }
  const SyntaxNode initial = ast::VarDeclaration(symbol.node).initial_value();
  if (!initial) return {};
  const auto value = model.constant_value(initial, symbol.owner);
  if (!value) return {};
  const std::string text = check::to_string(*value);
  if (check::names_equal(text, initial.text())) return {};
  return fmt::format("value `{}`", text);
}

}  // namespace

std::string code_block(std::string_view code) { return fmt::format("```iec61131\n{}\n```", code); }

std::string symbol_role(const check::ProjectModel& model, const Symbol& symbol) {
  std::string role;
  switch (symbol.kind) {
    case SymbolKind::Variable: role = variable_role(symbol); break;
    case SymbolKind::EnumValue: role = "value"; break;
    case SymbolKind::DataType: role = type_role(model, symbol); break;
    case SymbolKind::GlobalList: role = "global variable list"; break;
    default: role = check::symbol_kind_name(symbol.kind); break;
  }
  if (symbol.kind == SymbolKind::Variable && symbol.has(check::kConstant)) role = "constant " + role;
  const Symbol* owner = symbol.owner;
  if (owner && !owner->name.empty() && symbol.kind != SymbolKind::DataType) {
    role += fmt::format(" of `{}`", owner->name);
  }
  if (symbol.source < model.source_count() && model.source(symbol.source).library) {
    const std::string& library = model.source(symbol.source).library_name;
    role += library.empty() ? " (standard library)" : fmt::format(" (library `{}`)", library);
  }
  return role;
}

std::string symbol_markdown(const check::ProjectModel& model, const Symbol& symbol) {
  std::string markdown = code_block(check::query::declaration_text(model, symbol));
  std::string facts = symbol_role(model, symbol);
  if (symbol.kind == SymbolKind::Variable) {
    // The type the written one stands for, when they differ (an alias, a generic parameter).
    const check::Type* type = model.type_of(&symbol);
    const std::string written = check::query::written_type(model, symbol);
    if (type && !type->is_unknown() && !check::names_equal(type->name, written)) {
      facts += fmt::format(", type `{}`", type->name);
    }
  }
  if (const std::string value = constant_value_line(model, symbol); !value.empty()) facts += ", " + value;
  markdown += "\n\n" + facts;
  if (const std::string doc = check::query::doc_comment(model, symbol); !doc.empty()) {
    markdown += "\n\n---\n\n" + doc;
  }
  return markdown;
}

}  // namespace rung::lsp
