// Implicit check functions (CODESYS "POUs for implicit checks"): when the project declares
// CheckBounds, CheckDivInt/CheckDivDInt/CheckDivLint/CheckDivReal/CheckDivLReal,
// CheckRangeSigned/CheckRangeUnsigned or CheckPointer, the compiler calls them where CODESYS does:
// on every array index, every divisor, every assignment to a subrange and every dereference —
// never inside the check functions themselves, and never in a POU marked
// {attribute 'no_check'}.
#include <functional>

#include "checker/symbols/names.hpp"
#include "runner/compile/lowering.hpp"

namespace rung::run {
namespace {

constexpr std::string_view kCheckNames[] = {"CheckBounds",        "CheckDivInt",        "CheckDivDInt",
                                            "CheckDivLint",       "CheckDivReal",       "CheckDivLReal",
                                            "CheckRangeSigned",   "CheckRangeUnsigned", "CheckPointer"};

bool is_check_function(const Symbol* pou) {
  for (std::string_view name : kCheckNames) {
    if (check::names_equal(pou->name, name)) return true;
  }
  return false;
}

}  // namespace

const Symbol* BodyCompiler::check_function(std::string_view name) const {
  // CODESYS does not check POUs of libraries (the standard blocks' bodies here).
  if (is_check_function(pou_) || pou_->attribute("no_check") || pou_->has(check::kLibrary)) return nullptr;
  for (const Symbol* owner = pou_->owner; owner; owner = owner->owner) {
    if (owner->attribute("no_check")) return nullptr;
  }
  const Symbol* function = lowering_.model().find_global(name);
  if (!function || function->kind != SymbolKind::Function || function->has(check::kLibrary)) return nullptr;
  return function;
}

void BodyCompiler::call_check(const Symbol* function, const Type* value_type, const std::vector<int64_t>& extra) {
  std::vector<std::function<void()>> pushers;
  pushers.reserve(extra.size());
  for (const int64_t value : extra) pushers.emplace_back([this, value] { emit(Op::PUSH, 0, value); });
  call_check_computed(function, value_type, pushers);
}

void BodyCompiler::call_check_computed(const Symbol* function, const Type* value_type,
                                       const std::vector<std::function<void()>>& extra) {
  // The value on top goes through the check function: value := Check(value, extra...).
  std::vector<const Symbol*> inputs;
  for (const Symbol* member : function->ordered) {
    if (member->kind == SymbolKind::Variable && member->section == ast::VarSection::Input) inputs.push_back(member);
  }
  const Type* result = Layouts::result_type(function);
  if (inputs.size() < 1 + extra.size() || !result) return;  // not the documented signature: leave it
  const uint64_t temp = temporary(value_type);
  store(Place{Place::Mode::Frame, temp, value_type, -1, nullptr}, value_type);
  const uint32_t callable = lowering_.callable_for(function);
  Layouts& layouts = lowering_.layouts();
  layouts.pou(function);
  emit(Op::FRAME, callable);
  emit(Op::ADDR_N, static_cast<uint32_t>(layouts.offset(inputs[0])));
  load(Place{Place::Mode::Frame, temp, value_type, -1, nullptr});
  convert(value_type, inputs[0]->type);
  store(Place{Place::Mode::Pointer, 0, inputs[0]->type, -1, nullptr}, inputs[0]->type);
  for (size_t i = 0; i < extra.size(); ++i) {
    emit(Op::ADDR_N, static_cast<uint32_t>(layouts.offset(inputs[i + 1])));
    extra[i]();
    convert(elementary("LINT"), inputs[i + 1]->type);
    store(Place{Place::Mode::Pointer, 0, inputs[i + 1]->type, -1, nullptr}, inputs[i + 1]->type);
  }
  emit(Op::PUSH, 0, 0);
  emit(Op::CALL, callable);
  emit(Op::ADDR_R, static_cast<uint32_t>(layouts.pou(function).result_offset));
  load(Place{Place::Mode::Pointer, 0, result, -1, nullptr});
  convert(result, value_type);
}

void BodyCompiler::range_check(const Type* target) {
  // CODESYS calls CheckRangeSigned/CheckRangeUnsigned on every assignment to a variable of a
  // subrange type; the value stored is the function's result.
  const Type* type = check::underlying(target);
  if (!type || type->kind != TypeKind::Subrange || !type->element) return;
  const Symbol* function = check_function(check::is_signed(type->element) ? "CheckRangeSigned" : "CheckRangeUnsigned");
  if (!function) return;
  call_check(function, target, {type->range_lower, type->range_upper});
}

}  // namespace rung::run
