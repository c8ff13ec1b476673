// One callable's code: the frame (parameters, locals, temporaries), the body (ST, IL or SFC), the
// jumps patched at the end, and the initial values that are set on every call (VAR_TEMP, a
// function's locals) through the frame image.
#include <fmt/format.h>

#include "checker/symbols/names.hpp"
#include "runner/compile/lowering.hpp"

namespace rung::run {

BodyCompiler::BodyCompiler(Lowering& lowering, uint32_t callable_index)
    : lowering_(lowering),
      callable_index_(callable_index),
      pou_(lowering.program().callables[callable_index].symbol),
      checker_(lowering.model(), *pou_, checker_output_) {}

uint32_t BodyCompiler::emit(Op op, uint32_t a, int64_t b, uint16_t aux) {
  Program& program = lowering_.program();
  program.code.push_back(Instr{op, aux, a, b});
  program.positions.push_back(position_);
  return static_cast<uint32_t>(program.code.size() - 1);
}

uint32_t BodyCompiler::here() const { return static_cast<uint32_t>(lowering_.program().code.size()); }

void BodyCompiler::patch(uint32_t at, uint32_t target) { lowering_.program().code[at].a = target; }

void BodyCompiler::runtime_initial_value(const Symbol* variable) {
  // `x : T := expression` computed in code.
  SyntaxNode value_node = variable->node.child_by_field("value");
  set_position(value_node);
  if (Layouts::held_by_reference(variable)) {
    // REFERENCE TO x := y: the slot takes y's address.
    const Storage storage = lowering_.storage_of(variable, pou_);
    if (storage.kind == Storage::Kind::None) return;
    auto source = place(value_node);
    if (!source) {
      fail(value_node, "a REFERENCE's initial value must be a variable");
      return;
    }
    address_of(*source);
    emit(storage.kind == Storage::Kind::Global     ? Op::ST_64_G
         : storage.kind == Storage::Kind::Instance ? Op::ST_64_I
                                                   : Op::ST_64_F,
         static_cast<uint32_t>(storage.offset));
    return;
  }
  Place target = variable_place(variable);
  if (!target.type) return;
  const bool aggregate = scalar_kind(target.type) == Scalar::None;
  if (target.mode == Place::Mode::Pointer || aggregate) target = as_pointer(target);
  const Type* pushed = value(value_node, target.type);
  store(target, pushed);
}

void BodyCompiler::compile() {
  Program& program = lowering_.program();
  const CallableKind kind = program.callables[callable_index_].kind;
  if (kind == CallableKind::Init || kind == CallableKind::Construct || kind == CallableKind::Exit ||
      kind == CallableKind::Destruct) {
    compile_lifecycle();
    return;
  }
  const PouLayout& layout = lowering_.layouts().pou(pou_);
  frame_size_ = layout.frame_size;
  SyntaxNode body = pou_->node.child_by_field("body");
  // Transitions written as `TRANSITION t := expr;` and property accessors keep their body under
  // the same field; a POU without a body (a stub, an interface's method) gets no code.
  if (!body || (body.kind() == "statement_list" && ast::statements(body).empty() && pou_->has(check::kLibrary))) {
    if (pou_->kind == SymbolKind::Interface || pou_->has(check::kLibrary) || pou_->has(check::kAbstract) ||
        (pou_->owner && pou_->owner->kind == SymbolKind::Interface) ||
        (pou_->owner && pou_->owner->owner && pou_->owner->owner->kind == SymbolKind::Interface)) {
      Callable& callable = program.callables[callable_index_];
      callable.frame_size = static_cast<uint32_t>((frame_size_ + 7) / 8 * 8);
      callable.frame_image.assign(callable.frame_size, 0);
      for (const Symbol* variable : layout.frame_variables) {
        lowering_.write_variable_initial(callable.frame_image, lowering_.layouts().offset(variable), variable);
      }
      return;
    }
  }
  // The frame's initial bytes first: writing them also finds the initial values that must be
  // computed in code.
  std::vector<uint8_t> frame_image(layout.frame_size, 0);
  for (const Symbol* variable : layout.frame_variables) {
    lowering_.write_variable_initial(frame_image, lowering_.layouts().offset(variable), variable);
  }
  // A function's result starts as its type's default.
  if (const Type* result = Layouts::result_type(pou_)) {
    lowering_.write_default(frame_image, layout.result_offset, result);
  }
  const uint32_t begin = here();
  position_ = pou_->node.begin();
  // The frame's variables with computed initial values or FB instances (a function's or method's
  // locals, VAR_TEMP), on every call.
  initialize_variables(pou_, true);
  std::vector<SyntaxNode> bodies;
  if (body) {
    bodies.push_back(body);
  } else if (pou_->node.kind() == "source_file") {
    // A snippet (VAR blocks and statements without a POU header, as manuals print them) is the
    // body of an unnamed PROGRAM: its statements, in file order.
    for (uint32_t i = 0; i < pou_->node.named_child_count(); ++i) {
      SyntaxNode child = pou_->node.named_child(i);
      const std::string_view kind = child.kind();
      if (kind == "statement_list" || kind == "il_body" || kind == "sfc_network") bodies.push_back(child);
    }
  }
  for (SyntaxNode part : bodies) {
    const std::string_view kind = part.kind();
    if (kind == "statement_list") {
      statement_list(part);
    } else if (kind == "il_body") {
      il_body(part);
    } else if (kind == "sfc_network") {
      sfc_body(part);
    } else {
      // TRANSITION t := expression; as a callable returning BOOL.
      fail(part, fmt::format("rung cannot run this kind of body yet ({})", kind));
    }
  }
  const uint32_t end_of_body = here();
  for (uint32_t jump : returns_) patch(jump, end_of_body);
  for (const auto& [jump, label] : jumps_) {
    auto found = labels_.find(label);
    if (found == labels_.end()) {
      lowering_.error(pou_, SyntaxNode(), fmt::format("jump to unknown label '{}'", label));
      continue;
    }
    patch(jump, found->second);
  }
  finish_callable(begin, std::move(frame_image));
}

void BodyCompiler::finish_callable(uint32_t begin, std::vector<uint8_t> frame_image) {
  emit(Op::RET);
  Callable& callable = lowering_.program().callables[callable_index_];
  callable.code_begin = begin;
  callable.code_end = here();
  callable.compiled = true;
  callable.frame_size = static_cast<uint32_t>((frame_size_ + 7) / 8 * 8);
  callable.frame_image = std::move(frame_image);
  callable.frame_image.resize(callable.frame_size, 0);
}

}  // namespace rung::run
