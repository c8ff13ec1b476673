// Calls: functions (a fresh frame per call), function block and program instances (inputs stored
// into the instance, the body run on it), methods and property accessors (a frame, THIS = the
// object, dispatched through the class's method table), actions (the owner's instance). Library
// functions without a body are built-ins (compile_builtin.cpp).
#include <fmt/format.h>

#include "checker/symbols/names.hpp"
#include "runner/compile/lowering.hpp"

namespace rung::run {
namespace {

bool is_parameter(const Symbol* member) {
  return member->kind == SymbolKind::Variable &&
         (member->section == ast::VarSection::Input || member->section == ast::VarSection::InOut ||
          member->section == ast::VarSection::Output);
}

// The parameters a positional argument list fills, in order: inputs and in-outs (and, for
// functions, outputs after them).
std::vector<const Symbol*> positional_parameters(const Symbol* callee) {
  std::vector<const Symbol*> inputs;
  std::vector<const Symbol*> outputs;
  std::vector<const Symbol*> chain;
  for (const Symbol* c = callee; c; c = c->base == c ? nullptr : c->base) chain.insert(chain.begin(), c);
  for (const Symbol* c : chain) {
    for (const Symbol* member : c->ordered) {
      if (!is_parameter(member)) continue;
      if (check::names_equal(member->name, "EN") || check::names_equal(member->name, "ENO")) continue;
      (member->section == ast::VarSection::Output ? outputs : inputs).push_back(member);
    }
  }
  inputs.insert(inputs.end(), outputs.begin(), outputs.end());
  return inputs;
}

const Symbol* parameter_for(const check::ProjectModel& model, const Symbol* callee, const check::CallArgument& argument,
                            size_t position, const std::vector<const Symbol*>& positional) {
  if (argument.name) {
    const Symbol* member = model.find_member(callee, argument.name.text());
    if (member && member->kind == SymbolKind::Variable) return member;
    // The other dialect's name of a standard block's input (CTU R for RESET): rung.alias.
    for (const Symbol* c = callee; c; c = c->base == c ? nullptr : c->base) {
      for (const Symbol* candidate : c->ordered) {
        const check::Attribute* alias = candidate->attribute("rung.alias");
        if (alias && check::names_equal(alias->value, argument.name.text())) return candidate;
      }
    }
    return nullptr;
  }
  return position < positional.size() ? positional[position] : nullptr;
}

bool has_body(const Symbol* pou) {
  SyntaxNode body = pou->node.child_by_field("body");
  if (!body) return false;
  if (body.kind() == "statement_list") return !ast::statements(body).empty();
  return body.named_child_count() > 0;
}

}  // namespace

// A function block or program instance a call works on: a fixed place, or an address computed
// once and kept in a frame temporary.
struct InstanceRef {
  Place fixed;
  bool computed = false;
  uint64_t temp = 0;
};

namespace {

InstanceRef make_instance(BodyCompiler& body, const Place& place) {
  InstanceRef ref;
  ref.fixed = place;
  if (place.mode != Place::Mode::Pointer) return ref;
  ref.computed = true;
  ref.temp = body.temporary(body.elementary("LWORD"));
  if (place.offset != 0) {
    body.emit(Op::PUSH, 0, static_cast<int64_t>(place.offset));
    body.emit(Op::ADD);
  }
  body.emit(Op::ST_64_F, static_cast<uint32_t>(ref.temp));
  return ref;
}

void push_instance_address(BodyCompiler& body, const InstanceRef& ref) {
  if (ref.computed) {
    body.emit(Op::LD_I64_F, static_cast<uint32_t>(ref.temp));
    return;
  }
  body.address_of(ref.fixed);
}

Place field_of(BodyCompiler& body, const InstanceRef& ref, uint64_t offset, const Type* type) {
  if (ref.computed) {
    body.emit(Op::LD_I64_F, static_cast<uint32_t>(ref.temp));
    return Place{Place::Mode::Pointer, offset, type, -1, nullptr};
  }
  Place place = ref.fixed;
  place.offset += offset;
  place.type = type;
  place.bit = -1;
  return place;
}

}  // namespace

void BodyCompiler::in_out_address(SyntaxNode argument, const Symbol* parameter) {
  // A variable passes its address; a value (allowed for VAR_IN_OUT CONSTANT) passes the address of
  // a temporary copy.
  const ExprInfo argument_info = info(argument);
  if (!argument_info.value) {
    if (auto source = place(argument)) {
      address_of(*source);
      return;
    }
  }
  const uint64_t temp = temporary(parameter->type);
  emit(Op::ADDR_F, static_cast<uint32_t>(temp));
  const Type* pushed = value(argument, parameter->type);
  store(Place{Place::Mode::Pointer, 0, parameter->type, -1, nullptr}, pushed);
  emit(Op::ADDR_F, static_cast<uint32_t>(temp));
}

void BodyCompiler::bind_open_bounds(SyntaxNode argument, const Symbol* parameter,
                                    const std::function<Place(uint64_t offset)>& bound_slot) {
  const size_t dimensions = Layouts::open_dimensions(parameter);
  for (size_t d = 0; d < dimensions; ++d) {
    for (const bool upper : {false, true}) {
      const Place slot = bound_slot(Layouts::kOpenBoundsOffset + 16 * d + (upper ? 8 : 0));
      if (!push_bound(argument, d, upper)) {
        fail(argument, "rung passes to an ARRAY[*] parameter only an array variable or an ARRAY[*] parameter");
        emit(Op::PUSH, 0, 0);
      }
      store(slot, elementary("LINT"));
    }
  }
}

void BodyCompiler::bind_frame_arguments(const Symbol* callee, const std::vector<check::CallArgument>& arguments) {
  const std::vector<const Symbol*> positional = positional_parameters(callee);
  Layouts& layouts = lowering_.layouts();
  layouts.pou(callee);
  size_t position = 0;
  for (const check::CallArgument& argument : arguments) {
    const size_t index = position++;
    if (argument.output || !argument.value) continue;  // `PV:= ,` leaves the default
    const Symbol* parameter = parameter_for(lowering_.model(), callee, argument, index, positional);
    if (!parameter) continue;
    if (check::names_equal(parameter->name, "EN")) continue;
    set_position(argument.node);
    const uint64_t offset = layouts.offset(parameter);
    emit(Op::ADDR_N, static_cast<uint32_t>(offset));
    if (parameter->section == ast::VarSection::InOut) {
      in_out_address(argument.value, parameter);
      emit(Op::ST_64_P);
      bind_open_bounds(argument.value, parameter, [&](uint64_t at) {
        emit(Op::ADDR_N, static_cast<uint32_t>(offset + at));
        return Place{Place::Mode::Pointer, 0, elementary("LINT"), -1, nullptr};
      });
      continue;
    }
    if (parameter->section == ast::VarSection::Output) {
      emit(Op::POP);
      continue;
    }
    const Type* pushed = value(argument.value, parameter->type);
    range_check(parameter->type);
    store(Place{Place::Mode::Pointer, 0, parameter->type, -1, parameter}, pushed);
  }
}

void BodyCompiler::copy_outputs(const Symbol* callee, const std::vector<check::CallArgument>& arguments,
                                bool from_frame, const std::optional<Place>& instance) {
  const std::vector<const Symbol*> positional = positional_parameters(callee);
  size_t position = 0;
  for (const check::CallArgument& argument : arguments) {
    const size_t index = position++;
    const Symbol* parameter = parameter_for(lowering_.model(), callee, argument, index, positional);
    if (!parameter || parameter->section != ast::VarSection::Output) continue;
    if (!argument.output && argument.name) continue;  // `Q := x` on an output is not an output binding
    SyntaxNode target_node = argument.value;
    if (!target_node) continue;
    auto target = place(target_node);
    if (!target) {
      fail(target_node, "an output argument must be a variable");
      continue;
    }
    Place at = *target;
    const bool aggregate = scalar_kind(at.type) == Scalar::None;
    if (at.mode == Place::Mode::Pointer || aggregate) at = as_pointer(at);
    const uint64_t offset = lowering_.layouts().offset(parameter);
    if (from_frame) {
      emit(Op::ADDR_R, static_cast<uint32_t>(offset));
      load(Place{Place::Mode::Pointer, 0, parameter->type, -1, parameter});
    } else if (instance) {
      Place source = *instance;
      source.offset += offset;
      source.type = parameter->type;
      load(source);
    }
    // OpenPCS / IEC `NOT Q => x`: the negation flag of the output argument.
    if (argument.node && argument.node.child_by_field("negation")) emit(Op::BNOT);
    convert(parameter->type, at.type);
    store(at, parameter->type);
  }
}

const Type* BodyCompiler::take_result(const Symbol* callee, bool want_result) {
  const Type* result = Layouts::result_type(callee);
  if (!result) return lowering_.model().types().void_type();
  if (!want_result) return result;
  const uint64_t offset = lowering_.layouts().pou(callee).result_offset;
  if (scalar_kind(result) != Scalar::None) {
    emit(Op::ADDR_R, static_cast<uint32_t>(offset));
    load(Place{Place::Mode::Pointer, 0, result, -1, nullptr});
    return result;
  }
  // A structured result outlives the callee's frame in a temporary of the caller's.
  const uint64_t temp = temporary(result);
  emit(Op::ADDR_F, static_cast<uint32_t>(temp));
  emit(Op::ADDR_R, static_cast<uint32_t>(offset));
  store(Place{Place::Mode::Pointer, 0, result, -1, nullptr}, result);
  emit(Op::ADDR_F, static_cast<uint32_t>(temp));
  return result;
}

const Type* BodyCompiler::function_call(const Symbol* callee, const std::vector<check::CallArgument>& arguments,
                                        bool want_result, SyntaxNode call_node) {
  const uint32_t index = lowering_.callable_for(callee);
  set_position(call_node);
  emit(Op::FRAME, index);
  bind_frame_arguments(callee, arguments);
  set_position(call_node);
  emit(Op::PUSH, 0, 0);
  emit(Op::CALL, index);
  copy_outputs(callee, arguments, true, std::nullopt);
  return take_result(callee, want_result);
}

const Type* BodyCompiler::instance_call(const Symbol* pou_type, const Place& instance, const Symbol* body,
                                        const std::vector<check::CallArgument>& arguments, SyntaxNode call_node) {
  Layouts& layouts = lowering_.layouts();
  layouts.pou(pou_type);
  const InstanceRef ref = make_instance(*this, instance);
  const std::vector<const Symbol*> positional = positional_parameters(pou_type);
  size_t position = 0;
  for (const check::CallArgument& argument : arguments) {
    const size_t index = position++;
    if (argument.output || !argument.value) continue;  // `PV:= ,` keeps the input's value
    const Symbol* parameter = parameter_for(lowering_.model(), pou_type, argument, index, positional);
    if (!parameter || parameter->section == ast::VarSection::Output) continue;
    set_position(argument.node);
    const uint64_t offset = layouts.offset(parameter);
    if (parameter->section == ast::VarSection::InOut) {
      Place slot = field_of(*this, ref, offset, elementary("LWORD"));
      if (slot.mode == Place::Mode::Pointer) slot = as_pointer(slot);
      in_out_address(argument.value, parameter);
      store(slot, slot.type);
      bind_open_bounds(argument.value, parameter, [&](uint64_t at) {
        Place bound = field_of(*this, ref, offset + at, elementary("LINT"));
        return bound.mode == Place::Mode::Pointer ? as_pointer(bound) : bound;
      });
      continue;
    }
    Place target = field_of(*this, ref, offset, parameter->type);
    const bool aggregate = scalar_kind(parameter->type) == Scalar::None;
    if (target.mode == Place::Mode::Pointer || aggregate) target = as_pointer(target);
    const Type* pushed = value(argument.value, parameter->type);
    if (!aggregate) range_check(parameter->type);
    store(target, pushed);
  }
  const uint32_t callable = lowering_.callable_for(body);
  set_position(call_node);
  emit(Op::FRAME, callable);
  push_instance_address(*this, ref);
  emit(Op::CALL, callable);
  // Outputs bound with =>: read from the instance.
  if (!ref.computed) {
    copy_outputs(pou_type, arguments, false, ref.fixed);
  } else {
    bool any_output = false;
    for (const check::CallArgument& argument : arguments) any_output = any_output || argument.output;
    if (any_output) {
      // The instance lives at the address in the temporary: copy each output through it.
      const std::vector<const Symbol*> params = positional_parameters(pou_type);
      size_t at = 0;
      for (const check::CallArgument& argument : arguments) {
        const size_t index = at++;
        if (!argument.output || !argument.value) continue;
        const Symbol* parameter = parameter_for(lowering_.model(), pou_type, argument, index, params);
        if (!parameter) continue;
        auto target = place(argument.value);
        if (!target) continue;
        Place out = *target;
        if (out.mode == Place::Mode::Pointer || scalar_kind(out.type) == Scalar::None) out = as_pointer(out);
        load(field_of(*this, ref, layouts.offset(parameter), parameter->type));
        if (argument.node && argument.node.child_by_field("negation")) emit(Op::BNOT);
        convert(parameter->type, out.type);
        store(out, parameter->type);
      }
    }
  }
  return lowering_.model().types().void_type();
}

const Type* BodyCompiler::method_call(const Symbol* method, std::optional<Place> object, bool virtual_call,
                                      const std::vector<check::CallArgument>& arguments, bool want_result,
                                      SyntaxNode call_node) {
  const uint32_t declared = lowering_.callable_for(method);
  // THIS of the call: the object's address (or the running instance).
  std::optional<InstanceRef> ref;
  if (object) ref = make_instance(*this, *object);
  set_position(call_node);
  emit(Op::FRAME, declared);
  bind_frame_arguments(method, arguments);
  if (ref) {
    push_instance_address(*this, *ref);
  } else {
    emit(Op::ADDR_I, 0);
  }
  set_position(call_node);
  if (virtual_call) {
    std::string slot_name(method->name);
    if (method->owner && method->owner->kind == SymbolKind::Property) {
      slot_name = std::string(method->owner->name) + "." + std::string(method->name);
    }
    emit(Op::CALL_VIRT, lowering_.method_slot(slot_name));
  } else {
    emit(Op::CALL, declared);
  }
  copy_outputs(method, arguments, true, std::nullopt);
  return take_result(method, want_result);
}

namespace {

const Symbol* accessor_of(const check::ProjectModel& model, const Symbol* property, std::string_view which) {
  (void)model;
  for (const Symbol* member : property->ordered) {
    if (member->kind == SymbolKind::Method && check::names_equal(member->name, which)) return member;
  }
  return nullptr;
}

bool is_this_or_super(SyntaxNode object, bool* super) {
  if (object.kind() != "dereference_expression") return false;
  SyntaxNode operand = object.child_by_field("operand");
  if (!operand || operand.kind() != "identifier") return false;
  if (check::names_equal(operand.text(), "SUPER")) {
    *super = true;
    return true;
  }
  return check::names_equal(operand.text(), "THIS");
}

}  // namespace

std::optional<Place> BodyCompiler::property_object(SyntaxNode access, bool* super, bool* found) {
  *found = true;
  if (access.kind() != "member_expression") return std::nullopt;  // Prop inside the block: THIS
  SyntaxNode object_node = access.child_by_field("object");
  if (is_this_or_super(object_node, super)) return std::nullopt;
  const ExprInfo object_info = info(object_node);
  const Type* type = Layouts::storage_type(object_info.type);
  if (type && type->kind == TypeKind::Pou && type->declaration && type->declaration->kind == SymbolKind::Interface) {
    value(object_node);  // an interface value is the object's address
    return Place{Place::Mode::Pointer, 0, object_info.type, -1, nullptr};
  }
  auto object = place(object_node);
  if (!object) {
    fail(object_node, "rung cannot find the object of this property");
    *found = false;
  }
  return object;
}

void BodyCompiler::property_write(SyntaxNode target, const Symbol* property, SyntaxNode new_value) {
  const Symbol* setter = accessor_of(lowering_.model(), property, "SET");
  if (!setter) {
    fail(target, fmt::format("property '{}' has no SET accessor", property->name));
    return;
  }
  bool super = false;
  bool found = true;
  const std::optional<Place> object = property_object(target, &super, &found);
  if (!found) return;
  const uint32_t declared = lowering_.callable_for(setter);
  std::optional<InstanceRef> ref;
  if (object) ref = make_instance(*this, *object);
  emit(Op::FRAME, declared);
  const Type* type = Layouts::result_type(setter);
  emit(Op::ADDR_N, static_cast<uint32_t>(lowering_.layouts().pou(setter).result_offset));
  const Type* pushed = value(new_value, type);
  store(Place{Place::Mode::Pointer, 0, type, -1, nullptr}, pushed);
  if (ref) {
    push_instance_address(*this, *ref);
  } else {
    emit(Op::ADDR_I, 0);
  }
  set_position(target);
  if (super) {
    emit(Op::CALL, declared);
  } else {
    emit(Op::CALL_VIRT, lowering_.method_slot(std::string(property->name) + ".SET"));
  }
}

const Type* BodyCompiler::call(SyntaxNode node, bool want_result) {
  set_position(node);
  // Reading a property: obj.Prop or Prop.
  if (node.kind() != "call_expression") {
    const ExprInfo in = info(node);
    const Symbol* property = in.symbol;
    const Symbol* getter = property ? accessor_of(lowering_.model(), property, "GET") : nullptr;
    if (!getter) {
      fail(node, "this property has no GET accessor");
      return in.type;
    }
    bool super = false;
    bool found = true;
    const std::optional<Place> object = property_object(node, &super, &found);
    if (!found) return in.type;
    return method_call(getter, object, !super, {}, want_result, node);
  }

  SyntaxNode function = node.child_by_field("function");
  const std::vector<check::CallArgument> arguments = check::call_arguments(node.child_by_field("arguments"));
  const ExprInfo callee_info = info(function);
  const ExprInfo call_info = info(node);
  const Symbol* callee = callee_info.symbol;
  const std::string_view name = function.kind() == "identifier" ? function.text() : std::string_view{};

  // SUPER^(): the base block's body on this instance.
  bool super = false;
  if (function.kind() == "dereference_expression" && is_this_or_super(function, &super)) {
    const Symbol* owner = pou_;
    while (owner && owner->kind != SymbolKind::FunctionBlock && owner->kind != SymbolKind::Class) owner = owner->owner;
    const Symbol* base = owner && super ? owner->base : owner;
    if (!base) {
      fail(node, "SUPER^() needs a base function block");
      return lowering_.model().types().void_type();
    }
    const uint32_t callable = lowering_.callable_for(base);
    emit(Op::FRAME, callable);
    emit(Op::ADDR_I, 0);
    emit(Op::CALL, callable);
    return lowering_.model().types().void_type();
  }

  if (!callee) {
    // timers[i](IN := TRUE), pFb^(), inst.inner(): an instance that is not a declared name.
    const Type* instance_type = Layouts::storage_type(callee_info.type);
    if (instance_type && instance_type->kind == TypeKind::Reference) {
      instance_type = Layouts::storage_type(instance_type->element);
    }
    if (name.empty() && instance_type && instance_type->kind == TypeKind::Pou && instance_type->declaration &&
        (instance_type->declaration->kind == SymbolKind::FunctionBlock ||
         instance_type->declaration->kind == SymbolKind::Class)) {
      auto instance = place(function);
      if (!instance) {
        fail(function, "rung cannot find this instance");
        return call_info.type;
      }
      return instance_call(instance_type->declaration, *instance, instance_type->declaration, arguments, node);
    }
    if (!name.empty()) {
      if (auto result = builtin_call(name, node, nullptr, arguments, call_info)) return *result;
    }
    fail(node, fmt::format("rung cannot run a call of '{}' yet", function.text()));
    return call_info.type;
  }
  switch (callee->kind) {
    case SymbolKind::Function: {
      if (callee->has(check::kLibrary) && !has_body(callee)) {
        if (auto result = builtin_call(callee->name, node, callee, arguments, call_info)) return *result;
        // A stub without a built-in: the call fails when it is reached, not before.
        emit(Op::TRAP, static_cast<uint32_t>(TrapKind::MissingImplementation),
             lowering_.message(fmt::format("'{}' has no implementation: it is declared in a stub library without a "
                                           "body; give it one (or a mock) to run this code",
                                           callee->name)));
        if (want_result) {
          const Type* result = Layouts::result_type(callee);
          if (result) emit(Op::PUSH, 0, 0);
        }
        return Layouts::result_type(callee) ? Layouts::result_type(callee) : lowering_.model().types().void_type();
      }
      return function_call(callee, arguments, want_result, node);
    }
    case SymbolKind::Variable: {
      const Type* type = Layouts::storage_type(callee->type);
      if (type && type->kind == TypeKind::Reference) type = Layouts::storage_type(type->element);
      if (!type || type->kind != TypeKind::Pou || !type->declaration) {
        fail(node, fmt::format("'{}' cannot be called", function.text()));
        return call_info.type;
      }
      auto instance = place(function);
      if (!instance) {
        fail(function, "rung cannot find this instance");
        return call_info.type;
      }
      return instance_call(type->declaration, *instance, type->declaration, arguments, node);
    }
    case SymbolKind::Program: {
      const Place instance{Place::Mode::Global, lowering_.program_instance(callee), callee->type, -1, callee};
      return instance_call(callee, instance, callee, arguments, node);
    }
    case SymbolKind::Method: {
      std::optional<Place> object;
      bool virtual_call = !callee->has(check::kFinal);
      if (function.kind() == "member_expression") {
        SyntaxNode object_node = function.child_by_field("object");
        bool via_super = false;
        if (is_this_or_super(object_node, &via_super)) {
          if (via_super) virtual_call = false;
        } else {
          const ExprInfo object_info = info(object_node);
          const Type* type = Layouts::storage_type(object_info.type);
          const bool interface_value = type && type->kind == TypeKind::Pou && type->declaration &&
                                       type->declaration->kind == SymbolKind::Interface;
          if (interface_value || (type && type->kind == TypeKind::Pointer)) {
            value(object_node);
            object = Place{Place::Mode::Pointer, 0, object_info.type, -1, nullptr};
            virtual_call = true;
          } else {
            object = place(object_node);
            if (!object) {
              fail(object_node, "rung cannot find the object of this method call");
              return call_info.type;
            }
          }
        }
      }
      return method_call(callee, object, virtual_call, arguments, want_result, node);
    }
    case SymbolKind::Action: {
      std::optional<InstanceRef> ref;
      if (function.kind() == "member_expression") {
        auto object = place(function.child_by_field("object"));
        if (!object) {
          fail(function, "rung cannot find the instance of this action");
          return call_info.type;
        }
        ref = make_instance(*this, *object);
      }
      const uint32_t callable = lowering_.callable_for(callee);
      emit(Op::FRAME, callable);
      if (ref) {
        push_instance_address(*this, *ref);
      } else {
        emit(Op::ADDR_I, 0);
      }
      emit(Op::CALL, callable);
      return lowering_.model().types().void_type();
    }
    default: break;
  }
  if (!name.empty()) {
    if (auto result = builtin_call(name, node, callee, arguments, call_info)) return *result;
  }
  fail(node, fmt::format("rung cannot run a call of '{}' yet", function.text()));
  return call_info.type;
}

}  // namespace rung::run
