// Instruction List bodies. IL computes in one register, the current result (CR): LD sets it,
// operators combine it with their operand, ST copies it out (IEC 61131-3 2nd ed. 3.2; CODESYS V2.3
// manual, IL). Here the CR is one value-stack slot kept in a frame temporary; its type is known at
// compile time, following the instructions in order as IlChecker does, and every operator is
// typed by the checker's own rules (BodyChecker::binary_result), so IL computes what ST computes
// for the same expression. Parentheses `AND( ... )` get a fresh slot for their inner CR.
//
// Jumps are JMP_BACK (counted by the watchdog, whichever direction they go); JMPC/JMPCN, CALC/
// CALCN and RETC/RETCN test the CR first. A function call in the operator column takes the CR as
// its first argument (special_place() lets the argument binding load it); a standard function
// compiled inline (MAX, SEL, INT_TO_REAL, ...) needs the CR as it was loaded (`LD x` then `MAX 5`).
#include <fmt/format.h>

#include <utility>

#include "checker/symbols/names.hpp"
#include "checker/types/conversions.hpp"
#include "runner/compile/lowering.hpp"
#include "runner/stdlib/natives.hpp"

namespace rung::run {
namespace {

enum class IlKind : uint8_t { Load, Store, Set, Reset, Not, Logic, Arithmetic, Comparison, Jump, Call, Return, Other };

struct IlOp {
  IlKind kind = IlKind::Other;
  std::string_view op;  // as ST writes it (the checker's binary_result takes this)
  bool negated = false;
  bool conditional = false;
};

IlOp classify(std::string_view upper) {
  struct Row {
    std::string_view name;
    IlOp value;
  };
  static constexpr Row kRows[] = {
      {"LD", {IlKind::Load, "", false, false}},         {"LDN", {IlKind::Load, "", true, false}},
      {"ST", {IlKind::Store, "", false, false}},        {"STN", {IlKind::Store, "", true, false}},
      {"S", {IlKind::Set, "", false, false}},           {"R", {IlKind::Reset, "", false, false}},
      {"NOT", {IlKind::Not, "", false, false}},         {"AND", {IlKind::Logic, "AND", false, false}},
      {"ANDN", {IlKind::Logic, "AND", true, false}},    {"&", {IlKind::Logic, "AND", false, false}},
      {"&N", {IlKind::Logic, "AND", true, false}},      {"OR", {IlKind::Logic, "OR", false, false}},
      {"ORN", {IlKind::Logic, "OR", true, false}},      {"XOR", {IlKind::Logic, "XOR", false, false}},
      {"XORN", {IlKind::Logic, "XOR", true, false}},    {"ADD", {IlKind::Arithmetic, "+", false, false}},
      {"SUB", {IlKind::Arithmetic, "-", false, false}}, {"MUL", {IlKind::Arithmetic, "*", false, false}},
      {"DIV", {IlKind::Arithmetic, "/", false, false}}, {"MOD", {IlKind::Arithmetic, "MOD", false, false}},
      {"GT", {IlKind::Comparison, ">", false, false}},  {"GE", {IlKind::Comparison, ">=", false, false}},
      {"EQ", {IlKind::Comparison, "=", false, false}},  {"NE", {IlKind::Comparison, "<>", false, false}},
      {"LE", {IlKind::Comparison, "<=", false, false}}, {"LT", {IlKind::Comparison, "<", false, false}},
      {"JMP", {IlKind::Jump, "", false, false}},        {"JMPC", {IlKind::Jump, "", false, true}},
      {"JMPCN", {IlKind::Jump, "", true, true}},        {"CAL", {IlKind::Call, "", false, false}},
      {"CALC", {IlKind::Call, "", false, true}},        {"CALCN", {IlKind::Call, "", true, true}},
      {"RET", {IlKind::Return, "", false, false}},      {"RETC", {IlKind::Return, "", false, true}},
      {"RETCN", {IlKind::Return, "", true, true}},      {"RETURN", {IlKind::Return, "", false, false}},
  };
  for (const Row& row : kRows) {
    if (row.name == upper) return row.value;
  }
  return {};
}

// The inputs IEC 61131-3 table 53 lets stand in the operator column with an instance as operand.
bool is_fb_input_operator(std::string_view upper) {
  return upper == "S1" || upper == "R1" || upper == "S" || upper == "R" || upper == "CLK" || upper == "CU" ||
         upper == "CD" || upper == "PV" || upper == "IN" || upper == "PT";
}

bool has_token(SyntaxNode node, std::string_view text) {
  for (uint32_t i = 0; i < node.child_count(); ++i) {
    if (!node.child(i).is_named() && node.child(i).text() == text) return true;
  }
  return false;
}

bool is_signed(Scalar scalar) {
  return scalar == Scalar::S8 || scalar == Scalar::S16 || scalar == Scalar::S32 || scalar == Scalar::I64;
}

// The block an instance's type names (FUNCTION_BLOCK, CLASS), or nullptr.
const Symbol* block_of(const Type* type) {
  type = Layouts::storage_type(type);
  if (type && type->kind == TypeKind::Reference) type = Layouts::storage_type(type->element);
  if (!type || type->kind != TypeKind::Pou || !type->declaration) return nullptr;
  return type->declaration->kind == SymbolKind::FunctionBlock || type->declaration->kind == SymbolKind::Class
             ? type->declaration
             : nullptr;
}

ExprInfo typed_as(const Type* type) {
  ExprInfo info;
  info.type = type;
  return info;
}

check::CallArgument argument_of(SyntaxNode node, SyntaxNode value, std::optional<ExprInfo> typed) {
  check::CallArgument argument;
  argument.node = node;
  argument.value = value;
  argument.typed = std::move(typed);
  return argument;
}

}  // namespace

void BodyCompiler::il_body(SyntaxNode body) {
  il_ = IlResult{};
  il_.slot = temporary(elementary("LWORD"));
  il_.type = elementary("BOOL");
  il_.info = typed_as(il_.type);
  il_sequence(body);
}

void BodyCompiler::il_sequence(SyntaxNode parent) {
  for (uint32_t i = 0; i < parent.named_child_count(); ++i) {
    SyntaxNode child = parent.named_child(i);
    const std::string_view kind = child.kind();
    if (kind == "il_label") {
      labels_[check::upper_name(child.child_by_field("name").text())] = here();
      il_.loaded = {};
    } else if (kind == "il_instruction") {
      il_instruction(child);
    } else if (kind == "sfc_step_macro") {
      sfc_step_macro(child);
    }
  }
}

void BodyCompiler::il_set(const Type* type, const ExprInfo& info) {
  emit(Op::ST_64_F, static_cast<uint32_t>(il_.slot));
  il_.type = type;
  il_.info = info;
  il_.info.assignable = false;
  il_.info.symbol = nullptr;
  il_.loaded = {};
}

void BodyCompiler::il_negate(const Type* type) {
  const Type* storage = Layouts::storage_type(type);
  if (storage && storage->kind == TypeKind::Bool) {
    emit(Op::BNOT);
    return;
  }
  // Bitwise: the complement of a zero-extended value is cut back to the type's width.
  emit(Op::NOT);
  convert(is_signed(scalar_kind(type)) ? elementary("LINT") : elementary("LWORD"), type);
}

void BodyCompiler::il_load(SyntaxNode operand, bool negate) {
  ExprInfo operand_info = info(operand);
  const Type* type = value(operand);
  if (auto special = special_place(operand)) {
    // step.X, step.T: the checker does not type them; their place does.
    operand_info = typed_as(special->type);
    type = special->type;
  }
  if (negate) il_negate(type);
  il_set(type, operand_info);
  // (A built-in called next reads this operand again: only when that has no side effect.)
  if (!negate && operand.kind() != "call_expression") il_.loaded = operand;
}

void BodyCompiler::il_instruction(SyntaxNode instruction) {
  set_position(instruction);
  SyntaxNode op_node = instruction.child_by_field("operator");
  if (!op_node || op_node.is_missing()) return;
  const std::string name = check::upper_name(op_node.text());
  const IlOp op = classify(name);
  const std::vector<SyntaxNode> operands = instruction.children_by_field("operand");
  if (has_token(instruction, "(")) {
    il_deferred(instruction, name);
    return;
  }
  if (is_fb_input_operator(name) && operands.size() == 1 && il_fb_input(name, operands[0])) return;
  auto conditional_skip = [&]() -> std::optional<uint32_t> {
    if (!op.conditional) return std::nullopt;
    emit(Op::LD_I64_F, static_cast<uint32_t>(il_.slot));
    return emit(op.negated ? Op::JNZ : Op::JZ);
  };
  switch (op.kind) {
    case IlKind::Load:
      if (!operands.empty()) il_load(operands[0], op.negated);
      return;
    case IlKind::Store:
      if (!operands.empty()) il_store(operands[0], op.negated, -1);
      return;
    case IlKind::Set:
    case IlKind::Reset:
      if (!operands.empty()) il_store(operands[0], false, op.kind == IlKind::Set ? 1 : 0);
      return;
    case IlKind::Not: {
      emit(Op::LD_I64_F, static_cast<uint32_t>(il_.slot));
      il_negate(il_.type);
      const ExprInfo kept = il_.info;
      il_set(il_.type, kept);
      return;
    }
    case IlKind::Logic:
    case IlKind::Arithmetic:
    case IlKind::Comparison: {
      if (operands.empty()) return;
      ExprInfo operand_info = info(operands[0]);
      if (auto special = special_place(operands[0])) operand_info = typed_as(special->type);
      il_combine(name, operand_info, IlOperand{operands[0], nullptr, op.negated}, operands[0]);
      return;
    }
    case IlKind::Jump: {
      if (operands.empty()) return;
      const auto skip = conditional_skip();
      jumps_.emplace_back(emit(Op::JMP_BACK), check::upper_name(operands[0].text()));
      if (skip) patch(*skip, here());
      il_.loaded = {};
      return;
    }
    case IlKind::Call: {
      if (operands.empty()) return;
      const auto skip = conditional_skip();
      il_call(operands[0]);
      if (skip) patch(*skip, here());
      il_.loaded = {};
      return;
    }
    case IlKind::Return: {
      if (op.conditional) {
        emit(Op::LD_I64_F, static_cast<uint32_t>(il_.slot));
        returns_.push_back(emit(op.negated ? Op::JZ : Op::JNZ));
      } else {
        returns_.push_back(emit(Op::JMP));
      }
      return;
    }
    case IlKind::Other: il_function(instruction, op_node); return;
  }
}

void BodyCompiler::il_deferred(SyntaxNode instruction, std::string_view name) {
  // AND( ... ): the CR waits while the parentheses compute the operand (IEC 2nd ed. 3.2.2).
  const IlOp op = classify(name);
  if (op.kind != IlKind::Logic && op.kind != IlKind::Arithmetic && op.kind != IlKind::Comparison) {
    fail(instruction, fmt::format("{} cannot be deferred with '('", name));
    return;
  }
  const IlResult waiting = il_;
  il_ = IlResult{};
  il_.slot = temporary(elementary("LWORD"));
  il_.type = waiting.type;
  il_.info = waiting.info;
  const std::vector<SyntaxNode> operands = instruction.children_by_field("operand");
  if (!operands.empty()) il_load(operands[0], false);
  il_sequence(instruction);
  const IlResult inner = il_;
  il_ = waiting;
  il_combine(name, inner.info, IlOperand{SyntaxNode(), &inner, op.negated}, instruction);
}

void BodyCompiler::il_push_operand(const IlOperand& operand, const Type* target) {
  const Type* own = nullptr;
  if (operand.inner) {
    emit(Op::LD_I64_F, static_cast<uint32_t>(operand.inner->slot));
    own = operand.inner->type;
  } else {
    own = value(operand.node);
    if (auto special = special_place(operand.node)) own = special->type;
  }
  // The N modifier negates the operand in its own type, before it widens (ANDN on a WORD).
  if (operand.negate) il_negate(own);
  convert(own, target);
}

void BodyCompiler::il_combine(std::string_view name, const ExprInfo& operand_info, const IlOperand& operand,
                              SyntaxNode where) {
  const IlOp op = classify(name);
  ExprInfo right = operand_info;
  right.assignable = false;
  const ExprInfo result = checker_.binary_result(op.op, il_.info, right, where, where.range(), name);
  const Type* result_type = Layouts::storage_type(result.type);
  if (!result_type || result_type->is_unknown() || scalar_kind(result_type) == Scalar::None) {
    // Strings compare through the runtime's comparison; anything else is not typed here.
    const Type* left_type = Layouts::storage_type(il_.type);
    const bool text = left_type && (left_type->kind == TypeKind::String || left_type->kind == TypeKind::WString);
    if (op.kind == IlKind::Comparison && text) {
      const bool wide = left_type->kind == TypeKind::WString;
      emit(Op::LD_I64_F, static_cast<uint32_t>(il_.slot));
      il_push_operand(operand, nullptr);
      emit(Op::NATIVE, lowering_.native(wide ? native_wstring_compare : native_string_compare,
                                        wide ? "WSTRING_COMPARE" : "STRING_COMPARE"));
      emit(Op::PUSH, 0, 0);
      static constexpr std::pair<std::string_view, Op> kTextOps[] = {
          {"=", Op::EQ}, {"<>", Op::NE}, {"<", Op::LT_S}, {"<=", Op::LE_S}, {">", Op::GT_S}, {">=", Op::GE_S}};
      for (const auto& [text_op, code] : kTextOps) {
        if (text_op == op.op) emit(code);
      }
      il_set(bool_type(), typed_as(bool_type()));
      return;
    }
    fail(where, fmt::format("rung cannot run {} on these operands in IL yet", name));
    return;
  }
  // The type both sides are computed in: the comparison's common type, else the result's.
  const Type* computed = arithmetic_type(result_type);
  if (op.kind == IlKind::Comparison) {
    if (right.untyped_literal && !il_.info.untyped_literal) {
      computed = arithmetic_type(il_.info.type);
    } else if (il_.info.untyped_literal && !right.untyped_literal) {
      computed = arithmetic_type(right.type);
    } else {
      computed = check::common_numeric_type(arithmetic_type(il_.info.type), arithmetic_type(right.type),
                                            lowering_.model().types());
      computed = arithmetic_type(computed ? computed : il_.info.type);
    }
  } else if (op.kind == IlKind::Logic) {
    computed = result_type;
  }
  const Scalar scalar = scalar_kind(computed);
  if (scalar == Scalar::None) {
    fail(where, fmt::format("rung cannot run {} on these operands in IL yet", name));
    return;
  }
  emit(Op::LD_I64_F, static_cast<uint32_t>(il_.slot));
  convert(il_.type, computed);
  il_push_operand(operand, computed);
  const bool single = scalar == Scalar::F32;
  const bool real = single || scalar == Scalar::F64;
  const bool sign = is_signed(scalar);
  struct Code {
    std::string_view op;
    Op integer_signed, integer_unsigned, f32, f64;
  };
  static constexpr Code kCodes[] = {
      {"AND", Op::AND, Op::AND, Op::HALT, Op::HALT},         {"OR", Op::OR, Op::OR, Op::HALT, Op::HALT},
      {"XOR", Op::XOR, Op::XOR, Op::HALT, Op::HALT},         {"+", Op::ADD, Op::ADD, Op::ADD_F32, Op::ADD_F64},
      {"-", Op::SUB, Op::SUB, Op::SUB_F32, Op::SUB_F64},     {"*", Op::MUL, Op::MUL, Op::MUL_F32, Op::MUL_F64},
      {"/", Op::DIV_S, Op::DIV_U, Op::DIV_F32, Op::DIV_F64}, {"MOD", Op::MOD_S, Op::MOD_U, Op::HALT, Op::HALT},
      {">", Op::GT_S, Op::GT_U, Op::GT_F32, Op::GT_F64},     {">=", Op::GE_S, Op::GE_U, Op::GE_F32, Op::GE_F64},
      {"=", Op::EQ, Op::EQ, Op::EQ_F32, Op::EQ_F64},         {"<>", Op::NE, Op::NE, Op::NE_F32, Op::NE_F64},
      {"<=", Op::LE_S, Op::LE_U, Op::LE_F32, Op::LE_F64},    {"<", Op::LT_S, Op::LT_U, Op::LT_F32, Op::LT_F64},
  };
  Op code = Op::HALT;
  for (const Code& row : kCodes) {
    if (row.op == op.op)
      code = real ? (single ? row.f32 : row.f64) : (sign ? row.integer_signed : row.integer_unsigned);
  }
  if (code == Op::HALT) {
    fail(where, fmt::format("{} needs integer operands", name));
    return;
  }
  emit(code);
  if (op.kind == IlKind::Comparison) {
    il_set(bool_type(), result);
    return;
  }
  // Arithmetic wraps in the computed type's width (as ST does).
  if (op.kind == IlKind::Arithmetic && !real) convert(elementary(sign ? "LINT" : "LWORD"), computed);
  il_set(computed, result);
}

void BodyCompiler::il_store(SyntaxNode operand, bool negate, int set_value) {
  auto target = place(operand);
  if (!target || !target->type) {
    fail(operand, "rung cannot store the current result here yet");
    return;
  }
  Place at = *target;
  if (at.mode == Place::Mode::Pointer || (scalar_kind(at.type) == Scalar::None && at.bit < 0)) at = as_pointer(at);
  std::optional<uint32_t> skip;
  if (set_value >= 0) {
    // S / R: only when the CR is TRUE (IEC 61131-3 table 52).
    emit(Op::LD_I64_F, static_cast<uint32_t>(il_.slot));
    skip = emit(Op::JZ);
  }
  Place word = at;
  word.bit = -1;
  if (at.bit >= 0) {
    if (at.mode == Place::Mode::Pointer) emit(Op::DUP);
    load(word);
  }
  const Type* destination = at.bit >= 0 ? bool_type() : at.type;
  if (set_value >= 0) {
    emit(Op::PUSH, 0, set_value);
  } else {
    emit(Op::LD_I64_F, static_cast<uint32_t>(il_.slot));
    if (negate) il_negate(il_.type);
    if (scalar_kind(at.type) != Scalar::None || at.bit >= 0) convert(il_.type, destination);
  }
  if (at.bit >= 0) emit(Op::BIT_SET, static_cast<uint32_t>(at.bit));
  store(word, scalar_kind(at.type) == Scalar::None ? il_.type : word.type);
  if (skip) {
    if (at.mode == Place::Mode::Pointer) {
      const uint32_t done = emit(Op::JMP);
      patch(*skip, here());
      emit(Op::POP);
      patch(done, here());
    } else {
      patch(*skip, here());
    }
  }
}

bool BodyCompiler::il_fb_input(std::string_view name, SyntaxNode operand) {
  // S1 RS1, PT Timer1: the input of that name of the instance takes the CR (IEC table 53).
  if (operand.kind() != "identifier") return false;
  const ExprInfo operand_info = info(operand);
  const Symbol* variable = operand_info.symbol;
  if (!variable || variable->kind != SymbolKind::Variable) return false;
  const Symbol* block = block_of(variable->type);
  if (!block) return false;
  const Symbol* input = nullptr;
  for (const Symbol* scope = block; scope && !input; scope = scope->base == scope ? nullptr : scope->base) {
    for (const Symbol* member : scope->ordered) {
      if (member->kind != SymbolKind::Variable || member->section != ast::VarSection::Input) continue;
      const check::Attribute* alias = member->attribute("rung.alias");
      if (check::names_equal(member->name, name) || (alias && check::names_equal(alias->value, name))) {
        input = member;
        break;
      }
    }
  }
  if (!input) return false;
  auto instance = place(operand);
  if (!instance) return false;
  lowering_.layouts().pou(block);
  Place at = *instance;
  at.offset += lowering_.layouts().offset(input);
  at.type = input->type;
  at.bit = -1;
  if (at.mode == Place::Mode::Pointer) at = as_pointer(at);
  emit(Op::LD_I64_F, static_cast<uint32_t>(il_.slot));
  convert(il_.type, input->type);
  store(at, input->type);
  return true;
}

void BodyCompiler::il_call(SyntaxNode operand) {
  // CAL fb(IN := x, PT := t) is the ST call; CAL fb and CAL prog call without arguments.
  if (operand.kind() == "call_expression") {
    call(operand, false);
    return;
  }
  const ExprInfo target = info(operand);
  if (target.symbol && target.symbol->kind == SymbolKind::Program) {
    const Place instance{Place::Mode::Global, lowering_.program_instance(target.symbol), target.symbol->type, -1,
                         target.symbol};
    instance_call(target.symbol, instance, target.symbol, {}, operand);
    return;
  }
  const Symbol* block = block_of(target.type);
  auto instance = block ? place(operand) : std::nullopt;
  if (!instance) {
    fail(operand, fmt::format("rung cannot CAL '{}'", operand.text()));
    return;
  }
  instance_call(block, *instance, block, {}, operand);
}

void BodyCompiler::il_function(SyntaxNode instruction, SyntaxNode op_node) {
  // LIMIT 0, 100: a function whose first argument is the CR, the others follow (IEC 3.2.3).
  const Symbol* callee = lowering_.model().lookup(pou_, op_node.text());
  const std::string upper = check::upper_name(op_node.text());
  if (const size_t at = upper.rfind("_TO_"); !callee && at != std::string::npos && il_.loaded) {
    // A conversion without a declaration (INT_TO_REAL): the built-in, typed by its name.
    const Type* target = elementary(upper.substr(at + 4));
    std::vector<check::CallArgument> arguments{argument_of(op_node, il_.loaded, il_.info)};
    auto pushed = target ? builtin_call(upper, instruction, nullptr, arguments, typed_as(target)) : std::nullopt;
    if (!pushed) {
      fail(op_node, fmt::format("rung cannot run '{}' in IL yet", op_node.text()));
      return;
    }
    il_set(*pushed, typed_as(*pushed));
    return;
  }
  if (!callee || callee->kind != SymbolKind::Function) {
    fail(op_node, fmt::format("rung cannot run the IL operator '{}' yet", op_node.text()));
    return;
  }
  bool has_inputs = false;
  for (const Symbol* member : callee->ordered) {
    has_inputs = has_inputs || (member->kind == SymbolKind::Variable && (member->section == ast::VarSection::Input ||
                                                                         member->section == ast::VarSection::InOut));
  }
  std::vector<check::CallArgument> arguments;
  SyntaxNode body = callee->node.child_by_field("body");
  const bool builtin =
      callee->has(check::kLibrary) && (!body || (body.kind() == "statement_list" && ast::statements(body).empty()));
  if (has_inputs) {
    // A built-in reads its first argument's type from the syntax: give it the LD's operand.
    SyntaxNode first = builtin && il_.loaded ? il_.loaded : op_node;
    if (builtin && !il_.loaded) {
      fail(op_node, fmt::format("rung runs the standard function {} in IL only right after LD", op_node.text()));
      return;
    }
    arguments.push_back(argument_of(op_node, first, il_.info));
  }
  for (SyntaxNode operand : instruction.children_by_field("operand")) {
    arguments.push_back(argument_of(operand, operand, std::nullopt));
  }
  const ExprInfo call_info = checker_.check_arguments(callee, false, arguments, instruction, 0);
  const Type* result = nullptr;
  if (builtin) {
    auto pushed = builtin_call(callee->name, instruction, callee, arguments, call_info);
    if (!pushed) {
      fail(op_node, fmt::format("rung cannot run '{}' in IL yet", op_node.text()));
      return;
    }
    result = *pushed;
  } else {
    il_first_argument_ = op_node;
    result = function_call(callee, arguments, true, instruction);
    il_first_argument_ = {};
  }
  if (!result || result->kind == TypeKind::Void) {
    il_.loaded = {};
    return;
  }
  il_set(result, typed_as(call_info.type && !call_info.type->is_unknown() ? call_info.type : result));
}

}  // namespace rung::run
