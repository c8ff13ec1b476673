#include "runner/compile/lowering.hpp"

#include <algorithm>
#include <cstring>

#include <fmt/format.h>

#include "checker/semantic/direct_address.hpp"
#include "checker/symbols/names.hpp"

namespace rung::run {

namespace {

uint64_t round_up(uint64_t value, uint64_t alignment) { return (value + alignment - 1) / alignment * alignment; }

CallableKind callable_kind(const Symbol* pou) {
  switch (pou->kind) {
    case SymbolKind::Program: return CallableKind::Program;
    case SymbolKind::FunctionBlock:
    case SymbolKind::Class: return CallableKind::FunctionBlock;
    case SymbolKind::Method:
      if (pou->owner && pou->owner->kind == SymbolKind::Property) {
        return check::names_equal(pou->name, "SET") ? CallableKind::PropertySet : CallableKind::PropertyGet;
      }
      return CallableKind::Method;
    case SymbolKind::Action: return CallableKind::Action;
    default: return CallableKind::Function;
  }
}


// The POU whose instance a member POU (method, action, accessor) runs on.
const Symbol* instance_owner(const Symbol* pou) {
  const Symbol* owner = pou->owner;
  if (owner && owner->kind == SymbolKind::Property) owner = owner->owner;
  return owner;
}

}  // namespace

std::string qualified_name(const Symbol* pou) {
  std::vector<std::string_view> parts{pou->name};
  for (const Symbol* owner = pou->owner; owner; owner = owner->owner) {
    if (!check::is_pou_kind(owner->kind)) break;
    parts.push_back(owner->name);
  }
  std::string name;
  for (auto part = parts.rbegin(); part != parts.rend(); ++part) {
    if (!name.empty()) name += '.';
    name += *part;
  }
  return name;
}

Lowering::Lowering(const check::ProjectModel& model, Program& program, Layouts& layouts)
    : model_(model), program_(program), layouts_(layouts) {
  program_.image.assign(kNullGuard, 0);
  image_areas_ = allocate(3 * kImageAreaBytes, 8);
  program_.vtables.emplace_back();  // class id 0: not an object
  program_.class_names.emplace_back("(none)");
  classes_.push_back(nullptr);
}

void Lowering::error(const Symbol* where, SyntaxNode node, std::string message) {
  CompileError error;
  error.source = where ? where->source : check::kNoSource;
  error.offset = node ? node.begin() : (where ? where->name_range.begin : 0);
  error.message = std::move(message);
  errors_.push_back(std::move(error));
}

uint64_t Lowering::allocate(uint64_t size, uint64_t alignment) {
  const uint64_t at = round_up(program_.image.size(), std::max<uint64_t>(alignment, 1));
  program_.image.resize(at + std::max<uint64_t>(size, 1), 0);
  return at;
}

uint64_t Lowering::constant_bytes(const std::string& bytes, uint64_t alignment) {
  if (auto found = constants_.find(bytes); found != constants_.end()) return found->second;
  const uint64_t at = allocate(bytes.size(), alignment);
  std::memcpy(program_.image.data() + at, bytes.data(), bytes.size());
  constants_.emplace(bytes, at);
  return at;
}

uint32_t Lowering::dimension(const check::ArrayDimension& dimension, uint64_t stride) {
  for (size_t i = 0; i < program_.dimensions.size(); ++i) {
    const Dimension& known = program_.dimensions[i];
    if (known.lower == dimension.lower && known.upper == dimension.upper && known.stride == stride) {
      return static_cast<uint32_t>(i);
    }
  }
  program_.dimensions.push_back(Dimension{dimension.lower, dimension.upper, stride});
  return static_cast<uint32_t>(program_.dimensions.size() - 1);
}

uint32_t Lowering::native(NativeFn function, std::string_view name) {
  const std::string key(name);
  if (auto found = natives_.find(key); found != natives_.end()) return found->second;
  program_.natives.push_back(function);
  program_.native_names.push_back(key);
  const auto index = static_cast<uint32_t>(program_.natives.size() - 1);
  natives_.emplace(key, index);
  return index;
}

uint32_t Lowering::message(std::string text) {
  program_.messages.push_back(std::move(text));
  return static_cast<uint32_t>(program_.messages.size() - 1);
}

uint32_t Lowering::callable_for(const Symbol* pou) {
  if (auto found = callables_.find(pou); found != callables_.end()) return found->second;
  Callable callable;
  callable.name = qualified_name(pou);
  callable.kind = callable_kind(pou);
  callable.source = pou->source;
  callable.symbol = pou;
  const PouLayout& layout = layouts_.pou(pou);
  callable.frame_size = static_cast<uint32_t>(layout.frame_size);
  callable.param_bytes = static_cast<uint32_t>(layout.param_bytes);
  if (callable.kind == CallableKind::FunctionBlock || callable.kind == CallableKind::Program) {
    callable.instance_size = static_cast<uint32_t>(layout.instance_size);
  } else if (const Symbol* owner = instance_owner(pou); owner && callable.kind != CallableKind::Function) {
    callable.instance_size = static_cast<uint32_t>(layouts_.pou(owner).instance_size);
  }
  const auto index = static_cast<uint32_t>(program_.callables.size());
  program_.callables.push_back(std::move(callable));
  callables_.emplace(pou, index);
  queue_.push_back(index);
  return index;
}

void Lowering::compile_queue() {
  while (queue_next_ < queue_.size()) {
    const uint32_t index = queue_[queue_next_++];
    BodyCompiler body(*this, index);
    body.compile();
  }
}

std::optional<ImageAddress> Lowering::image_address(std::string_view text, std::string* error) {
  const check::DirectAddressResult parsed = check::parse_direct_address(text, profile().addressing);
  if (!parsed.ok()) {
    if (error) *error = parsed.error;
    return std::nullopt;
  }
  const check::DirectAddress& address = *parsed.address;
  if (address.wildcard) {
    if (error) *error = "an incomplete address (%I*, %Q*) has no place until it is configured";
    return std::nullopt;
  }
  if (address.last_byte >= kImageAreaBytes) {
    if (error) *error = fmt::format("'{}' is beyond the {} bytes of rung's process image", text, kImageAreaBytes);
    return std::nullopt;
  }
  const uint64_t area = address.area == check::AddressArea::Input    ? 0
                        : address.area == check::AddressArea::Output ? 1
                                                                     : 2;
  ImageAddress out;
  out.address = image_areas_ + area * kImageAreaBytes + address.first_byte;
  const check::TypeArena& types = model_.types();
  switch (address.size_bits()) {
    case 8: out.type = types.elementary("BYTE"); break;
    case 16: out.type = types.elementary("WORD"); break;
    case 32: out.type = types.elementary("DWORD"); break;
    case 64: out.type = types.elementary("LWORD"); break;
    default:
      out.type = types.elementary("BOOL");
      out.bit = address.bit.value_or(0);
      break;
  }
  return out;
}

uint64_t Lowering::global_address(const Symbol* variable) {
  if (auto found = globals_.find(variable); found != globals_.end()) return found->second;
  // A located variable lives in the process image, where other variables may overlap it.
  if (variable->location_node) {
    SyntaxNode address_node = variable->location_node.child_by_field("address");
    std::string why;
    if (auto at = address_node ? image_address(address_node.text(), &why) : std::nullopt) {
      globals_.emplace(variable, at->address);
      global_order_.push_back(variable);
      if (at->bit < 0) write_variable_initial(program_.image, at->address, variable);
      return at->address;
    }
  }
  const bool by_reference = Layouts::held_by_reference(variable);
  const TypeLayout layout = by_reference ? TypeLayout{8, 8} : layouts_.of(variable->type);
  const uint64_t at = allocate(layout.size, layout.alignment);
  globals_.emplace(variable, at);
  global_order_.push_back(variable);
  write_variable_initial(program_.image, at, variable);
  return at;
}

uint64_t Lowering::program_instance(const Symbol* program) {
  if (auto found = globals_.find(program); found != globals_.end()) return found->second;
  const PouLayout& layout = layouts_.pou(program);
  const uint64_t at = allocate(layout.instance_size, layout.instance_alignment);
  globals_.emplace(program, at);
  write_instance(program_.image, at, program, 0);
  return at;
}

Storage Lowering::storage_of(const Symbol* variable, const Symbol* callable_pou) {
  using Kind = Storage::Kind;
  const Symbol* owner = variable->owner;
  if (variable->location_node) {
    SyntaxNode address_node = variable->location_node.child_by_field("address");
    if (auto at = address_node ? image_address(address_node.text(), nullptr) : std::nullopt) {
      global_address(variable);
      return {Kind::Global, at->address, at->bit};
    }
  }
  if (variable->section == ast::VarSection::External) {
    if (const Symbol* global = model_.find_linked_global(variable->name)) return {Kind::Global, global_address(global)};
    return {};
  }
  if (!owner || owner->kind == SymbolKind::GlobalList || variable->section == ast::VarSection::Global ||
      variable->section == ast::VarSection::Stat || variable->section == ast::VarSection::Config) {
    return {Kind::Global, global_address(variable)};
  }
  if (!check::is_pou_kind(owner->kind)) return {};
  // Frame variables of the running callable (its parameters, locals, temps).
  if (owner == callable_pou) {
    const PouLayout& layout = layouts_.pou(owner);
    if (std::find(layout.frame_variables.begin(), layout.frame_variables.end(), variable) !=
        layout.frame_variables.end()) {
      return {Kind::Frame, layouts_.offset(variable)};
    }
  }
  if (Layouts::in_instance(variable) && (owner->kind == SymbolKind::FunctionBlock || owner->kind == SymbolKind::Class ||
                                         owner->kind == SymbolKind::Program)) {
    layouts_.pou(owner);
    // Inside the POU itself or one of its members (methods, actions, accessors) or a derived POU.
    if (owner->kind == SymbolKind::Program && callable_pou != owner && instance_owner(callable_pou) != owner) {
      return {Kind::Global, program_instance(owner) + layouts_.offset(variable)};
    }
    return {Kind::Instance, layouts_.offset(variable)};
  }
  return {};
}

uint32_t Lowering::init_callable(const Symbol* owner, uint64_t instance) {
  if (auto found = init_callables_.find(owner); found != init_callables_.end()) {
    // Another instance of the same program (two tasks calling it) starts the same way.
    if (found->second != kNoCallable) program_.init_calls.push_back(Program::InitCall{found->second, instance});
    return found->second;
  }
  bool needed = false;
  for (const Symbol* variable : owner->ordered) {
    if (variable->kind != SymbolKind::Variable || variable->section == ast::VarSection::External) continue;
    if (computed_initial(variable) || instance_needs_init(variable)) needed = true;
  }
  if (!needed) {
    init_callables_.emplace(owner, kNoCallable);
    return kNoCallable;
  }
  Callable callable;
  callable.name = qualified_name(owner) + " (initial values)";
  callable.kind = CallableKind::Init;
  callable.source = owner->source;
  callable.symbol = owner;
  if (owner->kind == SymbolKind::Program) callable.instance_size = static_cast<uint32_t>(layouts_.pou(owner).instance_size);
  const auto index = static_cast<uint32_t>(program_.callables.size());
  program_.callables.push_back(std::move(callable));
  init_callables_.emplace(owner, index);
  queue_.push_back(index);
  program_.init_calls.push_back(Program::InitCall{index, instance});
  return index;
}

uint32_t Lowering::class_id(const Symbol* pou) {
  if (auto found = class_ids_.find(pou); found != class_ids_.end()) return found->second;
  const auto id = static_cast<uint32_t>(classes_.size());
  classes_.push_back(pou);
  class_ids_.emplace(pou, id);
  program_.class_names.push_back(qualified_name(pou));
  program_.vtables.emplace_back();
  // Every method may be reached through dynamic dispatch once an instance exists.
  for (const Symbol* c = pou; c; c = c->base == c ? nullptr : c->base) {
    for (const Symbol* member : c->ordered) {
      if (member->kind == SymbolKind::Method) {
        method_slot(member->name);
        callable_for(member);
      } else if (member->kind == SymbolKind::Property) {
        for (const Symbol* accessor : member->ordered) {
          if (accessor->kind == SymbolKind::Method) callable_for(accessor);
        }
      }
    }
  }
  return id;
}

uint32_t Lowering::method_slot(std::string_view name) {
  const std::string key = check::upper_name(name);
  if (auto found = slots_.find(key); found != slots_.end()) return found->second;
  const auto slot = static_cast<uint32_t>(slots_.size());
  slots_.emplace(key, slot);
  program_.slot_names.push_back(std::string(name));
  return slot;
}

void Lowering::build_vtables() {
  for (size_t id = 1; id < classes_.size(); ++id) {
    std::vector<uint32_t>& table = program_.vtables[id];
    table.assign(slots_.size(), kNoCallable);
    // Walk from the most derived class up: the first definition of a name wins (overrides).
    for (const Symbol* c = classes_[id]; c; c = c->base == c ? nullptr : c->base) {
      for (const Symbol* member : c->ordered) {
        if (member->kind == SymbolKind::Method) {
          const uint32_t slot = method_slot(member->name);
          if (slot < table.size() && table[slot] == kNoCallable && !member->has(check::kAbstract)) {
            table[slot] = callable_for(member);
          }
        } else if (member->kind == SymbolKind::Property) {
          for (const Symbol* accessor : member->ordered) {
            if (accessor->kind != SymbolKind::Method) continue;
            const std::string slot_name = std::string(member->name) + "." + std::string(accessor->name);
            const uint32_t slot = method_slot(slot_name);
            if (slot >= table.size()) table.resize(slot + 1, kNoCallable);
            if (table[slot] == kNoCallable) table[slot] = callable_for(accessor);
          }
        }
      }
    }
    table.resize(slots_.size(), kNoCallable);
  }
}

std::vector<GlobalList> Lowering::global_lists() {
  std::vector<GlobalList> lists;
  for (const Symbol* variable : global_order_) {
    if (variable->kind != SymbolKind::Variable) continue;
    if (variable->section == ast::VarSection::Stat) continue;
    const Symbol* owner = variable->owner;
    std::string list_name = owner ? std::string(owner->name) : std::string("globals");
    auto it = std::find_if(lists.begin(), lists.end(), [&](const GlobalList& list) { return list.name == list_name; });
    if (it == lists.end()) {
      lists.push_back(GlobalList{list_name, {}});
      it = lists.end() - 1;
    }
    VariableView view{std::string(variable->name), variable->type, globals_.at(variable),
                      Layouts::held_by_reference(variable)};
    if (variable->location_node) view.bit = storage_of(variable, nullptr).bit;
    it->variables.push_back(std::move(view));
  }
  return lists;
}

}  // namespace rung::run
