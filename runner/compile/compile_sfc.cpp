// Textual SFC bodies (IEC 61131-3 2nd ed. 2.6). The chart's state lives in the POU's instance
// (SfcLayout, reserved by Layouts::pou): per step X, T and its activation time, per associated
// action its action control state. One call of the POU is one SFC cycle, in this order (CODESYS:
// "in one cycle all actions of active steps run; when the following transition is TRUE the next
// step becomes active and runs in the next cycle", V2.3 manual L868-879):
//
//  1. SFCPause TRUE (when declared): nothing happens in this call.
//  2. the first call, or SFCInit/SFCReset TRUE: every step inactive but the initial ones, every
//     action control cleared; with SFCInit TRUE nothing else happens in this call.
//  3. each active step's T := time since its activation; each action's control (IEC Fig. 21:
//     N, R, S, L, D, P, P1, P0, SD, DS, SL with their times) computes its Q.
//  4. actions, in the order the chart first names them: an action runs while Q is TRUE and once
//     more in the call where Q falls (the final scan; CODESYS V2.3 L945); a BOOL variable
//     associated instead takes Q.
//  5. transitions in source order: one fires when all its FROM steps are active and not taken by
//     an earlier transition in this call (selective branches: the first TRUE wins) and its
//     condition is TRUE; then its FROM steps go inactive and its TO steps active (simultaneous
//     branches: several TO steps; convergence: several FROM steps), effective at the end of
//     the call, so a step activated now runs its actions in the next call. SFCTrans (when
//     declared) tells whether one fired.
//
// The control logic is one native (sfc_control) that reads a descriptor of the chart from the
// constant image; conditions and actions are compiled code.
#include <fmt/format.h>

#include <algorithm>
#include <cstring>

#include "checker/symbols/names.hpp"
#include "runner/compile/lowering.hpp"
#include "runner/vm/machine.hpp"

