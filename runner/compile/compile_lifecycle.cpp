// The life cycle of function block instances, as CODESYS runs it: when an instance is created
// (the program starts, a function's call frame opens, __NEW), its variables' computed initial
// values are computed, its member instances are built, and FB_init is called (the base's first,
// with bInitRetains TRUE and bInCopyCode FALSE, and with the arguments of the declaration
// `fb : FB_X(a := 1)`); when the run ends, FB_exit is called (derived first, then the members').
// FB_reinit belongs to online change, which a run does not have: it is never called.
#include <fmt/format.h>

#include "checker/semantic/body_checker.hpp"
#include "checker/symbols/names.hpp"
#include "runner/compile/lowering.hpp"

namespace rung::run {
namespace {

// The variables a start (or a call, `per_call`) initialises: kept in the instance or globally, or in
// the frame; never others' storage (VAR_EXTERNAL, VAR_IN_OUT) or VAR_STAT's single copy.
bool initialised_here(const Symbol* variable, const Storage& storage, bool per_call) {
  if (variable->kind != SymbolKind::Variable || storage.kind == Storage::Kind::None) return false;
  if (variable->section == ast::VarSection::External || variable->section == ast::VarSection::Stat) return false;
  if (variable->section == ast::VarSection::InOut) return false;
  return (storage.kind == Storage::Kind::Frame) == per_call;
}

// The chain of `block` and its bases, base first.
std::vector<const Symbol*> base_chain(const Symbol* block) {
  std::vector<const Symbol*> chain;
  for (const Symbol* c = block; c && chain.size() < 64; c = c->base == c ? nullptr : c->base)
    chain.insert(chain.begin(), c);
  return chain;
}

uint64_t element_count(const Type* type) {
  uint64_t count = 1;
  for (const check::ArrayDimension& dimension : type->dimensions) {
    count *= static_cast<uint64_t>(std::max<int64_t>(0, dimension.upper - dimension.lower + 1));
  }
  return count;
}

}  // namespace

// --- Lowering: which blocks need code, and their callables -----------------------------------------

const Symbol* Lowering::own_method(const Symbol* block, std::string_view name) const {
  for (const Symbol* member : block->ordered) {
    if (member->kind == SymbolKind::Method && check::names_equal(member->name, name)) return member;
  }
  return nullptr;
}

const Symbol* Lowering::instance_block(const Symbol* variable) const {
  if (variable->kind != SymbolKind::Variable || Layouts::held_by_reference(variable)) return nullptr;
  const Type* type = Layouts::storage_type(variable->type);
  if (type && type->kind == TypeKind::Array) type = Layouts::storage_type(type->element);
  if (!type || type->kind != TypeKind::Pou || !type->declaration) return nullptr;
  const Symbol* block = type->declaration;
  return block->kind == SymbolKind::FunctionBlock || block->kind == SymbolKind::Class ? block : nullptr;
}

bool Lowering::needs_construction(const Symbol* block) {
  if (auto found = needs_construction_.find(block); found != needs_construction_.end()) return found->second;
  needs_construction_[block] = false;  // a block cannot contain itself; this ends a cycle in broken code
  bool needed = block->base && block->base != block && needs_construction(block->base);
  for (const Symbol* member : block->ordered) {
    if (needed) break;
    if (member->kind != SymbolKind::Variable || !Layouts::in_instance(member)) continue;
    if (Layouts::held_by_reference(member)) continue;
    if (computed_initial(member) || instance_needs_init(member)) needed = true;
  }
  needs_construction_[block] = needed;
  return needed;
}

bool Lowering::instance_needs_init(const Symbol* variable) {
  const Symbol* block = instance_block(variable);
  return block && (needs_init(block) || variable->node.child_by_field("arguments"));
}

bool Lowering::needs_init(const Symbol* block) {
  if (needs_construction(block)) return true;
  for (const Symbol* c : base_chain(block)) {
    if (own_method(c, "FB_init")) return true;
  }
  return false;
}

bool Lowering::needs_exit(const Symbol* block) {
  if (auto found = needs_exit_.find(block); found != needs_exit_.end()) return found->second;
  needs_exit_[block] = false;
  bool needed = false;
  for (const Symbol* c : base_chain(block)) {
    if (own_method(c, "FB_exit")) needed = true;
    for (const Symbol* member : c->ordered) {
      if (needed) break;
      if (member->kind != SymbolKind::Variable || !Layouts::in_instance(member)) continue;
      if (const Symbol* inner = instance_block(member); inner && inner != block && needs_exit(inner)) needed = true;
    }
  }
  needs_exit_[block] = needed;
  return needed;
}

namespace {

uint32_t add_lifecycle_callable(Program& program, std::vector<uint32_t>& queue, const Symbol* symbol, CallableKind kind,
                                std::string name, uint32_t instance_size) {
  Callable callable;
  callable.name = std::move(name);
  callable.kind = kind;
  callable.source = symbol->source;
  callable.symbol = symbol;
  callable.instance_size = instance_size;
  const auto index = static_cast<uint32_t>(program.callables.size());
  program.callables.push_back(std::move(callable));
  queue.push_back(index);
  return index;
}

}  // namespace

uint32_t Lowering::constructor_for(const Symbol* block) {
  if (auto found = constructors_.find(block); found != constructors_.end()) return found->second;
  if (!needs_construction(block)) return kNoCallable;
  const auto size = static_cast<uint32_t>(layouts_.pou(block).instance_size);
  const uint32_t index = add_lifecycle_callable(program_, queue_, block, CallableKind::Construct,
                                                qualified_name(block) + " (new instance)", size);
  constructors_.emplace(block, index);
  return index;
}

uint32_t Lowering::destructor_for(const Symbol* block) {
  if (auto found = destructors_.find(block); found != destructors_.end()) return found->second;
  if (!needs_exit(block)) return kNoCallable;
  const auto size = static_cast<uint32_t>(layouts_.pou(block).instance_size);
  const uint32_t index = add_lifecycle_callable(program_, queue_, block, CallableKind::Destruct,
                                                qualified_name(block) + " (FB_exit)", size);
  destructors_.emplace(block, index);
  return index;
}

void Lowering::exit_callable(const Symbol* owner, uint64_t instance) {
  uint32_t index = kNoCallable;
  if (auto found = exit_callables_.find(owner); found != exit_callables_.end()) {
    index = found->second;
  } else {
    bool needed = false;
    for (const Symbol* variable : owner->ordered) {
      const Symbol* block = instance_block(variable);
      if (block && variable->section != ast::VarSection::External && needs_exit(block)) needed = true;
    }
    if (needed) {
      const uint32_t size =
          owner->kind == SymbolKind::Program ? static_cast<uint32_t>(layouts_.pou(owner).instance_size) : 0;
      index = add_lifecycle_callable(program_, queue_, owner, CallableKind::Exit, qualified_name(owner) + " (FB_exit)",
                                     size);
    }
    exit_callables_.emplace(owner, index);
  }
  if (index != kNoCallable) program_.exit_calls.push_back(Program::InitCall{index, instance});
}

// --- BodyCompiler: the code ------------------------------------------------------------------------

void BodyCompiler::initialize_variables(const Symbol* owner, bool per_call) {
  Lowering& lowering = lowering_;
  // A derived block's constructor builds its base's part first (the same instance).
  if (!per_call && (owner->kind == SymbolKind::FunctionBlock || owner->kind == SymbolKind::Class) && owner->base &&
      owner->base != owner) {
    const uint32_t base = lowering.constructor_for(owner->base);
    if (base != kNoCallable) {
      emit(Op::FRAME, base);
      emit(Op::ADDR_I, 0);
      emit(Op::CALL, base);
    }
  }
  std::vector<const Symbol*> computed;
  for (const Symbol* variable : owner->ordered) {
    if (variable->kind != SymbolKind::Variable) continue;
    const Storage storage = lowering.storage_of(variable, pou_);
    if (!initialised_here(variable, storage, per_call)) continue;
    if (lowering.computed_initial(variable)) {
      computed.push_back(variable);
      continue;
    }
    const Symbol* block = lowering.instance_block(variable);
    if (!block || !lowering.instance_needs_init(variable)) continue;
    set_position(variable->node);
    const Type* type = Layouts::storage_type(variable->type);
    const Place whole = variable_place(variable);
    SyntaxNode arguments = variable->node.child_by_field("arguments");
    if (type->kind != TypeKind::Array) {
      construct_instance(
          block, [&] { address_of(whole); }, arguments);
      continue;
    }
    // ARRAY[..] OF FB_X[(a := 1), (a := 2)]: each element with its own arguments.
    const uint64_t element_size = lowering.layouts().of(type->element).size;
    const uint64_t count = element_count(type);
    std::vector<SyntaxNode> lists;
    if (arguments && arguments.kind() == "argument_lists") lists = arguments.children_of_kind("argument_list");
    for (uint64_t i = 0; i < count; ++i) {
      Place element = whole;
      element.offset += i * element_size;
      construct_instance(
          block, [&] { address_of(element); }, i < lists.size() ? lists[i] : SyntaxNode());
    }
  }
  // Computed initial values after the instances, in declaration order.
  for (const Symbol* variable : computed) runtime_initial_value(variable);
}

void BodyCompiler::construct_instance(const Symbol* block, const std::function<void()>& push_address,
                                      SyntaxNode arguments) {
  Lowering& lowering = lowering_;
  const uint32_t constructor = lowering.constructor_for(block);
  if (constructor != kNoCallable) {
    emit(Op::FRAME, constructor);
    push_address();
    emit(Op::CALL, constructor);
  }
  const std::vector<check::CallArgument> given = arguments && arguments.kind() == "argument_list"
                                                     ? check::call_arguments(arguments)
                                                     : std::vector<check::CallArgument>{};
  // The FB_init the declaration's arguments are for: the most derived one.
  const Symbol* addressed = nullptr;
  for (const Symbol* c : base_chain(block)) {
    if (const Symbol* init = lowering.own_method(c, "FB_init")) addressed = init;
  }
  Layouts& layouts = lowering.layouts();
  if (!addressed) {
    // No FB_init: the arguments are input values (fb : TON(PT := T#1S)).
    for (const check::CallArgument& argument : given) {
      if (!argument.name || !argument.value) continue;
      const Symbol* input = lowering.model().find_member(block, argument.name.text());
      if (!input || input->kind != SymbolKind::Variable || Layouts::held_by_reference(input)) continue;
      layouts.pou(block);
      push_address();
      Place target{Place::Mode::Pointer, layouts.offset(input), input->type, -1, input};
      target = as_pointer(target);
      const Type* pushed = value(argument.value, input->type);
      store(target, pushed);
    }
    return;
  }
  for (const Symbol* c : base_chain(block)) {
    const Symbol* init = lowering.own_method(c, "FB_init");
    if (!init) continue;
    const uint32_t callable = lowering.callable_for(init);
    layouts.pou(init);
    emit(Op::FRAME, callable);
    // A base's FB_init takes the arguments of the same name (TwinCAT: a derived FB_init repeats
    // its base's parameters and adds its own).
    std::vector<check::CallArgument> mine;
    for (const check::CallArgument& argument : given) {
      if (init == addressed || argument.name) mine.push_back(argument);
    }
    bind_frame_arguments(init, mine);
    // A cold start: retain variables are initialised too (CODESYS passes bInitRetains TRUE).
    if (const Symbol* retains = lowering.model().find_member(init, "bInitRetains");
        retains && retains->kind == SymbolKind::Variable && layouts.has_offset(retains)) {
      emit(Op::ADDR_N, static_cast<uint32_t>(layouts.offset(retains)));
      emit(Op::PUSH, 0, 1);
      store(Place{Place::Mode::Pointer, 0, retains->type, -1, retains}, bool_type());
    }
    push_address();
    emit(Op::CALL, callable);
  }
}

void BodyCompiler::destruct_instance(const Symbol* block, const std::function<void()>& push_address) {
  const uint32_t destructor = lowering_.destructor_for(block);
  if (destructor == kNoCallable) return;
  emit(Op::FRAME, destructor);
  push_address();
  emit(Op::CALL, destructor);
}

void BodyCompiler::compile_lifecycle() {
  Program& program = lowering_.program();
  const CallableKind kind = program.callables[callable_index_].kind;
  const uint32_t begin = here();
  position_ = pou_->node.begin();
  if (kind == CallableKind::Init || kind == CallableKind::Construct) {
    initialize_variables(pou_, false);
  } else if (kind == CallableKind::Destruct) {
    // FB_exit of each level, the derived first; then the member instances', last declared first.
    const std::vector<const Symbol*> chain = base_chain(pou_);
    for (auto c = chain.rbegin(); c != chain.rend(); ++c) {
      if (const Symbol* exit = lowering_.own_method(*c, "FB_exit")) {
        const uint32_t callable = lowering_.callable_for(exit);
        emit(Op::FRAME, callable);
        emit(Op::ADDR_I, 0);
        emit(Op::CALL, callable);
      }
    }
    for (auto c = chain.rbegin(); c != chain.rend(); ++c) exit_members(*c);
  } else if (kind == CallableKind::Exit) {
    exit_members(pou_);
  }
  finish_callable(begin, {});
}

void BodyCompiler::exit_members(const Symbol* owner) {
  for (auto it = owner->ordered.rbegin(); it != owner->ordered.rend(); ++it) {
    const Symbol* variable = *it;
    const Symbol* block = lowering_.instance_block(variable);
    if (!block || !lowering_.needs_exit(block)) continue;
    const Storage storage = lowering_.storage_of(variable, pou_);
    if (!initialised_here(variable, storage, false)) continue;
    const Place whole = variable_place(variable);
    const Type* type = Layouts::storage_type(variable->type);
    if (type->kind != TypeKind::Array) {
      destruct_instance(block, [&] { address_of(whole); });
      continue;
    }
    const uint64_t element_size = lowering_.layouts().of(type->element).size;
    for (uint64_t i = element_count(type); i-- > 0;) {
      Place element = whole;
      element.offset += i * element_size;
      destruct_instance(block, [&] { address_of(element); });
    }
  }
}

}  // namespace rung::run
