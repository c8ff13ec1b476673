#include "parser/ast.hpp"

#include <gtest/gtest.h>

#include "parser/tree_printer.hpp"

namespace rung::ast {
namespace {

// IEC text shape: members inside the FB, closed by END_ keywords.
constexpr const char* kIecShape = R"(
TYPE E_Mode : (Off := 0, Manual, Auto) INT; END_TYPE
TYPE ST_Point :
STRUCT
  x, y : REAL;
END_STRUCT
END_TYPE
{attribute 'qualified_only'}
VAR_GLOBAL CONSTANT
  MAX_AXES : INT := 8;
END_VAR
FUNCTION_BLOCK PUBLIC FB_Axis EXTENDS FB_Base IMPLEMENTS I_Axis, I_Reset
VAR_INPUT
  bEnable AT %IX0.0 : BOOL;
  rTarget : LREAL := 1.5;
END_VAR
VAR_OUTPUT RETAIN
  bDone : BOOL;
END_VAR
IF bEnable THEN bDone := TRUE; END_IF
METHOD PUBLIC MoveTo : BOOL
VAR_INPUT p : ST_Point; END_VAR
MoveTo := TRUE;
END_METHOD
PROPERTY Position : LREAL
GET
  Position := rTarget;
END_GET
END_PROPERTY
END_FUNCTION_BLOCK
)";

// CODESYS V3 / TwinCAT object shape: no END_ keywords, members follow the FB.
constexpr const char* kObjectShape = R"(FUNCTION_BLOCK FB_Lamp
VAR_INPUT
  bOn : BOOL;
END_VAR
bOn := NOT bOn;
METHOD Toggle
bOn := NOT bOn;
ACTION Reset:
bOn := FALSE;
PROGRAM MAIN
VAR
  fb : FB_Lamp;
END_VAR
fb();
)";

TEST(Ast, IecShapeOutline) {
  SyntaxTree tree = SyntaxTree::parse(kIecShape);
  ASSERT_FALSE(tree.root().has_error()) << print_sexp(tree.root());
  Outline o = outline(tree.root());

  ASSERT_EQ(o.types.size(), 2u);
  EXPECT_EQ(o.types[0].kind(), TypeKind::Enum);
  EXPECT_EQ(o.types[0].name(), "E_Mode");
  ASSERT_EQ(o.types[0].enum_values().size(), 3u);
  EXPECT_EQ(o.types[0].enum_values()[0].child_by_field("value").text(), "0");
  EXPECT_EQ(o.types[0].base_type().text(), "INT");
  EXPECT_EQ(o.types[1].kind(), TypeKind::Struct);
  ASSERT_EQ(o.types[1].fields().size(), 1u);
  EXPECT_EQ(o.types[1].fields()[0].names().size(), 2u);

  ASSERT_EQ(o.global_blocks.size(), 1u);
  EXPECT_TRUE(o.global_blocks[0].has_qualifier("constant"));

  ASSERT_EQ(o.pous.size(), 1u);
  const Pou& fb = o.pous[0];
  EXPECT_EQ(fb.kind(), PouKind::FunctionBlock);
  EXPECT_EQ(fb.name(), "FB_Axis");
  ASSERT_EQ(fb.modifiers().size(), 1u);
  EXPECT_EQ(fb.modifiers()[0], "PUBLIC");
  ASSERT_EQ(fb.extends().size(), 1u);
  EXPECT_EQ(fb.extends()[0].text(), "FB_Base");
  ASSERT_EQ(fb.implements().size(), 2u);
  EXPECT_EQ(fb.implements()[1].text(), "I_Reset");

  auto blocks = fb.var_blocks();
  ASSERT_EQ(blocks.size(), 2u);
  EXPECT_EQ(blocks[0].section(), VarSection::Input);
  EXPECT_EQ(blocks[1].section(), VarSection::Output);
  EXPECT_TRUE(blocks[1].has_qualifier("RETAIN"));
  auto decls = blocks[0].declarations();
  ASSERT_EQ(decls.size(), 2u);
  EXPECT_EQ(decls[0].names()[0].text(), "bEnable");
  EXPECT_NE(decls[0].location().text().find("%IX0.0"), std::string_view::npos);
  EXPECT_EQ(decls[1].type().text(), "LREAL");
  EXPECT_EQ(decls[1].initial_value().text(), "1.5");

  ASSERT_EQ(fb.members().size(), 2u);
  EXPECT_EQ(fb.members()[0].kind(), PouKind::Method);
  EXPECT_EQ(fb.members()[0].name(), "MoveTo");
  EXPECT_EQ(fb.members()[0].return_type().text(), "BOOL");
  EXPECT_EQ(fb.members()[1].kind(), PouKind::Property);
  ASSERT_EQ(fb.members()[1].members().size(), 1u);
  EXPECT_EQ(fb.members()[1].members()[0].kind(), PouKind::PropertyAccessor);

  auto body = statements(fb.body());
  ASSERT_EQ(body.size(), 1u);
  EXPECT_EQ(statement_kind(body[0]), StatementKind::If);
  EXPECT_EQ(expression_kind(body[0].child_by_field("condition")), ExpressionKind::Identifier);
}

