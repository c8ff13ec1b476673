// What the formatter needs to know about each grammar symbol, looked up by symbol id: the named
// node kinds it lays out differently, and the classes of anonymous tokens that decide spacing.
// One table built from the language at first use, so the walk over a large file never compares
// kind strings.
#pragma once

#include <tree_sitter/api.h>

#include <cstdint>

namespace rung::format {

// Named node kinds the layout distinguishes (everything else is Other).
enum class NodeKind : uint8_t {
  Other,
  SourceFile,
  StatementList,
  IfStatement,
  ElsifClause,
  ElseClause,
  CaseStatement,
  CaseElement,
  ForStatement,
  WhileStatement,
  RepeatStatement,
  TryStatement,
  CatchClause,
  FinallyClause,
  VarBlock,
  GenericConstantBlock,
  VarDeclaration,
  EmptyDeclaration,
  AccessDeclaration,
  StructType,
  UnionType,
  EnumType,
  EnumValue,
  AliasType,
  TypeDeclaration,
  Program,
  Function,
  FunctionBlock,
  Class,
  Method,
  Property,
  PropertyAccessor,
  Interface,
  Action,
  TransitionDeclaration,
  Namespace,
  UsingDirective,
  Configuration,
  Resource,
  TaskConfiguration,
  ProgramConfiguration,
  IlBody,
  IlInstruction,
  IlExpression,
  IlLabel,
  IlOperator,
  SfcNetwork,
  SfcStep,
  SfcAction,
  SfcTransition,
  SfcActionBlock,
  SfcStepMacro,
  Label,
  ExpressionFragment,
  BinaryExpression,
  UnaryExpression,
  ArgumentList,
  ArgumentLists,
  CallExpression,
  ParenthesizedExpression,
  IndexExpression,
  GlobalReference,
  TypedLiteral,
  GenericType,
  VariadicType,
  StringType,
  ArrayType,
  SubrangeType,
  ArrayInitializer,
  StructInitializer,
  RepeatedInitializer,
  TypeName,
  Identifier,
  Comment,
  Pragma,
  VarQualifier,
  Modifier,
  Count,
};

// Classes of anonymous tokens (and of the few named leaves that spell keywords).
enum class TokenClass : uint8_t {
  Other,
  Keyword,       // IF, END_VAR, AND, TRUE, S=, ...: the grammar shows it in upper case
  Comma,         // ,
  Semicolon,     // ;
  OpenParen,     // (
  CloseParen,    // )
  OpenBracket,   // [
  CloseBracket,  // ]
  Dot,           // .
  Range,         // ..
  Caret,         // ^
  Hash,          // # of a typed literal
  Colon,         // :
  Assign,        // := => ?= (S= R= REF= are keywords that also assign)
  At,            // @ of an OpenPCS step macro
  Operator,      // + - * / ** = <> < > <= >= &
};

struct SymbolInfo {
  NodeKind node = NodeKind::Other;
  TokenClass token = TokenClass::Other;
  bool named = false;
  // A keyword spelling whose case the formatter may change (IF, S=, FUNCTIONBLOCK shown as
  // FUNCTION_BLOCK, the var_qualifier CONSTANT of a generic block).
  bool keyword = false;
  // END_IF, END_VAR, UNTIL, __ENDTRY: a comment line right before it belongs to the block body.
  bool closer = false;
  // ELSE, ELSIF, __CATCH, __FINALLY: they close the branch before them.
  bool middle = false;
};

const SymbolInfo& symbol_info(TSSymbol symbol);

}  // namespace rung::format
