#include "lsp/features/symbols_kinds.hpp"

namespace rung::lsp {
namespace {

// LSP SymbolKind values.
enum LspSymbolKind : int {
  kModule = 2,
  kNamespace = 3,
  kPackage = 4,
  kClass = 5,
  kMethod = 6,
  kProperty = 7,
  kField = 8,
  kEnum = 10,
  kInterface = 11,
  kFunction = 12,
  kVariable = 13,
  kConstant = 14,
  kBoolean = 17,
  kObject = 19,
  kKey = 20,
  kEnumMember = 22,
  kStruct = 23,
  kEvent = 24,
  kTypeParameter = 26,
};

}  // namespace

int lsp_symbol_kind(check::query::OutlineKind kind) {
  using check::query::OutlineKind;
  switch (kind) {
    case OutlineKind::Program: return kModule;
    case OutlineKind::Function: return kFunction;
    case OutlineKind::FunctionBlock:
    case OutlineKind::Class: return kClass;
    case OutlineKind::Interface: return kInterface;
    case OutlineKind::Method:
    case OutlineKind::Accessor: return kMethod;
    case OutlineKind::Property: return kProperty;
    case OutlineKind::Action: return kEvent;
    case OutlineKind::Transition: return kBoolean;  // a condition between steps
    case OutlineKind::Step: return kKey;
    case OutlineKind::Struct:
    case OutlineKind::Union: return kStruct;
    case OutlineKind::Enum: return kEnum;
    case OutlineKind::Alias: return kTypeParameter;
    case OutlineKind::EnumValue: return kEnumMember;
    case OutlineKind::VarBlock: return kObject;
    case OutlineKind::Variable: return kVariable;
    case OutlineKind::Constant: return kConstant;
    case OutlineKind::Field: return kField;
    case OutlineKind::GlobalList: return kNamespace;
    case OutlineKind::Configuration: return kModule;
    case OutlineKind::Resource: return kPackage;
    case OutlineKind::Task: return kEvent;
    case OutlineKind::ProgramInstance: return kVariable;
  }
  return kVariable;
}

}  // namespace rung::lsp
