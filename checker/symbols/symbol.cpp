#include "checker/symbols/symbol.hpp"

namespace rung::check {

std::string_view symbol_kind_name(SymbolKind kind) {
  switch (kind) {
    case SymbolKind::Program: return "program";
    case SymbolKind::Function: return "function";
    case SymbolKind::FunctionBlock: return "function block";
    case SymbolKind::Class: return "class";
    case SymbolKind::Interface: return "interface";
    case SymbolKind::Method: return "method";
    case SymbolKind::Property: return "property";
    case SymbolKind::Action: return "action";
    case SymbolKind::Transition: return "transition";
    case SymbolKind::DataType: return "type";
    case SymbolKind::Variable: return "variable";
    case SymbolKind::EnumValue: return "enum value";
    case SymbolKind::GlobalList: return "global variable list";
    case SymbolKind::Namespace: return "namespace";
    case SymbolKind::Configuration: return "configuration";
    case SymbolKind::Resource: return "resource";
    case SymbolKind::Task: return "task";
    case SymbolKind::ProgramInstance: return "program instance";
    case SymbolKind::Step: return "step";
  }
  return "symbol";
}

bool is_pou_kind(SymbolKind kind) { return kind >= SymbolKind::Program && kind <= SymbolKind::Transition; }

bool is_callable_kind(SymbolKind kind) {
  return kind == SymbolKind::Program || kind == SymbolKind::Function || kind == SymbolKind::FunctionBlock ||
         kind == SymbolKind::Method || kind == SymbolKind::Action || kind == SymbolKind::Class;
}

const Attribute* Symbol::attribute(std::string_view attribute_name) const {
  for (const auto& candidate : attributes) {
    if (names_equal(candidate.name, attribute_name)) return &candidate;
  }
  return nullptr;
}

}  // namespace rung::check
