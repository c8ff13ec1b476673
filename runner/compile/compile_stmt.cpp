// Statements: assignments, IF, CASE, FOR, WHILE, REPEAT, EXIT, CONTINUE, RETURN, JMP and labels.
// Loops jump back with JMP_BACK, which counts against the watchdog's budget.
#include <fmt/format.h>

#include "checker/symbols/names.hpp"
#include "runner/compile/lowering.hpp"

namespace rung::run {
namespace {

bool is_integer_type(const Type* type) {
  const Scalar scalar = scalar_kind(type);
  return scalar != Scalar::None && scalar != Scalar::F32 && scalar != Scalar::F64;
}

}  // namespace

void BodyCompiler::statement_list(SyntaxNode list) {
  if (!list) return;
  for (SyntaxNode statement_node : ast::statements(list)) statement(statement_node);
}

void BodyCompiler::statement(SyntaxNode node) {
  set_position(node);
  using Kind = ast::StatementKind;
  switch (ast::statement_kind(node)) {
    case Kind::Assignment: {
      assignment(node.child_by_field("left"), node.child_by_field("right"), node.child_by_field("operator").text());
      return;
    }
    case Kind::Call: {
      SyntaxNode call_node = node.named_child(0);
      if (call_node) {
        const Type* result = call(call_node, false);
        (void)result;
      }
      return;
    }
    case Kind::If: if_statement(node); return;
    case Kind::Case: case_statement(node); return;
    case Kind::For: for_statement(node); return;
    case Kind::While: while_statement(node); return;
    case Kind::Repeat: repeat_statement(node); return;
    case Kind::Exit:
      if (loops_.empty()) {
        fail(node, "EXIT outside a loop");
        return;
      }
      loops_.back().exits.push_back(emit(Op::JMP));
      return;
    case Kind::Continue:
      if (loops_.empty()) {
        fail(node, "CONTINUE outside a loop");
        return;
      }
      loops_.back().continues.push_back(emit(Op::JMP));
      return;
    case Kind::Return: {
      SyntaxNode condition = node.child_by_field("condition");
      if (condition) {
        // IL-style RETURN with a condition (RETC) written in ST by some dialects.
        value_as_bool(condition);
        returns_.push_back(emit(Op::JNZ));
        return;
      }
      returns_.push_back(emit(Op::JMP));
      return;
    }
    case Kind::Jump: {
      SyntaxNode label = node.child_by_field("label");
      jumps_.emplace_back(emit(Op::JMP_BACK), check::upper_name(label.text()));
      return;
    }
    case Kind::Label: {
      labels_[check::upper_name(node.child_by_field("name").text())] = here();
      return;
    }
    case Kind::Empty: return;
    case Kind::Try:
      statement_list(node.child_by_field("body"));
      return;
    case Kind::Unknown:
      if (node.kind() == "pragma" || node.kind() == "comment") return;
      fail(node, fmt::format("rung cannot run this statement yet ({})", node.kind()));
      return;
  }
}

void BodyCompiler::assignment(SyntaxNode left, SyntaxNode right, std::string_view op) {
  const ExprInfo target_info = info(left);
  // An assignment to a property calls its SET accessor.
  if (target_info.symbol && target_info.symbol->kind == SymbolKind::Property && !inside_accessor_of(target_info.symbol)) {
    property_write(left, target_info.symbol, right);
    return;
  }
  if (check::names_equal(op, "REF=")) {
    // ref REF= x: the reference's own slot takes x's address.
    const Symbol* reference = target_info.symbol;
    if (!reference || reference->kind != SymbolKind::Variable || !Layouts::held_by_reference(reference)) {
      fail(left, "REF= needs a REFERENCE variable on its left");
      return;
    }
    const Storage storage = lowering_.storage_of(reference, pou_);
    if (storage.kind == Storage::Kind::None) {
      fail(left, "rung cannot assign to this yet");
      return;
    }
    // `ref REF= 0` clears the reference (__ISVALIDREF is FALSE afterwards).
    const auto constant = lowering_.model().constant_value(right, pou_);
    if (constant && constant->is_integer() && constant->integer == 0) {
      emit(Op::PUSH, 0, 0);
    } else {
      auto source = place(right);
      if (!source) {
        fail(right, "REF= needs a variable on its right");
        return;
      }
      address_of(*source);
    }
    const Op op_store = storage.kind == Storage::Kind::Global     ? Op::ST_64_G
                        : storage.kind == Storage::Kind::Instance ? Op::ST_64_I
                                                                  : Op::ST_64_F;
    emit(op_store, static_cast<uint32_t>(storage.offset));
    return;
  }
  writing_ = true;
  auto target = place(left);
  writing_ = false;
  if (!target || !target->type) {
    fail(left, "rung cannot assign to this yet");
    return;
  }
  const bool set_reset = check::names_equal(op, "S=") || check::names_equal(op, "R=");
  if (set_reset) {
    // x S= c: IF c THEN x := TRUE; x R= c: IF c THEN x := FALSE.
    Place at = *target;
    if (at.mode == Place::Mode::Pointer) at = as_pointer(at);
    value_as_bool(right);
    const uint32_t skip = emit(Op::JZ);
    if (at.bit >= 0) {
      if (at.mode == Place::Mode::Pointer) emit(Op::DUP);
      load(at);
      emit(Op::PUSH, 0, check::names_equal(op, "S=") ? 1 : 0);
      emit(Op::BIT_SET, static_cast<uint32_t>(at.bit));
    } else {
      emit(Op::PUSH, 0, check::names_equal(op, "S=") ? 1 : 0);
    }
    Place word = at;
    word.bit = -1;
    store(word, word.type);
    if (at.mode == Place::Mode::Pointer) {
      const uint32_t done = emit(Op::JMP);
      patch(skip, here());
      emit(Op::POP);
      patch(done, here());
    } else {
      patch(skip, here());
    }
    return;
  }
  Place at = *target;
  const Scalar scalar = scalar_kind(at.type);
  if (at.bit >= 0) {
    if (at.mode == Place::Mode::Pointer) {
      at = as_pointer(at);
      emit(Op::DUP);
    }
    Place word = at;
    word.bit = -1;
    load(word);
    value_as_bool(right);
    emit(Op::BIT_SET, static_cast<uint32_t>(at.bit));
    store(word, word.type);
    return;
  }
  if (scalar == Scalar::None) {
    at = as_pointer(at);
    const Type* pushed = value(right, at.type);
    store(at, pushed);
    return;
  }
  if (at.mode == Place::Mode::Pointer) at = as_pointer(at);
  value(right, at.type);
  range_check(at.type);
  store(at, at.type);
}

void BodyCompiler::if_statement(SyntaxNode node) {
  std::vector<uint32_t> to_end;
  value_as_bool(node.child_by_field("condition"));
  uint32_t next = emit(Op::JZ);
  statement_list(node.child_by_field("body"));
  for (SyntaxNode clause : node.children_of_kind("elsif_clause")) {
    to_end.push_back(emit(Op::JMP));
    patch(next, here());
    set_position(clause);
    value_as_bool(clause.child_by_field("condition"));
    next = emit(Op::JZ);
    statement_list(clause.child_by_field("body"));
  }
  const std::vector<SyntaxNode> otherwise = node.children_of_kind("else_clause");
  if (!otherwise.empty()) {
    to_end.push_back(emit(Op::JMP));
    patch(next, here());
    statement_list(otherwise.front().child_by_field("body"));
  } else {
    patch(next, here());
  }
  for (uint32_t jump : to_end) patch(jump, here());
}

void BodyCompiler::case_statement(SyntaxNode node) {
  SyntaxNode selector = node.child_by_field("value");
  const ExprInfo selector_info = info(selector);
  const Type* type = arithmetic_type(selector_info.type);
  if (!is_integer_type(type)) {
    fail(selector, "CASE needs an integer or enumeration selector");
    return;
  }
  // The selector is evaluated once, into a temporary.
  const uint64_t slot = temporary(elementary("LINT"));
  value(selector, elementary("LINT"));
  emit(Op::ST_64_F, static_cast<uint32_t>(slot));
  std::vector<uint32_t> to_end;
  for (SyntaxNode element : node.children_of_kind("case_element")) {
    set_position(element);
    std::vector<uint32_t> matches;
    for (SyntaxNode label : element.children_by_field("label")) {
      if (label.kind() == "range") {
        // lower..upper
        emit(Op::LD_I64_F, static_cast<uint32_t>(slot));
        value(label.child_by_field("lower"), elementary("LINT"));
        emit(Op::GE_S);
        const uint32_t below = emit(Op::JZ);
        emit(Op::LD_I64_F, static_cast<uint32_t>(slot));
        value(label.child_by_field("upper"), elementary("LINT"));
        emit(Op::LE_S);
        matches.push_back(emit(Op::JNZ));
        patch(below, here());
      } else {
        emit(Op::LD_I64_F, static_cast<uint32_t>(slot));
        value(label, elementary("LINT"));
        emit(Op::EQ);
        matches.push_back(emit(Op::JNZ));
      }
    }
    const uint32_t skip = emit(Op::JMP);
    for (uint32_t match : matches) patch(match, here());
    statement_list(element.child_by_field("body"));
    to_end.push_back(emit(Op::JMP));
    patch(skip, here());
  }
  const std::vector<SyntaxNode> otherwise = node.children_of_kind("else_clause");
  if (!otherwise.empty()) statement_list(otherwise.front().child_by_field("body"));
  for (uint32_t jump : to_end) patch(jump, here());
}

void BodyCompiler::for_statement(SyntaxNode node) {
  SyntaxNode variable = node.child_by_field("variable");
  auto counter = place(variable);
  if (!counter || !is_integer_type(counter->type)) {
    fail(variable, "FOR needs an integer variable");
    return;
  }
  const Type* counter_type = counter->type;
  const Type* wide = elementary("LINT");
  Place at = *counter;
  if (at.mode == Place::Mode::Pointer) {
    fail(variable, "a FOR counter reached through a pointer or reference is not supported");
    return;
  }
  // The end and step are evaluated once, before the first iteration (IEC 61131-3 7.3.3.4.2).
  value(node.child_by_field("start"), counter_type);
  store(at, counter_type);
  const uint64_t end_slot = temporary(wide);
  value(node.child_by_field("end"), wide);
  emit(Op::ST_64_F, static_cast<uint32_t>(end_slot));
  const uint64_t step_slot = temporary(wide);
  SyntaxNode step = node.child_by_field("step");
  std::optional<int64_t> constant_step = 1;
  if (step) {
    const ExprInfo step_info = info(step);
    constant_step.reset();
    if (step_info.value && step_info.value->is_integer()) constant_step = static_cast<int64_t>(step_info.value->integer);
    value(step, wide);
  } else {
    emit(Op::PUSH, 0, 1);
  }
  emit(Op::ST_64_F, static_cast<uint32_t>(step_slot));

  // test: counter <= end (step >= 0) or counter >= end (step < 0)
  const uint32_t test = here();
  load(at);
  convert(counter_type, wide);
  emit(Op::LD_I64_F, static_cast<uint32_t>(end_slot));
  if (constant_step) {
    emit(*constant_step >= 0 ? Op::LE_S : Op::GE_S);
  } else {
    // (step >= 0 AND counter <= end) OR (step < 0 AND counter >= end)
    emit(Op::OVER);
    emit(Op::OVER);
    emit(Op::LE_S);
    emit(Op::LD_I64_F, static_cast<uint32_t>(step_slot));
    emit(Op::PUSH, 0, 0);
    emit(Op::GE_S);
    emit(Op::AND);
    const uint32_t done = emit(Op::JNZ_KEEP);
    emit(Op::GE_S);
    emit(Op::LD_I64_F, static_cast<uint32_t>(step_slot));
    emit(Op::PUSH, 0, 0);
    emit(Op::LT_S);
    emit(Op::AND);
    const uint32_t joined = emit(Op::JMP);
    patch(done, here());
    emit(Op::SWAP);
    emit(Op::POP);
    emit(Op::SWAP);
    emit(Op::POP);
    patch(joined, here());
  }
  const uint32_t leave = emit(Op::JZ);
  loops_.emplace_back();
  statement_list(node.child_by_field("body"));
  Loop loop = std::move(loops_.back());
  loops_.pop_back();
  for (uint32_t jump : loop.continues) patch(jump, here());
  // counter := counter + step; leave when it would pass the type's range (no endless wrap).
  load(at);
  convert(counter_type, wide);
  emit(Op::LD_I64_F, static_cast<uint32_t>(step_slot));
  emit(Op::ADD);
  store(at, counter_type);
  emit(Op::JMP_BACK, test);
  patch(leave, here());
  for (uint32_t jump : loop.exits) patch(jump, here());
}

void BodyCompiler::while_statement(SyntaxNode node) {
  const uint32_t test = here();
  value_as_bool(node.child_by_field("condition"));
  const uint32_t leave = emit(Op::JZ);
  loops_.emplace_back();
  statement_list(node.child_by_field("body"));
  Loop loop = std::move(loops_.back());
  loops_.pop_back();
  for (uint32_t jump : loop.continues) patch(jump, test);
  emit(Op::JMP_BACK, test);
  patch(leave, here());
  for (uint32_t jump : loop.exits) patch(jump, here());
}

void BodyCompiler::repeat_statement(SyntaxNode node) {
  const uint32_t start = here();
  loops_.emplace_back();
  statement_list(node.child_by_field("body"));
  Loop loop = std::move(loops_.back());
  loops_.pop_back();
  const uint32_t test = here();
  for (uint32_t jump : loop.continues) patch(jump, test);
  value_as_bool(node.child_by_field("condition"));
  const uint32_t leave = emit(Op::JNZ);
  emit(Op::JMP_BACK, start);
  patch(leave, here());
  for (uint32_t jump : loop.exits) patch(jump, here());
}

}  // namespace rung::run
