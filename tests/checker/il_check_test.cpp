// Semantic checks of Instruction List bodies: the current result (CR) through the instructions.
// Bad programs name the code and the line; the OpenPCS manual's own examples (003.md, S5xxx list)
// are quoted where a test follows one.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "checker/check.hpp"
#include "tests/support/project_findings.hpp"

namespace rung::check {
namespace {

using Found = std::vector<std::string>;

Found found(const std::string& text, project::Profile profile = project::Profile::Codesys) {
  return testing::codes_at_lines({{"P.il", text}}, testing::config_for(profile), testing::Warnings::Unmarked);
}

std::string program(const std::string& vars, const std::string& body) {
  return "PROGRAM P\nVAR\n" + vars + "\nEND_VAR\n" + body + "END_PROGRAM\n";
}

// --- Programs that are fine -----------------------------------------------------------------

TEST(IlCheck, LoadOperateStore) {
  EXPECT_EQ(found(program("a, b, c : INT; r : REAL; ok : BOOL;",
                          "LD a\nADD b\nMUL 2\nST c\nLD r\nDIV 2.0\nST r\nLD a\nGT b\nAND ok\nORN ok\nST ok\n")),
            Found{});
}

TEST(IlCheck, JumpsAndLabelsWithTheirOwnLoads) {
  EXPECT_EQ(found(program("a, b, c : REAL;",
                          "LD 10\nADD a\nGE b\nJMPC next1\nLD a\nADD b\nST c\nJMP next2\n"
                          "next1: LD a\nSUB b\nST c\nnext2:\n")),
            Found{});
}

TEST(IlCheck, SeveralStoresAndSetResetKeepTheResult) {
  // OpenPCS: ST leaves the CR unchanged, "multiple ST may follow one another"; so do S and R.
  EXPECT_EQ(found(program("a, b : DINT; q1, q2 : BOOL;", "LD a\nST b\nST a\nLD TRUE\nS q1\nR q2\nST q1\n")), Found{});
}

TEST(IlCheck, CalWithParametersAndOutputs) {
  EXPECT_EQ(found(program("t1 : TON; x, q : BOOL; et : TIME;",
                          "CAL t1(IN := x, PT := T#300ms, Q => q, ET => et)\nLD t1.Q\nST x\n")),
            Found{});
}

TEST(IlCheck, FunctionBlockInputOperators) {
  // IEC table 53: S1/R on an SR, S/R1 on an RS (2nd edition names), IN/PT on a TON set the input
  // from the CR.
  EXPECT_EQ(found(program("sr1 : SR; rs1 : RS; t1 : TON; x : BOOL;",
                          "LD x\nS1 sr1\nR sr1\nS rs1\nLDN x\nR1 rs1\nLD T#1s\nPT t1\nLD x\nIN t1\nCAL t1\nCAL rs1\n")),
            Found{});
  // A TON has no input PV; the CR must fit the input's type.
  EXPECT_EQ(found(program("t1 : TON; x : BOOL;", "LD x\nPV t1\nPT t1\n")), (Found{"E005@6", "E101@7"}));
}

TEST(IlCheck, FunctionWithTheResultAsFirstArgument) {
  EXPECT_EQ(found(program("n : INT; g : BOOL; r : REAL;",
                          "LD n\nLIMIT 0, 100\nST n\nLD g\nSEL 3, 4\nST n\nLD 0.5\nCOS\nST r\n")),
            Found{});
}

TEST(IlCheck, DeferredOperatorsNestAndMayStartWithLoad) {
  EXPECT_EQ(found(program("a, b, c, d, e, f : BOOL; r1, r2, r3, r4 : REAL;",
                          "LD a\nOR( b\nAND c\n)\nOR(\nLD d\nAND e\n)\nST f\n"
                          "LD r1\nADD( r2\nMUL( r3\nSUB r4\n)\n)\nST r1\n")),
            Found{});
}

TEST(IlCheck, FunctionBlockBodyWithReturn) {
  EXPECT_EQ(found("FUNCTION_BLOCK Wait1\nVAR_INPUT t : TIME; END_VAR\nVAR_OUTPUT ok : BOOL; END_VAR\n"
                  "VAR tel : TP; END_VAR\n"
                  "LD tel.Q\nJMPC mark\nCAL tel(IN := FALSE)\nLD t\nST tel.PT\nCAL tel(IN := TRUE)\nJMP done\n"
                  "mark: CAL tel\ndone: LD tel.Q\nNOT\nST ok\nRETC\nRET\nEND_FUNCTION_BLOCK\n"),
            Found{});
}

// --- The current result ---------------------------------------------------------------------

TEST(IlCheck, ResultUndefinedAtStartAndAfterLabel) {
  // OpenPCS S5009 (003.md L12487-12539): ST first, and ST first after the label END.
  EXPECT_EQ(found(program("Switch : BOOL;",
                          "ST Switch\nLD Switch\nEQ TRUE\nJMPC NextStep\nLD TRUE\nJMP End\n"
                          "NextStep:\nLD FALSE\nEND:\nST Switch\n")),
            (Found{"E801@5", "E801@14"}));
}

TEST(IlCheck, ResultUndefinedAfterCal) {
  EXPECT_EQ(found(program("t1 : TON; q : BOOL;", "LD TRUE\nCAL t1\nST q\n")), Found{"E801@7"});
}

TEST(IlCheck, InstructionAfterJmpIsUnreachable) {
  EXPECT_EQ(found(program("a : INT;", "LD 1\nJMP l1\nST a\nl1: LD 2\nST a\n")), (Found{"E801@7", "E409@7"}));
}

TEST(IlCheck, DeferredOperatorNeedsAResult) {
  EXPECT_EQ(found(program("a, b : BOOL;", "AND( a\nOR b\n)\nST a\n")), Found{"E801@5"});
}

// --- Parentheses and operands ---------------------------------------------------------------

TEST(IlCheck, CalAndLoadInsideParentheses) {
  // OpenPCS S5010 (003.md L12541-12631).
  EXPECT_EQ(found(program("c : TON; s, r : DINT;", "LD 5\nADD( s\nST s\nCAL c\nLD s\n)\nST r\n")),
            (Found{"E802@8", "E802@9"}));
}

TEST(IlCheck, OperandCount) {
  EXPECT_EQ(found(program("a, b : BOOL;", "LD\nNOT a\nLD a, b\nST b\n")), (Found{"E803@5", "E803@6", "E803@7"}));
}

TEST(IlCheck, UnknownOperatorSuggestsTheModifier) {
  EXPECT_EQ(found(program("a : BOOL;", "LD a\nJMPCL next1\nnext1:\n")), Found{"E002@6"});
}

// --- Jumps ------------------------------------------------------------------------------------

TEST(IlCheck, JumpToUnknownLabel) {
  EXPECT_EQ(
      found(program("b1, b2, erg : BOOL;", "LD TRUE\nANDN b1\nJMPC mark\nLDN b2\nST erg\nLable:\nLD b2\nST erg\n")),
      Found{"E410@7"});
}

TEST(IlCheck, ConditionalInstructionsNeedBool) {
  EXPECT_EQ(found(program("n : INT;", "LD n\nJMPC l1\nRETC\nl1:\n")), (Found{"E103@6", "E103@7"}));
}

TEST(IlCheck, TransitionCodeEndsWithBool) {
  const std::string text =
      "PROGRAM P\nVAR x : INT; END_VAR\nINITIAL_STEP s1: END_STEP\nTRANSITION FROM s1 TO s2 :\nLD x\nEND_TRANSITION\n"
      "STEP s2: END_STEP\nTRANSITION FROM s2 TO s1 :\nLD x\nGT 70\nEND_TRANSITION\nEND_PROGRAM\n";
  EXPECT_EQ(found(text), Found{"E103@5"});
}

// --- Stores -----------------------------------------------------------------------------------

TEST(IlCheck, StoreTargets) {
  EXPECT_EQ(found(program("k : INT := 3; t1 : TON; s : STRING;\nEND_VAR\nVAR CONSTANT c : INT := 1;",
                          "LD 1\nST c\nLD TRUE\nST t1.Q\nLD s\nST k\nLD 1\nST 5\n")),
            (Found{"E401@8", "E402@10", "E101@12", "E403@14"}));
}

TEST(IlCheck, ConstantOutOfRangeForTheTarget) {
  // OpenPCS S5012: LD 65000 / ST x (INT).
  EXPECT_EQ(found(program("x : INT;", "LD 65000\nST x\n"), project::Profile::Openpcs), Found{"E102@6"});
}

TEST(IlCheck, SetResetNeedBoolResultAndTarget) {
  EXPECT_EQ(found(program("n : INT; b : BOOL;", "LD n\nS b\nLD TRUE\nR n\n")), (Found{"E103@6", "E101@8"}));
}

// --- Operand types ----------------------------------------------------------------------------

TEST(IlCheck, OperatorNotDefinedForTheTypes) {
  // OpenPCS S3020 (DATE - TIME), S3028 (GT on structures), S3033 (TOD + integer).
  const std::string types = "TYPE Day : STRUCT n : INT; END_STRUCT; END_TYPE\n";
  EXPECT_EQ(found(types + program("d : DATE; t : TIME; d1, d2 : Day; b : BOOL; tod1 : TOD;",
                                  "LD d\nSUB t\nST d\nLD d1\nGT d2\nST b\nLD tod1\nADD 10000\nST tod1\n"),
                  project::Profile::Openpcs),
            (Found{"E104@7", "E104@10", "E104@13"}));
}

TEST(IlCheck, StandardFunctionArgumentsInOpenPcs) {
  // S5024 LD 1 / LN, S5027 LD 1 / MAX X (REAL), S5028 LD 1 / CONCAT 'EXAMPLE'.
  const std::string text =
      program("x : REAL; s : STRING;", "LD 1\nLN\nST x\nLD 1\nMAX x\nST x\nLD 1\nCONCAT 'EXAMPLE'\nST s\n");
  EXPECT_EQ(found(text, project::Profile::Openpcs), (Found{"E101@6", "E101@9", "E101@12"}));
  // CODESYS widens the integer to REAL; CONCAT still needs a string.
  EXPECT_EQ(found(text), Found{"E101@12"});
}

TEST(IlCheck, ResultTypeAgainstTheFunctionsFirstInput) {
  // OpenPCS S5013: CR is DINT, Fun1's first input INT.
  const std::string text = "FUNCTION Fun1 : BOOL\nVAR_INPUT InVar : INT; END_VAR\nFun1 := InVar > 0;\nEND_FUNCTION\n" +
                           program("x : DINT; b : BOOL;", "LD x\nADD 1000\nFun1\nST b\n");
  EXPECT_EQ(found(text, project::Profile::Openpcs), Found{"E101@11"});
  EXPECT_EQ(found(text), Found{"E105@11"});
}

TEST(IlCheck, TypeNameIsNoValue) {
  // OpenPCS S3012: LD Colours, where Colours is the enum type.
  EXPECT_EQ(found("TYPE Colours : (red, yellow, blue); END_TYPE\n" +
                  program("c : Colours;", "LD Colours\nST c\nLD red\nST c\n")),
            Found{"E004@6"});
}

TEST(IlCheck, BitAccessAndDirectAddresses) {
  // S5031: bits of a DINT only where integers are bit strings (CODESYS), S5032: WORD has 16 bits.
  const std::string text =
      program("d : DINT; w : WORD; b : BOOL;", "LD d.4\nST b\nLD w.16\nST %QX0.0\nLD %IX0.1\nAND w.3\nST b\n");
  EXPECT_EQ(found(text, project::Profile::Openpcs), (Found{"E104@5", "E107@7"}));
  EXPECT_EQ(found(text), Found{"E107@7"});
}

// --- Calls --------------------------------------------------------------------------------------

TEST(IlCheck, CalTargets) {
  EXPECT_EQ(found(program("n : INT;", "CAL n\nCAL TON\nCAL missing\n")), (Found{"E307@5", "E307@6", "E001@7"}));
}

TEST(IlCheck, CalParameters) {
  const std::string fb =
      "FUNCTION_BLOCK Fb1\nVAR_INPUT InParam1 : INT; InParam3 : BOOL; END_VAR\nVAR_IN_OUT Io : INT; END_VAR\n"
      "END_FUNCTION_BLOCK\n";
  // S5022 twice the same input, unknown input, S5034 constant for the IN_OUT, S5033 IN_OUT missing.
  EXPECT_EQ(found(fb + program("fbInst : Fb1; v : INT;",
                               "CAL fbInst(InParam1 := 1, InParam1 := 2, Io := v)\nCAL fbInst(Nope := 1, Io := v)\n"
                               "CAL fbInst(Io := 5)\nCAL fbInst()\nCAL fbInst\n"),
                  project::Profile::Openpcs),
            (Found{"E303@9", "E301@10", "E305@11", "E302@12", "E302@13"}));
}

TEST(IlCheck, OutputsAfterTheBar) {
  // OpenPCS: CAL SR_Instance_1(SET1 := On, RESET := Off | Result := Q1).
  EXPECT_EQ(found(program("sr1 : SR; on, off, result : BOOL;", "CAL sr1(SET1 := on, RESET := off | result := Q1)\n"),
                  project::Profile::Openpcs),
            Found{});
  EXPECT_EQ(
      found(program("sr1 : SR; on : BOOL; n : STRING;", "CAL sr1(SET1 := on | n := Q1)\n"), project::Profile::Openpcs),
      Found{"E101@5"});
}

TEST(IlCheck, CallingAnInputInstance) {
  // S5029: an FB instance received as VAR_INPUT cannot be called in OpenPCS.
  const std::string text =
      "FUNCTION_BLOCK Fb2\nVAR_INPUT inner : TON; END_VAR\nCAL inner(IN := TRUE)\nEND_FUNCTION_BLOCK\n";
  EXPECT_EQ(found(text, project::Profile::Openpcs), Found{"E307@3"});
  EXPECT_EQ(found(text), Found{});
}

TEST(IlCheck, FunctionBlockIsNoOperator) {
  EXPECT_EQ(found(program("t1 : TON; b : BOOL;", "LD b\nt1\nCU t1\n")), (Found{"E307@6", "E005@7"}));
}

TEST(IlCheck, ExtensibleFunctionsTakeOneOperandInOpenPcsIl) {
  // OpenPCS: MAX b, c is an error in IL (the current result and one operand); CODESYS accepts it.
  const std::string text = program("a : INT; b : INT; c : INT;", "LD a\nMAX b, c\nST a\nLD a\nMAX b\nST a\n");
  EXPECT_EQ(found(text, project::Profile::Openpcs), Found{"E803@6"});
  EXPECT_EQ(found(text), Found{});
}

TEST(IlCheck, MisplacedCallInParenthesesIsReportedOnce) {
  // The CAL inside the parentheses is the error; the value it leaves undefined is a follow-on.
  EXPECT_EQ(found(program("a : INT; b : INT; t : CTU;", "LD a\nADD( b\nCAL t\n)\nST a\n")), Found{"E802@7"});
}

TEST(IlCheck, IlExpressionIsNoStSyntax) {
  // (a ADD b) is an IL argument form; in an ST call it is a syntax error, reported once.
  EXPECT_EQ(found("PROGRAM P\nVAR a, b, c : INT; END_VAR\nc := MAX(IN1 := (a ADD b), IN2 := 1);\nEND_PROGRAM\n"),
            Found{"S001@3"});
}

}  // namespace
}  // namespace rung::check