TEST(Ast, ObjectShapeMembersAttachToThePouTheyFollow) {
  SyntaxTree tree = SyntaxTree::parse(kObjectShape);
  ASSERT_FALSE(tree.root().has_error()) << print_sexp(tree.root());
  Outline o = outline(tree.root());
  ASSERT_EQ(o.pous.size(), 2u);
  EXPECT_EQ(o.pous[0].name(), "FB_Lamp");
  ASSERT_EQ(o.pous[0].members().size(), 2u);
  EXPECT_EQ(o.pous[0].members()[0].kind(), PouKind::Method);
  EXPECT_EQ(o.pous[0].members()[0].name(), "Toggle");
  EXPECT_EQ(o.pous[0].members()[1].kind(), PouKind::Action);
  EXPECT_EQ(o.pous[0].members()[1].name(), "Reset");
  EXPECT_EQ(o.pous[1].kind(), PouKind::Program);
  EXPECT_TRUE(o.pous[1].members().empty());
}

TEST(Ast, SfcActionBlocksAreMembersOfTheirPou) {
  SyntaxTree tree = SyntaxTree::parse(
      "PROGRAM Seq\nVAR a : BOOL; END_VAR\nINITIAL_STEP S0:\n  Act(N);\nEND_STEP\nACTION Act:\n  a := TRUE;\n"
      "END_ACTION\nTRANSITION FROM S0 TO S1\n  := a;\nEND_TRANSITION\nSTEP S1:\nEND_STEP\nEND_PROGRAM\n");
  ASSERT_FALSE(tree.root().has_error()) << print_sexp(tree.root());
  Outline o = outline(tree.root());
  ASSERT_EQ(o.pous.size(), 1u);
  ASSERT_EQ(o.pous[0].members().size(), 1u);
  EXPECT_EQ(o.pous[0].members()[0].kind(), PouKind::Action);
  EXPECT_EQ(o.pous[0].members()[0].name(), "Act");
}

TEST(Ast, ExpressionsAndOperators) {
  SyntaxTree tree = SyntaxTree::parse("x := a + b * 2; y := NOT c; z := p^.q[1]; f(1);");
  ASSERT_FALSE(tree.root().has_error()) << print_sexp(tree.root());
  SyntaxNode list = tree.root().first_child_of_kind("statement_list");
  auto stmts = statements(list);
  ASSERT_EQ(stmts.size(), 4u);
  SyntaxNode sum = stmts[0].child_by_field("right");
  EXPECT_EQ(expression_kind(sum), ExpressionKind::Binary);
  EXPECT_EQ(operator_of(sum), "+");
  EXPECT_EQ(operator_of(sum.child_by_field("right")), "*");
  SyntaxNode neg = stmts[1].child_by_field("right");
  EXPECT_EQ(expression_kind(neg), ExpressionKind::Unary);
  EXPECT_EQ(operator_of(neg), "NOT");
  EXPECT_EQ(expression_kind(stmts[2].child_by_field("right")), ExpressionKind::Index);
  EXPECT_EQ(statement_kind(stmts[3]), StatementKind::Call);
}

}  // namespace
}  // namespace rung::ast
