// Instruction List: the current result through a body (see il_checker.hpp).
#include "checker/semantic/il_checker.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <map>

#include "checker/semantic/builtins.hpp"
#include "parser/diagnostic_codes.hpp"
#include "parser/keywords.hpp"

namespace rung::check {
namespace {

enum class IlKind { Load, Store, Set, Reset, Not, Logic, Arithmetic, Comparison, Jump, Call, Return, Other };

struct IlOperator {
  IlKind kind = IlKind::Other;
  std::string_view op;       // the ST operator it computes: "AND", "+", ">" ...
  bool negated = false;      // N modifier: LDN, ANDN, STN, JMPCN ...
  bool conditional = false;  // C modifier: JMPC, CALC, RETC
};

// The IL operators of IEC 61131-3 (2nd ed. table 52); anything else names a function or, with
// an FB instance as operand, one of its inputs (table 53: S1, R, S, R1, CLK, CU, CD, PV, IN, PT).
IlOperator classify(std::string_view upper) {
  struct Row {
    std::string_view name;
    IlOperator value;
  };
  static constexpr std::array kRows{
      Row{"LD", {IlKind::Load, "", false, false}},         Row{"LDN", {IlKind::Load, "", true, false}},
      Row{"ST", {IlKind::Store, "", false, false}},        Row{"STN", {IlKind::Store, "", true, false}},
      Row{"S", {IlKind::Set, "", false, false}},           Row{"R", {IlKind::Reset, "", false, false}},
      Row{"NOT", {IlKind::Not, "NOT", false, false}},      Row{"AND", {IlKind::Logic, "AND", false, false}},
      Row{"ANDN", {IlKind::Logic, "AND", true, false}},    Row{"&", {IlKind::Logic, "AND", false, false}},
      Row{"&N", {IlKind::Logic, "AND", true, false}},      Row{"OR", {IlKind::Logic, "OR", false, false}},
      Row{"ORN", {IlKind::Logic, "OR", true, false}},      Row{"XOR", {IlKind::Logic, "XOR", false, false}},
      Row{"XORN", {IlKind::Logic, "XOR", true, false}},    Row{"ADD", {IlKind::Arithmetic, "+", false, false}},
      Row{"SUB", {IlKind::Arithmetic, "-", false, false}}, Row{"MUL", {IlKind::Arithmetic, "*", false, false}},
      Row{"DIV", {IlKind::Arithmetic, "/", false, false}}, Row{"MOD", {IlKind::Arithmetic, "MOD", false, false}},
      Row{"GT", {IlKind::Comparison, ">", false, false}},  Row{"GE", {IlKind::Comparison, ">=", false, false}},
      Row{"EQ", {IlKind::Comparison, "=", false, false}},  Row{"NE", {IlKind::Comparison, "<>", false, false}},
      Row{"LE", {IlKind::Comparison, "<=", false, false}}, Row{"LT", {IlKind::Comparison, "<", false, false}},
      Row{"JMP", {IlKind::Jump, "", false, false}},        Row{"JMPC", {IlKind::Jump, "", false, true}},
      Row{"JMPCN", {IlKind::Jump, "", true, true}},        Row{"CAL", {IlKind::Call, "", false, false}},
      Row{"CALC", {IlKind::Call, "", false, true}},        Row{"CALCN", {IlKind::Call, "", true, true}},
      Row{"RET", {IlKind::Return, "", false, false}},      Row{"RETC", {IlKind::Return, "", false, true}},
      Row{"RETCN", {IlKind::Return, "", true, true}},      Row{"RETURN", {IlKind::Return, "", false, false}},
  };
  for (const Row& row : kRows) {
    if (row.name == upper) return row.value;
  }
  return {};
}

bool is_fb_input_operator(std::string_view upper) {
  return upper == "S1" || upper == "R1" || upper == "S" || upper == "R" || upper == "CLK" || upper == "CU" ||
         upper == "CD" || upper == "PV" || upper == "IN" || upper == "PT";
}

// The input `name` of a block, also by its IEC 2nd edition name (the stubs' rung.alias: S1 for
// SR's SET1, R1 for RS's RESET1).
const Symbol* find_input(const Symbol* block, std::string_view name) {
  int depth = 0;
  for (const Symbol* scope = block; scope && depth < 32; scope = scope->base, ++depth) {
    for (const Symbol* member : scope->ordered) {
      if (member->kind != SymbolKind::Variable || member->section != ast::VarSection::Input) continue;
      const Attribute* alias = member->attribute("rung.alias");
      if (names_equal(member->name, name) || (alias && names_equal(alias->value, name))) return member;
    }
  }
  return nullptr;
}

// The anonymous child `text` of a node: the ( and ) of a deferred operator.
SyntaxNode token(SyntaxNode node, std::string_view text) {
  for (uint32_t i = 0; i < node.child_count(); ++i) {
    SyntaxNode child = node.child(i);
    if (!child.is_named() && child.text() == text) return child;
  }
  return {};
}

// The function block (or program, class) an instance's type names, if it is one.
const Symbol* instance_block(const Type* type) {
  const Type* base = underlying(type);
  if (base->kind == TypeKind::Reference && base->element) base = underlying(base->element);
  if (base->kind != TypeKind::Pou || !base->declaration) return nullptr;
  const SymbolKind kind = base->declaration->kind;
  return kind == SymbolKind::FunctionBlock || kind == SymbolKind::Class || kind == SymbolKind::Program
             ? base->declaration
             : nullptr;
}

// ADD, MAX, MUX ...: the stubs mark the input that may repeat (rung.extensible).
bool has_extensible_input(const Symbol& callee) {
  return std::any_of(callee.ordered.begin(), callee.ordered.end(),
                     [](const Symbol* member) { return member->has(kExtensible); });
}

bool has_inputs(const Symbol& callee) {
  for (const Symbol* member : callee.ordered) {
    if (member->kind == SymbolKind::Variable &&
        (member->section == ast::VarSection::Input || member->section == ast::VarSection::InOut)) {
      return true;
    }
  }
  return false;
}

}  // namespace

IlChecker::IlChecker(BodyChecker& body, const ProjectModel& model, const Symbol& pou)
    : body_(body), model_(model), pou_(pou) {
  undefine();
}

void IlChecker::check(SyntaxNode il_body, bool transition) {
  if (!il_body) return;
  collect_labels(il_body);
  undefine();
  check_sequence(il_body, 0, false);
  if (!transition) return;
  // The transition fires when the CR is TRUE after its code (OpenPCS manual L2510-2545).
  if (!current_.defined) {
    body_.report(codes::kIlResultUndefined, "the transition's code ends without a current result", il_body.range(),
                 "end the code with the condition in the current result, e.g. LD x / GT 70");
  } else {
    const Type* type = arithmetic_type(current_.info.type);
    if (!type->is_unknown() && type->kind != TypeKind::Bool && type->kind != TypeKind::Generic) {
      body_.report(codes::kConditionNotBool,
                   fmt::format("the transition's code ends with a current result of type {}, not BOOL",
                               current_.info.type->name),
                   il_body.range());
    }
  }
}

ExprInfo IlChecker::value_of(SyntaxNode il_expression) {
  // Like the one-line deferred operator MUL (2 ADD 3): the operand loads, the rest applies to it.
  ExprInfo value = operand_value(il_expression.child_by_field("operand"));
  value.assignable = false;
  current_ = CurrentResult{true, value};
  check_sequence(il_expression, 1, false);
  ExprInfo result = current_.info;
  result.assignable = false;
  return result;
}

void IlChecker::collect_labels(SyntaxNode node) {
  std::map<std::string, SyntaxNode> seen;
  std::vector<SyntaxNode> stack{node};
  while (!stack.empty()) {
    SyntaxNode current = stack.back();
    stack.pop_back();
    for (uint32_t i = 0; i < current.named_child_count(); ++i) {
      SyntaxNode child = current.named_child(i);
      if (child.kind() == "il_instruction") {
        stack.push_back(child);
        continue;
      }
      if (child.kind() != "il_label") continue;
      SyntaxNode name = child.child_by_field("name");
      if (!name) continue;
      const std::string key = upper_name(name.text());
      auto [it, inserted] = seen.emplace(key, name);
      if (!inserted) {
        body_.report(codes::kDuplicateLabel, fmt::format("label '{}' is declared twice", name.text()), name.range(), {},
                     {{it->second.range(), "first declared here"}});
      }
      labels_.insert(key);
    }
  }
}

void IlChecker::check_sequence(SyntaxNode parent, int depth, bool load_may_open) {
  bool first = true;
  for (uint32_t i = 0; i < parent.named_child_count(); ++i) {
    SyntaxNode child = parent.named_child(i);
    if (child.kind() == "il_label") {
      if (depth > 0) {
        body_.report(codes::kIlNotInParentheses, "a label inside parentheses", child.range(),
                     "put the label before the instruction that opens the parentheses");
      }
      undefine();  // a jump may arrive here with any current result
      left_by_ = {};
      continue;
    }
    if (child.kind() != "il_instruction") continue;
    check_instruction(child, depth, first && load_may_open);
    first = false;
  }
}

void IlChecker::check_instruction(SyntaxNode instruction, int depth, bool first_in_parentheses) {
  SyntaxNode op_node = instruction.child_by_field("operator");
  if (!op_node || op_node.is_missing()) return;
  if (left_by_) {
    body_.report(codes::kUnreachableCode,
                 fmt::format("this instruction is never executed: the {} before it always leaves", left_by_.text()),
                 instruction.range(), "put a label before it, or make the jump conditional");
    left_by_ = {};
  }
  const std::string name = upper_name(op_node.text());
  const IlOperator op = classify(name);
  const std::vector<SyntaxNode> operands = instruction.children_by_field("operand");
  if (token(instruction, "(")) {
    check_deferred(instruction, op_node, depth);
    return;
  }
  if ((op.kind == IlKind::Other || op.kind == IlKind::Set || op.kind == IlKind::Reset) && is_fb_input_operator(name) &&
      check_fb_input(op_node, operands)) {
    return;
  }
  if (depth > 0 && (op.kind == IlKind::Jump || op.kind == IlKind::Call || op.kind == IlKind::Return ||
                    (op.kind == IlKind::Load && !first_in_parentheses))) {
    misplaced_in_parentheses_ = true;
    body_.report(
        codes::kIlNotInParentheses,
        op.kind == IlKind::Load ? fmt::format("{} inside parentheses would discard the value computed there", name)
                                : fmt::format("{} inside parentheses", name),
        op_node.range(),
        op.kind == IlKind::Load ? "only the first instruction after '(' may load; or give the operand after '('"
                                : "close the parentheses first");
  }
  switch (op.kind) {
    case IlKind::Load: {
      if (!expect_operands(op_node, operands, 1)) {
        current_ = CurrentResult{true, ExprInfo{.type = model_.types().unknown()}};
        return;
      }
      ExprInfo value = operand_value(operands[0]);
      if (op.negated) value = body_.unary_result("NOT", value, instruction.range());
      value.assignable = false;
      current_ = CurrentResult{true, value};
      return;
    }
    case IlKind::Store:
    case IlKind::Set:
    case IlKind::Reset: {
      const bool store = op.kind == IlKind::Store;
      if (store) {
        require_result(op_node);
      } else {
        require_bool_result(op_node);
      }
      if (!expect_operands(op_node, operands, 1)) return;
      ExprInfo target = body_.type_of(operands[0]);
      if (!body_.check_assignment_target(target, operands[0])) return;
      if (!store) {
        const Type* type = arithmetic_type(target.type);
        if (!type->is_unknown() && type->kind != TypeKind::Bool) {
          body_.report(codes::kTypeMismatch, fmt::format("{} needs a BOOL operand, not {}", name, target.type->name),
                       operands[0].range());
        }
        return;
      }
      ExprInfo value = current_.info;
      if (op.negated) value = body_.unary_result("NOT", value, op_node.range());
      body_.check_conversion(value, target.type, operands[0]);
      return;
    }
    case IlKind::Not:
      require_result(op_node);
      if (!expect_operands(op_node, operands, 0)) return;
      current_.info = body_.unary_result("NOT", current_.info, instruction.range());
      current_.info.symbol = nullptr;
      return;
    case IlKind::Logic:
    case IlKind::Arithmetic:
    case IlKind::Comparison: {
      require_result(op_node);
      if (!expect_operands(op_node, operands, 1)) return;
      ExprInfo operand = operand_value(operands[0]);
      if (op.negated) operand = body_.unary_result("NOT", operand, operands[0].range());
      apply(name, operand, operands[0], instruction.range());
      return;
    }
    case IlKind::Jump:
      if (op.conditional) require_bool_result(op_node);
      if (expect_operands(op_node, operands, 1)) check_jump_label(operands[0]);
      if (!op.conditional) {
        undefine();
        left_by_ = op_node;
      }
      return;
    case IlKind::Call:
      if (op.conditional) require_bool_result(op_node);
      if (expect_operands(op_node, operands, 1)) check_cal(operands[0]);
      undefine();  // the called block may have changed anything (OpenPCS S5009)
      return;
    case IlKind::Return:
      if (op.conditional) require_bool_result(op_node);
      expect_operands(op_node, operands, 0);
      if (!op.conditional) {
        undefine();
        left_by_ = op_node;
      }
      return;
    case IlKind::Other: check_function_call(instruction, op_node, operands); return;
  }
}

void IlChecker::check_deferred(SyntaxNode instruction, SyntaxNode op_node, int depth) {
  // AND( ... ): the CR waits while the parentheses compute the operand (IEC 2nd ed. 3.2.2).
  const std::string name = upper_name(op_node.text());
  const IlOperator op = classify(name);
  if (op.kind != IlKind::Logic && op.kind != IlKind::Arithmetic && op.kind != IlKind::Comparison) {
    body_.report(codes::kInvalidOperand, fmt::format("{} cannot be deferred with '('", name), op_node.range(),
                 "only AND, OR, XOR, ADD, SUB, MUL, DIV, MOD and the comparisons take the '(' modifier");
  }
  require_result(op_node);
  const CurrentResult waiting = current_;
  const std::vector<SyntaxNode> operands = instruction.children_by_field("operand");
  if (operands.size() > 1) {
    body_.report(codes::kIlOperandCount, fmt::format("{}( takes one operand", name), operands[1].range());
  }
  if (!operands.empty()) {
    ExprInfo value = operand_value(operands[0]);
    value.assignable = false;
    current_ = CurrentResult{true, value};
  } else {
    undefine();
    current_.defined = false;
  }
  check_sequence(instruction, depth + 1, operands.empty());
  SyntaxNode close = token(instruction, ")");
  if (!close || close.is_missing()) close = instruction;
  if (left_by_) left_by_ = {};
  if (!current_.defined) {
    // After an E802 inside them (a CAL or JMP there) the missing value is a follow-on.
    if (!misplaced_in_parentheses_) {
      body_.report(codes::kIlResultUndefined, fmt::format("the parentheses of {} compute no value", name),
                   close.range(), "start them with an operand, e.g. AND( x, or with LD");
    }
    current_ = CurrentResult{true, ExprInfo{.type = model_.types().unknown()}};
  }
  misplaced_in_parentheses_ = false;
  ExprInfo operand = current_.info;
  if (op.negated) operand = body_.unary_result("NOT", operand, instruction.range());
  current_ = waiting;
  if (op.kind == IlKind::Logic || op.kind == IlKind::Arithmetic || op.kind == IlKind::Comparison) {
    apply(name, operand, close, instruction.range());
  } else {
    current_.info = ExprInfo{.type = model_.types().unknown()};
  }
}

void IlChecker::apply(std::string_view op_name, const ExprInfo& operand, SyntaxNode operand_node, TextRange range) {
  const IlOperator op = classify(op_name);
  ExprInfo result = body_.binary_result(op.op, current_.info, operand, operand_node, range, op_name);
  result.assignable = false;
  current_ = CurrentResult{true, result};
}

ExprInfo IlChecker::operand_value(SyntaxNode operand) {
  ExprInfo info = body_.type_of(operand);
  if (info.names_type && info.symbol && info.symbol->kind != SymbolKind::EnumValue) {
    body_.report(codes::kWrongKindOfName, fmt::format("'{}' is a type, not a value", operand.text()), operand.range(),
                 "load a variable or a constant of that type");
    return ExprInfo{.type = model_.types().unknown()};
  }
  return info;
}

void IlChecker::require_result(SyntaxNode op_node) {
  if (current_.defined) return;
  body_.report(codes::kIlResultUndefined,
               fmt::format("{} uses the current result, which is undefined here", upper_name(op_node.text())),
               op_node.range(),
               "load a value first (LD): the current result is undefined at the start, after a label, JMP, CAL "
               "and RET");
  current_ = CurrentResult{true, ExprInfo{.type = model_.types().unknown()}};
}

void IlChecker::require_bool_result(SyntaxNode op_node) {
  if (!current_.defined) {
    require_result(op_node);
    return;
  }
  const Type* type = arithmetic_type(current_.info.type);
  if (type->is_unknown() || type->kind == TypeKind::Bool || type->kind == TypeKind::Generic) return;
  body_.report(
      codes::kConditionNotBool,
      fmt::format("{} needs a BOOL current result, not {}", upper_name(op_node.text()), current_.info.type->name),
      op_node.range(), "compare first, e.g. GT 0");
}

bool IlChecker::expect_operands(SyntaxNode op_node, const std::vector<SyntaxNode>& operands, size_t count) {
  if (operands.size() == count) return true;
  const std::string name = upper_name(op_node.text());
  if (count == 0) {
    body_.report(codes::kIlOperandCount, fmt::format("{} takes no operand", name), operands[0].range());
    return false;
  }
  if (operands.empty()) {
    body_.report(codes::kIlOperandCount, fmt::format("{} needs an operand", name), op_node.range());
    return false;
  }
  body_.report(codes::kIlOperandCount, fmt::format("{} takes one operand, {} are given", name, operands.size()),
               operands[1].range());
  return false;
}

void IlChecker::check_jump_label(SyntaxNode label) {
  if (label.kind() == "identifier" && labels_.contains(upper_name(label.text()))) return;
  body_.report(codes::kUnknownLabel, fmt::format("JMP to '{}', which is not a label of this POU", label.text()),
               label.range(), "declare the label as 'name:' before an instruction");
}

void IlChecker::check_cal(SyntaxNode operand) {
  SyntaxNode callee_node = operand.kind() == "call_expression" ? operand.child_by_field("function") : operand;
  const Symbol* called =
      callee_node && callee_node.kind() == "identifier" ? model_.lookup(&pou_, callee_node.text()) : nullptr;
  if (called && called->kind == SymbolKind::Variable && called->section == ast::VarSection::Input &&
      called->owner == &pou_ && !model_.profile().call_input_instances && instance_block(model_.type_of(called))) {
    body_.report(codes::kNotCallable,
                 fmt::format("'{}' is a VAR_INPUT of this block: an instance passed as input cannot be called",
                             callee_node.text()),
                 callee_node.range(), "call the instance where it is declared, or pass it as VAR_IN_OUT");
  }
  if (operand.kind() == "call_expression") {
    body_.type_of(operand);  // the FB call with its parameter list: E301/E303/E305/E307 ...
    return;
  }
  ExprInfo target = body_.type_of(operand);
  if (target.type->is_unknown() && !target.names_type) return;
  const Symbol* block = instance_block(target.type);
  if (target.symbol && target.symbol->kind == SymbolKind::Program) block = target.symbol;
  if (target.names_type || !block) {
    body_.report(codes::kNotCallable,
                 target.names_type ? fmt::format("'{}' is a function block type; CAL needs an instance", operand.text())
                                   : fmt::format("'{}' is not a function block instance", operand.text()),
                 operand.range(), "declare an instance (e.g. fbX : FB_X;) and call that");
    return;
  }
  body_.check_arguments(block, true, {}, operand, 0);  // connects nothing: VAR_IN_OUT missing
}

bool IlChecker::check_fb_input(SyntaxNode op_node, const std::vector<SyntaxNode>& operands) {
  // S1 RS1, PT Timer1: sets the input of that name of the instance to the CR (IEC table 53).
  // Only a declared instance makes S, R, PT ... an input operator; look without reporting.
  if (operands.size() != 1 || operands[0].kind() != "identifier") return false;
  const Symbol* variable = model_.lookup(&pou_, operands[0].text());
  if (!variable || variable->kind != SymbolKind::Variable) return false;
  const Symbol* block = instance_block(model_.type_of(variable));
  if (!block) return false;
  body_.type_of(operands[0]);
  require_result(op_node);
  const Symbol* input = find_input(block, op_node.text());
  if (!input) {
    body_.report(codes::kUnknownMember, fmt::format("'{}' has no input '{}'", block->name, op_node.text()),
                 op_node.range());
    return true;
  }
  body_.check_conversion(current_.info, model_.type_of(input), op_node);
  return true;
}

void IlChecker::check_function_call(SyntaxNode instruction, SyntaxNode op_node,
                                    const std::vector<SyntaxNode>& operands) {
  // LIMIT 0, 100: a function whose first argument is the CR; its other arguments follow.
  const std::string_view name = op_node.text();
  const Symbol* callee = model_.lookup(&pou_, name);
  if (callee && (callee->kind == SymbolKind::Function || callee->kind == SymbolKind::Method)) {
    std::vector<CallArgument> arguments;
    if (has_inputs(*callee)) {
      require_result(op_node);
      ExprInfo first = current_.info;
      first.assignable = false;
      arguments.push_back(CallArgument{.node = op_node, .value = op_node, .typed = first});
    }
    if (model_.profile().il_extensible_two_inputs && operands.size() > 1 && has_extensible_input(*callee)) {
      body_.report(codes::kIlOperandCount,
                   fmt::format("in IL, {} takes the current result and one operand", upper_name(name)),
                   operands[1].range(), "compute the rest in further instructions, e.g. MAX b then MAX c");
    }
    for (SyntaxNode operand : operands) arguments.push_back(CallArgument{.node = operand, .value = operand});
    ExprInfo result = body_.check_arguments(callee, false, arguments, instruction, 0);
    // A function without a result type (OpenPCS: BOOL by default) leaves a value of unknown type.
    current_ = CurrentResult{
        true, ExprInfo{.type = result.type->kind == TypeKind::Void ? model_.types().unknown() : result.type}};
    return;
  }
  for (SyntaxNode operand : operands) {
    // JMPCL next1: a misspelt jump names a label, not a variable.
    if (!callee && operand.kind() == "identifier" && labels_.contains(upper_name(operand.text()))) continue;
    body_.type_of(operand);
  }
  if (callee) {
    const bool block = callee->kind == SymbolKind::FunctionBlock || instance_block(model_.type_of(callee)) != nullptr;
    body_.report(codes::kNotCallable,
                 block ? fmt::format("'{}' is a function block: call it with CAL", name)
                       : fmt::format("'{}' is not an IL operator or a function", name),
                 op_node.range());
  } else if (const Builtin* builtin = find_builtin(name); builtin && builtin->is_callable) {
    current_ = CurrentResult{true, ExprInfo{.type = builtin->value_type ? model_.types().elementary(builtin->value_type)
                                                                        : model_.types().unknown()}};
    return;
  } else if (keywords::is_reserved(name) && !keywords::is_type_name(name) && !keywords::is_operator_word(name)) {
    // OF, END_PROGRAM ... where an operator stands: the syntax check reports the stray keyword.
  } else {
    std::vector<std::string_view> candidates = {"JMPC", "JMPCN", "CALC", "CALCN", "RETC", "RETCN",
                                                "ANDN", "ORN",   "XORN", "LDN",   "STN"};
    const std::string_view suggestion = closest_name(name, candidates);
    body_.report(codes::kUnknownLibraryName, fmt::format("unknown IL operator or function '{}'", name), op_node.range(),
                 suggestion.empty() ? "declare the function, or add the stubs of the library it comes from"
                                    : fmt::format("did you mean '{}'?", suggestion));
  }
  current_ = CurrentResult{true, ExprInfo{.type = model_.types().unknown()}};
}

}  // namespace rung::check