namespace rung::run {
namespace {

enum class Qualifier : uint32_t { N, R, S, L, D, P, P0, P1, SD, DS, SL };

struct DescriptorHeader {
  uint32_t steps = 0;
  uint32_t actions = 0;
  uint32_t associations = 0;
  uint32_t state = 0;  // SfcLayout::offset
};

struct Association {
  uint32_t step = 0;
  uint32_t action = 0;
  uint32_t qualifier = 0;
  uint32_t pad = 0;
  int64_t time_ns = 0;
};

// Bytes in a step's record and an action's record (SfcLayout).
constexpr uint64_t kStepX = 0, kStepTaken = 1, kStepNext = 2, kStepT = 4, kStepStart = 8;
constexpr uint64_t kActionQ = 0, kActionLastQ = 1;
// Flip-flops at 2..5, pulse memories at 6..7, timers' IN memory at 8 + k, start at 16 + 8k, preset
// at 56 + 8k, for k = the timer below.
enum Timer : uint64_t { kTimerL, kTimerD, kTimerSD, kTimerDS, kTimerSL, kTimers };
constexpr uint64_t kFlipS = 2, kFlipSD = 3, kFlipDS = 4, kFlipSL = 5, kPulseP = 6, kPulseP0 = 7;

template <typename T>
T read(const uint8_t* at) {
  T value;
  std::memcpy(&value, at, sizeof(T));
  return value;
}

template <typename T>
void write(uint8_t* at, T value) {
  std::memcpy(at, &value, sizeof(T));
}

// TON on the timer k of an action: Q when IN has been TRUE for the preset (IEC 61131-3 TON).
bool timer(uint8_t* action, Timer k, bool in, int64_t preset, int64_t now) {
  const bool was = action[8 + k] != 0;
  if (in && !was) {
    write<int64_t>(action + 16 + 8 * k, now);
    write<int64_t>(action + 56 + 8 * k, preset);
  }
  action[8 + k] = in ? 1 : 0;
  return in && now - read<int64_t>(action + 16 + 8 * k) >= read<int64_t>(action + 56 + 8 * k);
}

// b (Instr) 0: prepare (pops the reset flag, the descriptor, the instance); 1: commit the
// transitions that fired (pops the descriptor and the instance).
void sfc_control(Machine& machine, const Instr& instr) {
  const bool commit = instr.b == 1;
  const bool reset = commit ? false : machine.pop().u != 0;
  const uint64_t descriptor = machine.pop().u;
  const uint64_t instance = machine.pop().u;
  const uint8_t* header_bytes = machine.checked(descriptor, sizeof(DescriptorHeader));
  if (!header_bytes) return;
  const auto header = read<DescriptorHeader>(header_bytes);
  const uint64_t steps_bytes = uint64_t{4} * header.steps;
  const uint8_t* initial = machine.checked(descriptor + sizeof(DescriptorHeader),
                                           steps_bytes + sizeof(Association) * header.associations + 8);
  const uint64_t state_size =
      SfcLayout::kHeaderBytes + SfcLayout::kStepBytes * header.steps + SfcLayout::kActionBytes * header.actions;
  uint8_t* state = initial ? machine.checked(instance + header.state, state_size) : nullptr;
  if (!state) return;
  const auto now = static_cast<int64_t>(machine.time_ns());
  auto step = [&](uint32_t i) { return state + SfcLayout::kHeaderBytes + SfcLayout::kStepBytes * i; };
  auto action = [&](uint32_t i) {
    return state + SfcLayout::kHeaderBytes + SfcLayout::kStepBytes * header.steps + SfcLayout::kActionBytes * i;
  };
  auto activate = [&](uint32_t i) {
    step(i)[kStepX] = 1;
    write<uint32_t>(step(i) + kStepT, 0);
    write<int64_t>(step(i) + kStepStart, now);
  };
  if (commit) {
    for (uint32_t i = 0; i < header.steps; ++i) {
      uint8_t* s = step(i);
      if (s[kStepTaken]) s[kStepX] = 0;
      if (s[kStepNext]) activate(i);
      s[kStepTaken] = 0;
      s[kStepNext] = 0;
    }
    return;
  }
  if (state[0] == 0 || reset) {
    std::memset(state, 0, state_size);
    state[0] = 1;
    for (uint32_t i = 0; i < header.steps; ++i) {
      if (read<uint32_t>(initial + uint64_t{4} * i) != 0) activate(i);
    }
  }
  for (uint32_t i = 0; i < header.steps; ++i) {
    uint8_t* s = step(i);
    if (!s[kStepX]) continue;
    // T holds at its value when the step goes inactive; TIME counts milliseconds.
    const int64_t elapsed = (now - read<int64_t>(s + kStepStart)) / 1'000'000;
    write<uint32_t>(s + kStepT, static_cast<uint32_t>(std::clamp<int64_t>(elapsed, 0, UINT32_MAX)));
  }
  // The action control of each action (IEC 61131-3 2nd ed. Fig. 21, with ed. 3's P1 and P0).
  const uint8_t* list = initial + steps_bytes;
  for (uint32_t a = 0; a < header.actions; ++a) {
    bool inputs[11] = {};
    int64_t preset[11] = {};
    bool p0_steps = false;
    for (uint32_t k = 0; k < header.associations; ++k) {
      const auto association = read<Association>(list + sizeof(Association) * k);
      if (association.action != a || association.step >= header.steps || association.qualifier > 10) continue;
      const bool active = step(association.step)[kStepX] != 0;
      if (association.qualifier == static_cast<uint32_t>(Qualifier::P0)) p0_steps = p0_steps || active;
      if (!active) continue;
      inputs[association.qualifier] = true;
      preset[association.qualifier] = association.time_ns;
    }
    uint8_t* c = action(a);
    auto in = [&](Qualifier q) { return inputs[static_cast<uint32_t>(q)]; };
    auto pt = [&](Qualifier q) { return preset[static_cast<uint32_t>(q)]; };
    const bool r = in(Qualifier::R);
    c[kFlipS] = !r && (in(Qualifier::S) || c[kFlipS]) ? 1 : 0;
    const bool l_done = timer(c, kTimerL, in(Qualifier::L), pt(Qualifier::L), now);
    const bool d_done = timer(c, kTimerD, in(Qualifier::D), pt(Qualifier::D), now);
    const bool p_in = in(Qualifier::P) || in(Qualifier::P1);
    const bool pulse = p_in && !c[kPulseP];
    c[kPulseP] = p_in ? 1 : 0;
    const bool pulse0 = !p0_steps && c[kPulseP0];
    c[kPulseP0] = p0_steps ? 1 : 0;
    c[kFlipSD] = !r && (in(Qualifier::SD) || c[kFlipSD]) ? 1 : 0;
    // SD and SL keep the preset they started with after their step has gone.
    const bool sd_done = timer(c, kTimerSD, c[kFlipSD] != 0,
                               in(Qualifier::SD) ? pt(Qualifier::SD) : read<int64_t>(c + 56 + 8 * kTimerSD), now);
    const bool ds_done = timer(c, kTimerDS, in(Qualifier::DS), pt(Qualifier::DS), now);
    c[kFlipDS] = !r && (ds_done || c[kFlipDS]) ? 1 : 0;
    c[kFlipSL] = !r && (in(Qualifier::SL) || c[kFlipSL]) ? 1 : 0;
    const bool sl_done = timer(c, kTimerSL, c[kFlipSL] != 0,
                               in(Qualifier::SL) ? pt(Qualifier::SL) : read<int64_t>(c + 56 + 8 * kTimerSL), now);
    const bool q = !r && (in(Qualifier::N) || c[kFlipS] != 0 || (in(Qualifier::L) && !l_done) || d_done || pulse ||
                          pulse0 || sd_done || c[kFlipDS] != 0 || (c[kFlipSL] != 0 && !sl_done));
    c[kActionLastQ] = c[kActionQ];
    c[kActionQ] = q ? 1 : 0;
  }
}

Qualifier qualifier_of(std::string_view text) {
  static constexpr std::pair<std::string_view, Qualifier> kNames[] = {
      {"N", Qualifier::N},   {"R", Qualifier::R},   {"S", Qualifier::S},   {"L", Qualifier::L},
      {"D", Qualifier::D},   {"P", Qualifier::P},   {"P0", Qualifier::P0}, {"P1", Qualifier::P1},
      {"SD", Qualifier::SD}, {"DS", Qualifier::DS}, {"SL", Qualifier::SL}};
  for (const auto& [name, qualifier] : kNames) {
    if (check::names_equal(name, text)) return qualifier;
  }
  return Qualifier::N;
}

std::vector<SyntaxNode> step_names(SyntaxNode transition, std::string_view field) {
  std::vector<SyntaxNode> names;
  for (SyntaxNode name : transition.children_by_field(field)) {
    if (name.kind() == "identifier") names.push_back(name);
  }
  return names;
}

}  // namespace

const SfcLayout* BodyCompiler::sfc_layout_here() {
  const Symbol* owner = pou_;
  if ((owner->kind == SymbolKind::Action || owner->kind == SymbolKind::Transition ||
       owner->kind == SymbolKind::Method) &&
      owner->owner) {
    owner = owner->owner;
  }
  if (owner->kind != SymbolKind::Program && owner->kind != SymbolKind::FunctionBlock) return nullptr;
  const PouLayout& layout = lowering_.layouts().pou(owner);
  return layout.sfc ? &*layout.sfc : nullptr;
}

std::optional<Place> BodyCompiler::special_place(SyntaxNode node) {
  if (il_first_argument_ && node == il_first_argument_) {
    // IL: the current result as a function's first argument.
    if (scalar_kind(il_.type) == Scalar::None) {
      emit(Op::LD_I64_F, static_cast<uint32_t>(il_.slot));
      return Place{Place::Mode::Pointer, 0, il_.type, -1, nullptr};
    }
    return Place{Place::Mode::Frame, il_.slot, il_.type, -1, nullptr};
  }
  if (node.kind() != "member_expression") return std::nullopt;
  SyntaxNode object = node.child_by_field("object");
  SyntaxNode member = node.child_by_field("member");
  if (!object || !member || object.kind() != "identifier") return std::nullopt;
  const SfcLayout* sfc = sfc_layout_here();
  if (!sfc) return std::nullopt;
  // step.X (active), step.T (time since activation), action.X (the action's Q).
  if (const int step = sfc->step_index(object.text()); step >= 0) {
    if (check::names_equal(member.text(), "X")) {
      return Place{Place::Mode::Instance, sfc->step_offset(static_cast<size_t>(step)) + kStepX, bool_type(), -1,
                   nullptr};
    }
    if (check::names_equal(member.text(), "T")) {
      return Place{Place::Mode::Instance, sfc->step_offset(static_cast<size_t>(step)) + kStepT, elementary("TIME"), -1,
                   nullptr};
    }
    return std::nullopt;
  }
  const int action = sfc->action_index(object.text());
  const Symbol* declared = lowering_.model().lookup(pou_, object.text());
  if (action >= 0 && check::names_equal(member.text(), "X") && (!declared || declared->kind == SymbolKind::Action)) {
    return Place{Place::Mode::Instance, sfc->action_offset(static_cast<size_t>(action)) + kActionQ, bool_type(), -1,
                 nullptr};
  }
  return std::nullopt;
}

void BodyCompiler::sfc_step_macro(SyntaxNode macro) {
  // OpenPCS @ACTIVATE_STEP(s), @DEACTIVATE_STEP(s), @DEACTIVATE_ALL_STEPS(): take effect with
  // the transitions of this call.
  const SfcLayout* sfc = sfc_layout_here();
  SyntaxNode name = macro.child_by_field("name");
  if (!sfc || !name) {
    fail(macro, "a step macro outside an SFC");
    return;
  }
  const std::string which = check::upper_name(name.text());
  auto mark = [&](size_t step, uint64_t byte) {
    emit(Op::PUSH, 0, 1);
    emit(Op::ST_8_I, static_cast<uint32_t>(sfc->step_offset(step) + byte));
  };
  if (which == "DEACTIVATE_ALL_STEPS") {
    for (size_t i = 0; i < sfc->steps.size(); ++i) mark(i, kStepTaken);
    return;
  }
  SyntaxNode step_name = macro.child_by_field("step");
  const int step = step_name ? sfc->step_index(step_name.text()) : -1;
  if (step < 0) {
    fail(macro, "the step macro names no step of this SFC");
    return;
  }
  mark(static_cast<size_t>(step), which == "ACTIVATE_STEP" ? kStepNext : kStepTaken);
}

void BodyCompiler::sfc_body(SyntaxNode body) {
  const SfcLayout* sfc = sfc_layout_here();
  if (!sfc || sfc->steps.empty()) {
    fail(body, "rung runs SFC bodies of programs and function blocks with steps only");
    return;
  }
  const SfcLayout chart = *sfc;  // (the layouts' map may grow while this body compiles)
  auto flag = [&](std::string_view name) -> std::optional<Place> {
    const Symbol* variable = lowering_.model().lookup(pou_, name);
    if (!variable || variable->kind != SymbolKind::Variable) return std::nullopt;
    Place place = variable_place(variable);
    if (!place.type || place.mode == Place::Mode::Pointer) return std::nullopt;
    return place;
  };
  const auto pause = flag("SFCPause");
  const auto init = flag("SFCInit");
  const auto reset = flag("SFCReset");
  const auto trans = flag("SFCTrans");
  std::vector<uint32_t> to_end;
  if (pause) {
    load(*pause);
    to_end.push_back(emit(Op::JNZ));
  }

  // The descriptor: header, initial flags, associations.
  DescriptorHeader header;
  header.steps = static_cast<uint32_t>(chart.steps.size());
  header.actions = static_cast<uint32_t>(chart.actions.size());
  header.state = static_cast<uint32_t>(chart.offset);
  std::vector<Association> associations;
  for (uint32_t i = 0; i < body.named_child_count(); ++i) {
    SyntaxNode step = body.named_child(i);
    SyntaxNode step_name = step.child_by_field("name");
    if (step.kind() != "sfc_step" || !step_name) continue;
    for (uint32_t j = 0; j < step.named_child_count(); ++j) {
      SyntaxNode association = step.named_child(j);
      SyntaxNode action_name = association.child_by_field("name");
      if (association.kind() != "sfc_action" || !action_name) continue;
      Association entry;
      entry.step = static_cast<uint32_t>(chart.step_index(step_name.text()));
      entry.action = static_cast<uint32_t>(chart.action_index(action_name.text()));
      SyntaxNode qualifier = association.child_by_field("qualifier");
      const Qualifier q = qualifier ? qualifier_of(qualifier.text()) : Qualifier::N;
      entry.qualifier = static_cast<uint32_t>(q);
      const std::vector<SyntaxNode> arguments = association.children_by_field("argument");
      if (!arguments.empty()) {
        auto time = lowering_.model().constant_value(arguments.front(), pou_);
        if (time && time->kind == check::ConstValue::Kind::Duration)
          entry.time_ns = static_cast<int64_t>(time->integer);
      }
      const bool timed =
          q == Qualifier::L || q == Qualifier::D || q == Qualifier::SD || q == Qualifier::DS || q == Qualifier::SL;
      if (timed && arguments.empty()) fail(association, fmt::format("the qualifier {} needs a time", qualifier.text()));
      associations.push_back(entry);
    }
  }
  header.associations = static_cast<uint32_t>(associations.size());
  std::string bytes(sizeof(header), '\0');
  std::memcpy(bytes.data(), &header, sizeof(header));
  for (bool initial : chart.initial) {
    const uint32_t value = initial ? 1 : 0;
    bytes.append(reinterpret_cast<const char*>(&value), sizeof(value));
  }
  for (const Association& entry : associations) bytes.append(reinterpret_cast<const char*>(&entry), sizeof(entry));
  bytes.append(8, '\0');
  const auto descriptor = static_cast<uint32_t>(lowering_.constant_bytes(bytes, 8));
  const uint32_t control = lowering_.native(sfc_control, "SFC_CONTROL");

  // 2, 3: start, SFCInit/SFCReset, step times and action control.
  emit(Op::ADDR_I, 0);
  emit(Op::ADDR_G, descriptor);
  if (init || reset) {
    emit(Op::PUSH, 0, 0);
    if (init) {
      load(*init);
      emit(Op::OR);
    }
    if (reset) {
      load(*reset);
      emit(Op::OR);
    }
  } else {
    emit(Op::PUSH, 0, 0);
  }
  emit(Op::NATIVE, control, 0);
  if (init) {
    load(*init);
    to_end.push_back(emit(Op::JNZ));
  }

  // 4: the actions.
  for (size_t a = 0; a < chart.actions.size(); ++a) {
    const uint32_t q = static_cast<uint32_t>(chart.action_offset(a) + kActionQ);
    const Symbol* target = lowering_.model().lookup(pou_, chart.actions[a]);
    if (target && target->kind == SymbolKind::Variable) {
      Place variable = variable_place(target);
      if (variable.mode == Place::Mode::Pointer) variable = as_pointer(variable);
      emit(Op::LD_U8_I, q);
      convert(bool_type(), variable.type);
      store(variable, variable.type);
      continue;
    }
    if (!target || target->kind != SymbolKind::Action) {
      fail(body, fmt::format("rung cannot find the action '{}'", chart.actions[a]));
      continue;
    }
    emit(Op::LD_U8_I, q);
    emit(Op::LD_U8_I, static_cast<uint32_t>(chart.action_offset(a) + kActionLastQ));
    emit(Op::OR);
    const uint32_t skip = emit(Op::JZ);
    const uint32_t callable = lowering_.callable_for(target);
    emit(Op::FRAME, callable);
    emit(Op::ADDR_I, 0);
    emit(Op::CALL, callable);
    patch(skip, here());
  }

  // 5: the transitions.
  if (trans) {
    emit(Op::PUSH, 0, 0);
    store(*trans, bool_type());
  }
  for (uint32_t i = 0; i < body.named_child_count(); ++i) {
    SyntaxNode transition = body.named_child(i);
    if (transition.kind() != "sfc_transition") continue;
    set_position(transition);
    std::vector<uint32_t> skips;
    const std::vector<SyntaxNode> from = step_names(transition, "from");
    const std::vector<SyntaxNode> to = step_names(transition, "to");
    for (SyntaxNode name : from) {
      const uint64_t at = chart.step_offset(static_cast<size_t>(std::max(0, chart.step_index(name.text()))));
      emit(Op::LD_U8_I, static_cast<uint32_t>(at + kStepX));
      emit(Op::LD_U8_I, static_cast<uint32_t>(at + kStepTaken));
      emit(Op::BNOT);
      emit(Op::AND);
      skips.push_back(emit(Op::JZ));
    }
    if (SyntaxNode condition = transition.child_by_field("condition")) {
      value_as_bool(condition);
    } else if (SyntaxNode code = transition.child_by_field("body"); code && code.kind() == "il_body") {
      // The transition fires when the CR is TRUE after its code (OpenPCS L2510-2545).
      il_body(code);
      emit(Op::LD_I64_F, static_cast<uint32_t>(il_.slot));
    } else {
      fail(transition, "rung runs transitions written as ':= condition;' or as IL code only");
      emit(Op::PUSH, 0, 0);
    }
    skips.push_back(emit(Op::JZ));
    for (SyntaxNode name : from) {
      emit(Op::PUSH, 0, 1);
      emit(Op::ST_8_I,
           static_cast<uint32_t>(chart.step_offset(static_cast<size_t>(std::max(0, chart.step_index(name.text())))) +
                                 kStepTaken));
    }
    for (SyntaxNode name : to) {
      emit(Op::PUSH, 0, 1);
      emit(Op::ST_8_I,
           static_cast<uint32_t>(chart.step_offset(static_cast<size_t>(std::max(0, chart.step_index(name.text())))) +
                                 kStepNext));
    }
    if (trans) {
      emit(Op::PUSH, 0, 1);
      store(*trans, bool_type());
    }
    for (uint32_t skip : skips) patch(skip, here());
  }
  emit(Op::ADDR_I, 0);
  emit(Op::ADDR_G, descriptor);
  emit(Op::NATIVE, control, 1);
  for (uint32_t jump : to_end) patch(jump, here());
}

}  // namespace rung::run
