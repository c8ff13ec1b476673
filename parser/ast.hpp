// Typed views over the concrete syntax tree: POUs, VAR blocks, declarations, types, statements
// and expressions by what they mean rather than by grammar node names. Views are cheap values
// holding a SyntaxNode; they never copy text and are valid while their SyntaxTree is unedited.
//
// Both POU shapes land in the same model: in IEC text a METHOD sits inside its FUNCTION_BLOCK
// (closed by END_FUNCTION_BLOCK); in the CODESYS V3 / TwinCAT object shape it follows the block
// at top level. outline() attaches such members to the POU they follow.
#pragma once

#include <string_view>
#include <vector>

#include "parser/syntax_tree.hpp"

namespace rung::ast {

enum class PouKind {
  Program,
  Function,
  FunctionBlock,
  Method,
  Property,
  PropertyAccessor,  // GET or SET of a property
  Interface,
  Action,
  Transition,
  Class,
};
std::string_view pou_kind_name(PouKind kind);

enum class VarSection { Var, Input, Output, InOut, Global, External, Temp, Stat, Inst, Config, Access, Unknown };
std::string_view var_section_name(VarSection section);

class VarDeclaration {
 public:
  // Everything a declaration holds, found in one pass over its children: asking for each field
  // separately walks the children again every time (the symbol pass of a large project spent a
  // fifth of its time there).
  struct Parts {
    std::vector<SyntaxNode> names;
    SyntaxNode type;
    SyntaxNode initial_value;
    SyntaxNode location;        // AT %IX0.0
    SyntaxNode init_arguments;  // fb : FB(1, 2)
    // A syntax error or missing token before the initial value (or anywhere, without one): then
    // the type that error recovery found is a guess.
    bool error_before_value = false;
  };
  Parts parts() const;

  explicit VarDeclaration(SyntaxNode node) : node_(node) {}
  SyntaxNode node() const { return node_; }
  std::vector<SyntaxNode> names() const { return node_.children_by_field("name"); }
  SyntaxNode type() const { return node_.child_by_field("type"); }
  SyntaxNode initial_value() const { return node_.child_by_field("value"); }
  SyntaxNode location() const { return node_.child_by_field("location"); }         // AT %IX0.0
  SyntaxNode init_arguments() const { return node_.child_by_field("arguments"); }  // fb : FB(1, 2)

 private:
  SyntaxNode node_;
};

class VarBlock {
 public:
  explicit VarBlock(SyntaxNode node) : node_(node) {}
  SyntaxNode node() const { return node_; }
  VarSection section() const;
  bool has_qualifier(std::string_view qualifier) const;  // "CONSTANT", "RETAIN", "PERSISTENT", ...
  std::vector<VarDeclaration> declarations() const;

 private:
  SyntaxNode node_;
};

class Pou {
 public:
  Pou(SyntaxNode node, PouKind kind) : node_(node), kind_(kind) {}
  SyntaxNode node() const { return node_; }
  PouKind kind() const { return kind_; }
  SyntaxNode name_node() const { return node_.child_by_field("name"); }
  std::string_view name() const { return name_node().text(); }
  SyntaxNode return_type() const { return node_.child_by_field("type"); }  // FUNCTION/METHOD/PROPERTY
  SyntaxNode body() const { return node_.child_by_field("body"); }
  std::vector<VarBlock> var_blocks() const;
  std::vector<std::string_view> modifiers() const;  // PUBLIC, ABSTRACT, FINAL, ... as written
  std::vector<SyntaxNode> extends() const;          // base type names
  std::vector<SyntaxNode> implements() const;       // interface names
  // Methods, properties, actions, transitions (and a property's GET/SET) declared inside it, or
  // following it in the object shape.
  const std::vector<Pou>& members() const { return members_; }

 private:
  friend struct OutlineBuilder;
  SyntaxNode node_;
  PouKind kind_;
  std::vector<Pou> members_;
};

enum class TypeKind { Struct, Enum, Union, Alias };

class TypeDeclaration {
 public:
  TypeDeclaration(SyntaxNode node, TypeKind kind) : node_(node), kind_(kind) {}
  SyntaxNode node() const { return node_; }
  TypeKind kind() const { return kind_; }
  std::string_view name() const { return node_.child_by_field("name").text(); }
  std::vector<VarDeclaration> fields() const;   // STRUCT / UNION members
  std::vector<SyntaxNode> enum_values() const;  // enum_value nodes (name, value fields)
  SyntaxNode aliased_type() const { return node_.child_by_field("type"); }
  SyntaxNode base_type() const { return node_.child_by_field("base"); }  // enum base type

 private:
  SyntaxNode node_;
  TypeKind kind_;
};

// What a file declares, in text order.
struct Outline {
  std::vector<Pou> pous;                // top-level POUs with their members attached
  std::vector<TypeDeclaration> types;   // every TYPE, also inside namespaces
  std::vector<VarBlock> global_blocks;  // VAR_GLOBAL / VAR_CONFIG at top level (GVL files)
  std::vector<SyntaxNode> configurations;
};

Outline outline(SyntaxNode root);

enum class StatementKind {
  Assignment,
  Call,
  If,
  Case,
  For,
  While,
  Repeat,
  Exit,
  Continue,
  Return,
  Jump,
  Label,
  Empty,
  Try,
  Unknown
};
StatementKind statement_kind(SyntaxNode statement);
// The statements of a statement_list (comments and pragmas skipped).
std::vector<SyntaxNode> statements(SyntaxNode statement_list);

enum class ExpressionKind {
  Binary,
  Unary,
  Parenthesized,
  Call,
  Member,
  Index,
  Dereference,
  Identifier,
  Literal,
  DirectAddress,
  Initializer,
  Unknown
};
ExpressionKind expression_kind(SyntaxNode expression);
// For binary and unary expressions: the operator as written, upper-cased ("AND", "+", "MOD").
std::string operator_of(SyntaxNode expression);

}  // namespace rung::ast
