// Expressions: values pushed on the value stack, places in memory (variables, members, array
// elements, dereferenced pointers), and the conversions between types. Types come from the
// checker (BodyChecker::type_of), so the runner computes exactly what the checker accepted.
#include <cstring>

#include <fmt/format.h>

#include "checker/symbols/names.hpp"
#include "checker/types/conversions.hpp"
#include "runner/compile/lowering.hpp"
#include "runner/stdlib/datetime.hpp"
#include "runner/stdlib/natives.hpp"
#include "runner/stdlib/text.hpp"

namespace rung::run {
namespace {

bool is_float(Scalar scalar) { return scalar == Scalar::F32 || scalar == Scalar::F64; }
bool is_integer_scalar(Scalar scalar) { return scalar != Scalar::None && !is_float(scalar); }
bool is_signed_scalar(Scalar scalar) {
  return scalar == Scalar::S8 || scalar == Scalar::S16 || scalar == Scalar::S32 || scalar == Scalar::I64;
}
unsigned scalar_bits(Scalar scalar) {
  switch (scalar) {
    case Scalar::U8:
    case Scalar::S8: return 8;
    case Scalar::U16:
    case Scalar::S16: return 16;
    case Scalar::U32:
    case Scalar::S32:
    case Scalar::F32: return 32;
    default: return 64;
  }
}

Op load_op(Scalar scalar, Place::Mode mode) {
  int kind = 0;
  switch (scalar) {
    case Scalar::U8: kind = 0; break;
    case Scalar::S8: kind = 1; break;
    case Scalar::U16: kind = 2; break;
    case Scalar::S16: kind = 3; break;
    case Scalar::U32: kind = 4; break;
    case Scalar::S32: kind = 5; break;
    case Scalar::I64:
    case Scalar::U64: kind = 6; break;
    case Scalar::F32: kind = 7; break;
    case Scalar::F64: kind = 8; break;
    case Scalar::None: kind = 6; break;
  }
  const int base = static_cast<int>(mode == Place::Mode::Global     ? Op::LD_U8_G
                                    : mode == Place::Mode::Instance ? Op::LD_U8_I
                                    : mode == Place::Mode::Frame    ? Op::LD_U8_F
                                                                    : Op::LD_U8_P);
  return static_cast<Op>(base + kind);
}

Op store_op(Scalar scalar, Place::Mode mode) {
  int kind = 0;
  switch (scalar) {
    case Scalar::U8:
    case Scalar::S8: kind = 0; break;
    case Scalar::U16:
    case Scalar::S16: kind = 1; break;
    case Scalar::U32:
    case Scalar::S32: kind = 2; break;
    case Scalar::F32: kind = 4; break;
    case Scalar::F64: kind = 5; break;
    default: kind = 3; break;
  }
  const int base = static_cast<int>(mode == Place::Mode::Global     ? Op::ST_8_G
                                    : mode == Place::Mode::Instance ? Op::ST_8_I
                                    : mode == Place::Mode::Frame    ? Op::ST_8_F
                                                                    : Op::ST_8_P);
  return static_cast<Op>(base + kind);
}

std::optional<Op> wrap_op(Scalar scalar) {
  switch (scalar) {
    case Scalar::U8: return Op::WRAP_U8;
    case Scalar::S8: return Op::WRAP_S8;
    case Scalar::U16: return Op::WRAP_U16;
    case Scalar::S16: return Op::WRAP_S16;
    case Scalar::U32: return Op::WRAP_U32;
    case Scalar::S32: return Op::WRAP_S32;
    default: return std::nullopt;
  }
}

bool is_point_in_time(const Type* type) {
  return type && (type->kind == TypeKind::Date || type->kind == TypeKind::TimeOfDay || type->kind == TypeKind::DateTime);
}

bool is_string_type(const Type* type) {
  return type && (type->kind == TypeKind::String || type->kind == TypeKind::WString);
}

int64_t units_per_ns_divisor(TimeUnit unit) {
  switch (unit) {
    case TimeUnit::Milliseconds: return 1'000'000;
    case TimeUnit::Seconds: return 1'000'000'000;
    case TimeUnit::Nanoseconds: return 1;
  }
  return 1;
}

}  // namespace

bool BodyCompiler::inside_accessor_of(const Symbol* property) const {
  // In GET and SET the property's name is the value itself (the accessor's result slot).
  return pou_->owner == property && property->kind == SymbolKind::Property;
}

const Type* BodyCompiler::bool_type() const { return lowering_.model().types().elementary("BOOL"); }
const Type* BodyCompiler::elementary(std::string_view name) const { return lowering_.model().types().elementary(name); }

void BodyCompiler::fail(SyntaxNode node, std::string message) {
  lowering_.error(pou_, node, std::move(message));
  emit(Op::TRAP, static_cast<uint32_t>(TrapKind::Unsupported), lowering_.message("not compiled: see the error above"));
}

uint64_t BodyCompiler::temporary(const Type* type) {
  const TypeLayout layout = lowering_.layouts().of(type);
  const uint64_t alignment = std::max<uint64_t>(layout.alignment, 1);
  frame_size_ = (frame_size_ + alignment - 1) / alignment * alignment;
  const uint64_t at = frame_size_;
  frame_size_ += std::max<uint64_t>(layout.size, 1);
  return at;
}

void BodyCompiler::push_constant(const check::ConstValue& value, const Type* type) {
  using Kind = check::ConstValue::Kind;
  const Type* storage = Layouts::storage_type(type);
  if (value.kind == Kind::String || is_string_type(storage)) {
    const bool wide = storage && storage->kind == TypeKind::WString;
    std::string bytes = wide ? utf8_to_utf16le(value.text) : utf8_to_single_byte(value.text);
    bytes.append(wide ? 2 : 1, '\0');
    emit(Op::ADDR_G, static_cast<uint32_t>(lowering_.constant_bytes(bytes, wide ? 2 : 1)));
    return;
  }
  const Scalar scalar = scalar_kind(storage);
  if (scalar == Scalar::F32) {
    const auto v = static_cast<float>(value.as_real());
    uint32_t bits = 0;
    std::memcpy(&bits, &v, 4);
    emit(Op::PUSH_F32, 0, bits);
    return;
  }
  if (scalar == Scalar::F64) {
    const double v = value.as_real();
    int64_t bits = 0;
    std::memcpy(&bits, &v, 8);
    emit(Op::PUSH_F64, 0, bits);
    return;
  }
  __int128 number = value.integer;
  if (value.kind == Kind::Real) {
    int64_t bits = 0;
    std::memcpy(&bits, &value.real, 8);
    emit(Op::PUSH_F64, 0, bits);
    convert(elementary("LREAL"), type);
    return;
  }
  if (value.kind == Kind::Duration && storage && storage->kind == TypeKind::Duration && !storage->long_variant) {
    number /= 1'000'000;
  }
  if (storage && storage->kind == TypeKind::Bool) number = number != 0;
  int64_t pushed = static_cast<int64_t>(static_cast<uint64_t>(number));
  // Sign- or zero-extend to the slot representation of the type.
  switch (scalar) {
    case Scalar::U8: pushed = static_cast<uint8_t>(pushed); break;
    case Scalar::S8: {
      const auto byte = static_cast<uint8_t>(pushed);
      pushed = static_cast<int64_t>(byte ^ 0x80u) - 0x80;  // sign-extend the low byte
      break;
    }
    case Scalar::U16: pushed = static_cast<uint16_t>(pushed); break;
    case Scalar::S16: pushed = static_cast<int16_t>(pushed); break;
    case Scalar::U32: pushed = static_cast<uint32_t>(pushed); break;
    case Scalar::S32: pushed = static_cast<int32_t>(pushed); break;
    default: break;
  }
  emit(Op::PUSH, 0, pushed);
}

void BodyCompiler::convert(const Type* from, const Type* to) {
  if (!from || !to || from == to) return;
  const Type* source = Layouts::storage_type(from);
  const Type* target = Layouts::storage_type(to);
  if (!source || !target || source == target) return;
  const Scalar fs = scalar_kind(source);
  const Scalar ts = scalar_kind(target);
  if (ts == Scalar::None || fs == Scalar::None) return;
  const auto rounding = lowering_.profile().real_to_int_rounding == 1 ? RoundRule::HalfToEven : RoundRule::HalfAwayFromZero;
  // Durations and points in time of different resolution (TIME ms, LTIME ns, DT s).
  const bool timed_source = source->kind == TypeKind::Duration || is_point_in_time(source);
  const bool timed_target = target->kind == TypeKind::Duration || is_point_in_time(target);
  if (timed_source && timed_target) {
    const int64_t from_div = units_per_ns_divisor(time_unit_of(source));
    const int64_t to_div = units_per_ns_divisor(time_unit_of(target));
    if (from_div > to_div) {
      emit(Op::PUSH, 0, from_div / to_div);
      emit(Op::MUL);
    } else if (from_div < to_div) {
      emit(Op::PUSH, 0, to_div / from_div);
      emit(Op::DIV_S);
    }
  }
  if (is_float(fs) && is_float(ts)) {
    if (fs != ts) emit(fs == Scalar::F32 ? Op::F32_TO_F64 : Op::F64_TO_F32);
    return;
  }
  if (is_integer_scalar(fs) && is_float(ts)) {
    const bool unsigned_source = fs == Scalar::U64;
    if (ts == Scalar::F32) emit(unsigned_source ? Op::U64_TO_F32 : Op::S64_TO_F32);
    if (ts == Scalar::F64) emit(unsigned_source ? Op::U64_TO_F64 : Op::S64_TO_F64);
    return;
  }
  if (is_float(fs) && is_integer_scalar(ts)) {
    const bool unsigned_target = !is_signed_scalar(ts);
    if (unsigned_target && lowering_.profile().negative_real_to_unsigned_clamps) {
      emit(Op::PUSH_F64, 0, 0);
      if (fs == Scalar::F32) emit(Op::F64_TO_F32);
      emit(fs == Scalar::F32 ? Op::MAX_F32 : Op::MAX_F64);
    }
    if (fs == Scalar::F32) emit(unsigned_target ? Op::F32_TO_U64 : Op::F32_TO_S64, static_cast<uint32_t>(rounding));
    if (fs == Scalar::F64) emit(unsigned_target ? Op::F64_TO_U64 : Op::F64_TO_S64, static_cast<uint32_t>(rounding));
    if (target->kind == TypeKind::Bool) {
      emit(Op::TO_BOOL);
    } else if (auto wrap = wrap_op(ts)) {
      emit(*wrap);
    }
    return;
  }
  // Integers of every kind.
  if (target->kind == TypeKind::Bool && source->kind != TypeKind::Bool) {
    emit(Op::TO_BOOL);
    return;
  }
  if (fs == ts) return;
  if (scalar_bits(ts) < scalar_bits(fs) || is_signed_scalar(ts) != is_signed_scalar(fs)) {
    if (auto wrap = wrap_op(ts)) emit(*wrap);
  }
}

const Type* BodyCompiler::arithmetic_type(const Type* type) const {
  const Type* storage = Layouts::storage_type(type);
  if (!storage) return type;
  if (storage->kind == TypeKind::Enum) storage = storage->element ? storage->element : elementary("INT");
  if (lowering_.profile().integer_promotion &&
      (storage->kind == TypeKind::SignedInt || storage->kind == TypeKind::UnsignedInt ||
       storage->kind == TypeKind::Bit) &&
      storage->bits < 32 && storage->bits > 1) {
    return elementary("DINT");
  }
  return storage;
}

const Type* BodyCompiler::value(SyntaxNode node, const Type* target) {
  if (!node) {
    fail(node, "missing expression");
    return target;
  }
  if (++depth_ > 400) {
    --depth_;
    fail(node, "expression nested too deeply to run");
    return target;
  }
  struct DepthGuard {
    int& depth;
    ~DepthGuard() { --depth; }
  } guard{depth_};
  const std::string_view kind = node.kind();
  if (kind == "parenthesized_expression" && node.named_child_count() >= 1) return value(node.named_child(0), target);
  set_position(node);
  const ExprInfo in = info(node);
  if (in.value && !in.names_type && kind != "call_expression") {
    const Type* type = target ? target : in.type;
    // A duration used as a number counts in its own unit (T#1s is 1000 in a TIME, 10^9 in an
    // LTIME): push it as its type, then convert.
    const Type* own = Layouts::storage_type(in.type);
    const Type* wanted = Layouts::storage_type(type);
    if (in.value->kind == check::ConstValue::Kind::Duration && own && own->kind == TypeKind::Duration && wanted &&
        wanted->kind != TypeKind::Duration) {
      push_constant(*in.value, in.type);
      convert(in.type, type);
      return type;
    }
    push_constant(*in.value, type);
    return type;
  }
  const Type* pushed = in.type;
  if (kind == "binary_expression") {
    pushed = binary(node, in);
  } else if (kind == "unary_expression") {
    pushed = unary(node, in);
  } else if (kind == "call_expression") {
    pushed = call(node, true);
  } else if (kind == "date_literal" || kind == "time_of_day_literal" || kind == "date_and_time_literal") {
    const PointKind point = kind == "date_literal"          ? PointKind::Date
                            : kind == "time_of_day_literal" ? PointKind::TimeOfDay
                                                            : PointKind::DateAndTime;
    const Type* type = Layouts::storage_type(in.type);
    auto number = parse_point_literal(node.text(), point, time_unit_of(type));
    if (!number) {
      fail(node, fmt::format("cannot read the literal '{}'", node.text()));
      return target;
    }
    emit(Op::PUSH, 0, *number);
  } else if (in.symbol && in.symbol->kind == SymbolKind::Property && !inside_accessor_of(in.symbol)) {
    pushed = call(node, true);  // reading a property calls its GET
  } else if (auto where = place(node)) {
    load(*where);
    pushed = where->type;
  } else {
    fail(node, fmt::format("rung cannot run this expression yet ({})", kind));
    return target ? target : in.type;
  }
  if (target) {
    convert(pushed, target);
    return target;
  }
  return pushed;
}

const Type* BodyCompiler::comparison(std::string_view op, SyntaxNode left, SyntaxNode right) {
  const ExprInfo l = info(left);
  const ExprInfo r = info(right);
  const Type* lt = Layouts::storage_type(l.type);
  const Type* rt = Layouts::storage_type(r.type);
  if (is_string_type(lt) || is_string_type(rt)) {
    const bool wide = (lt && lt->kind == TypeKind::WString) || (rt && rt->kind == TypeKind::WString);
    // A literal takes the other side's string type (its capacity does not matter here).
    value(left, l.untyped_literal ? rt : nullptr);
    value(right, r.untyped_literal ? lt : nullptr);
    emit(Op::NATIVE, lowering_.native(wide ? native_wstring_compare : native_string_compare,
                                      wide ? "WSTRING_COMPARE" : "STRING_COMPARE"));
    emit(Op::PUSH, 0, 0);
    if (op == "=") emit(Op::EQ);
    if (op == "<>") emit(Op::NE);
    if (op == "<") emit(Op::LT_S);
    if (op == "<=") emit(Op::LE_S);
    if (op == ">") emit(Op::GT_S);
    if (op == ">=") emit(Op::GE_S);
    return bool_type();
  }
  // The type both sides are compared in.
  const Type* common = nullptr;
  if (l.untyped_literal && !r.untyped_literal) {
    common = r.type;
  } else if (r.untyped_literal && !l.untyped_literal) {
    common = l.type;
  } else {
    common = check::common_numeric_type(arithmetic_type(l.type), arithmetic_type(r.type), lowering_.model().types());
    if (!common) common = l.type;
  }
  common = arithmetic_type(common);
  value(left, common);
  value(right, common);
  const Scalar scalar = scalar_kind(common);
  if (scalar == Scalar::F32 || scalar == Scalar::F64) {
    const bool single = scalar == Scalar::F32;
    if (op == "=") emit(single ? Op::EQ_F32 : Op::EQ_F64);
    if (op == "<>") emit(single ? Op::NE_F32 : Op::NE_F64);
    if (op == "<") emit(single ? Op::LT_F32 : Op::LT_F64);
    if (op == "<=") emit(single ? Op::LE_F32 : Op::LE_F64);
    if (op == ">") emit(single ? Op::GT_F32 : Op::GT_F64);
    if (op == ">=") emit(single ? Op::GE_F32 : Op::GE_F64);
    return bool_type();
  }
  if (scalar == Scalar::None) {
    // Structures compare bytewise (CODESYS allows = on structures of one type only in newer versions).
    fail(left, "comparison of structured values is not supported");
    return bool_type();
  }
  const bool is_signed = is_signed_scalar(scalar);
  if (op == "=") emit(Op::EQ);
  if (op == "<>") emit(Op::NE);
  if (op == "<") emit(is_signed ? Op::LT_S : Op::LT_U);
  if (op == "<=") emit(is_signed ? Op::LE_S : Op::LE_U);
  if (op == ">") emit(is_signed ? Op::GT_S : Op::GT_U);
  if (op == ">=") emit(is_signed ? Op::GE_S : Op::GE_U);
  return bool_type();
}

const Type* BodyCompiler::binary(SyntaxNode node, const ExprInfo& in) {
  const std::string op = ast::operator_of(node);
  SyntaxNode left = node.child_by_field("left");
  SyntaxNode right = node.child_by_field("right");
  if (op == "=" || op == "<>" || op == "<" || op == "<=" || op == ">" || op == ">=") return comparison(op, left, right);

  const Type* result = Layouts::storage_type(in.type);
  if (!result || result->is_unknown()) {
    fail(node, "the type of this expression is unknown");
    return in.type;
  }
  // Logic on BOOL, with or without short-circuit.
  if (op == "AND" || op == "&" || op == "OR" || op == "XOR" || op == "AND_THEN" || op == "OR_ELSE") {
    if (result->kind == TypeKind::Bool) {
      const bool is_and = op == "AND" || op == "&" || op == "AND_THEN";
      const bool short_circuit = op == "AND_THEN" || op == "OR_ELSE" || (op != "XOR" && lowering_.profile().short_circuit_logic);
      value(left, bool_type());
      if (short_circuit) {
        const uint32_t skip = emit(is_and ? Op::JZ_KEEP : Op::JNZ_KEEP);
        value(right, bool_type());
        patch(skip, here());
        return bool_type();
      }
      value(right, bool_type());
      emit(op == "XOR" ? Op::XOR : (is_and ? Op::AND : Op::OR));
      return bool_type();
    }
    value(left, result);
    value(right, result);
    emit(op == "XOR" ? Op::XOR : ((op == "OR" || op == "OR_ELSE") ? Op::OR : Op::AND));
    return result;
  }
  const ExprInfo l = info(left);
  const ExprInfo r = info(right);
  // Points in time and durations: different units on each side.
  const Type* lt = Layouts::storage_type(l.type);
  const Type* rt = Layouts::storage_type(r.type);
  if ((op == "+" || op == "-") && (is_point_in_time(lt) || is_point_in_time(rt))) {
    const Type* nano = elementary("LINT");
    // Compute in nanoseconds, then back into the result's unit.
    auto to_ns = [&](SyntaxNode side, const Type* type) {
      value(side, type);
      const int64_t factor = units_per_ns_divisor(time_unit_of(type));
      if (factor != 1) {
        emit(Op::PUSH, 0, factor);
        emit(Op::MUL);
      }
    };
    to_ns(left, lt->kind == TypeKind::Duration || is_point_in_time(lt) ? lt : result);
    to_ns(right, rt->kind == TypeKind::Duration || is_point_in_time(rt) ? rt : result);
    emit(op == "+" ? Op::ADD : Op::SUB);
    const int64_t factor = units_per_ns_divisor(time_unit_of(result));
    if (factor != 1) {
      emit(Op::PUSH, 0, factor);
      emit(Op::DIV_S);
    }
    (void)nano;
    if (auto wrap = wrap_op(scalar_kind(result))) emit(*wrap);
    return result;
  }
  if (op == "**") {
    const Type* real = scalar_kind(result) == Scalar::F32 ? elementary("REAL") : elementary("LREAL");
    value(left, elementary("LREAL"));
    value(right, elementary("LREAL"));
    emit(Op::NATIVE, lowering_.native(native_expt_lreal, "EXPT_LREAL"));
    convert(elementary("LREAL"), real);
    return real;
  }
  const Type* computed = arithmetic_type(result);
  // TIME * 2, TIME / 2: the factor is a plain number.
  const bool scale_duration = (op == "*" || op == "/") && result->kind == TypeKind::Duration &&
                              (!lt || lt->kind != TypeKind::Duration || !rt || rt->kind != TypeKind::Duration);
  if (scale_duration && rt && (rt->kind == TypeKind::Real)) {
    value(left, elementary("LREAL"));
    value(right, elementary("LREAL"));
    emit(op == "*" ? Op::MUL_F64 : Op::DIV_F64);
    convert(elementary("LREAL"), result);
    return result;
  }
  value(left, computed);
  value(right, computed);
  const Scalar scalar = scalar_kind(computed);
  if (op == "/" || op == "MOD") {
    const Type* storage_type = Layouts::storage_type(computed);
    const char* name = scalar == Scalar::F32   ? "CheckDivReal"
                       : scalar == Scalar::F64 ? "CheckDivLReal"
                       : storage_type->bits >= 64 ? "CheckDivLint"
                       : storage_type->bits >= 32 ? "CheckDivDInt"
                                                  : "CheckDivInt";
    const Symbol* check = check_function(name);
    if (!check && storage_type->bits == 32 && scalar != Scalar::F32) check = check_function("CheckDivInt");
    if (check) call_check(check, computed, {});
  }
  if (scalar == Scalar::F32 || scalar == Scalar::F64) {
    const bool single = scalar == Scalar::F32;
    if (op == "+") emit(single ? Op::ADD_F32 : Op::ADD_F64);
    if (op == "-") emit(single ? Op::SUB_F32 : Op::SUB_F64);
    if (op == "*") emit(single ? Op::MUL_F32 : Op::MUL_F64);
    if (op == "/") emit(single ? Op::DIV_F32 : Op::DIV_F64);
    if (op == "MOD") fail(node, "MOD needs integers");
    return computed;
  }
  const bool is_signed = is_signed_scalar(scalar);
  if (op == "+") emit(Op::ADD);
  if (op == "-") emit(Op::SUB);
  if (op == "*") emit(Op::MUL);
  if (op == "/") emit(is_signed ? Op::DIV_S : Op::DIV_U);
  if (op == "MOD") emit(is_signed ? Op::MOD_S : Op::MOD_U);
  if (auto wrap = wrap_op(scalar)) emit(*wrap);
  return computed;
}

const Type* BodyCompiler::unary(SyntaxNode node, const ExprInfo& in) {
  const std::string op = ast::operator_of(node);
  SyntaxNode operand = node.child_by_field("operand");
  const Type* result = Layouts::storage_type(in.type);
  if (!result || result->is_unknown()) {
    fail(node, "the type of this expression is unknown");
    return in.type;
  }
  if (op == "NOT") {
    value(operand, result);
    if (result->kind == TypeKind::Bool) {
      emit(Op::BNOT);
    } else {
      emit(Op::NOT);
      if (auto wrap = wrap_op(scalar_kind(result))) emit(*wrap);
    }
    return result;
  }
  if (op == "-") {
    const Type* computed = arithmetic_type(result);
    value(operand, computed);
    const Scalar scalar = scalar_kind(computed);
    if (scalar == Scalar::F32) {
      emit(Op::NEG_F32);
    } else if (scalar == Scalar::F64) {
      emit(Op::NEG_F64);
    } else {
      emit(Op::NEG);
      if (auto wrap = wrap_op(scalar)) emit(*wrap);
    }
    return computed;
  }
  return value(operand, result);  // unary +
}

// --- places ---------------------------------------------------------------------------------------

Place BodyCompiler::slot_place(const Symbol* variable) {
  Place place;
  place.symbol = variable;
  place.type = variable->type;
  const Storage storage = lowering_.storage_of(variable, pou_);
  switch (storage.kind) {
    case Storage::Kind::Global: place.mode = Place::Mode::Global; break;
    case Storage::Kind::Instance: place.mode = Place::Mode::Instance; break;
    case Storage::Kind::Frame: place.mode = Place::Mode::Frame; break;
    case Storage::Kind::None:
      place.mode = Place::Mode::Global;
      place.type = nullptr;
      return place;
  }
  place.offset = storage.offset;
  place.bit = storage.bit;
  return place;
}

Place BodyCompiler::variable_place(const Symbol* variable) {
  Place place = slot_place(variable);
  if (place.type && Layouts::held_by_reference(variable)) {
    // The slot holds the address of the value.
    emit(load_op(Scalar::U64, place.mode), static_cast<uint32_t>(place.offset));
    place.mode = Place::Mode::Pointer;
    place.offset = 0;
    const Type* type = variable->type;
    if (type && type->kind == TypeKind::Reference) {
      place.type = type->element;
      // CODESYS (compiler 3.5.7.40 on) calls CheckPointer on REFERENCE accesses as on pointers.
      if (const Symbol* check = check_function("CheckPointer")) {
        Layouts& layouts = lowering_.layouts();
        call_check(check, elementary("LWORD"),
                   {static_cast<int64_t>(layouts.of(type->element).size),
                    static_cast<int64_t>(layouts.granularity(type->element)), writing_ ? 1 : 0});
      }
    }
  }
  return place;
}

bool BodyCompiler::push_bound(SyntaxNode array, size_t dimension, bool upper) {
  while (array && array.kind() == "parenthesized_expression" && array.named_child_count() == 1) {
    array = array.named_child(0);
  }
  const ExprInfo in = info(array);
  const Type* type = Layouts::storage_type(in.type);
  if (!type || type->kind != TypeKind::Array || dimension >= type->dimensions.size()) return false;
  const check::ArrayDimension& bounds = type->dimensions[dimension];
  if (!bounds.open) {
    emit(Op::PUSH, 0, upper ? bounds.upper : bounds.lower);
    return true;
  }
  // ARRAY[*]: the bounds the caller stored in the parameter's slot.
  const Symbol* variable = in.symbol;
  if (array.kind() != "identifier" || !variable || Layouts::open_dimensions(variable) == 0) return false;
  Place slot = slot_place(variable);
  if (!slot.type) return false;
  slot.offset += Layouts::kOpenBoundsOffset + 16 * dimension + (upper ? 8 : 0);
  slot.type = elementary("LINT");
  slot.bit = -1;
  load(slot);
  return true;
}

Place BodyCompiler::as_pointer(const Place& place) {
  Place out = place;
  switch (place.mode) {
    case Place::Mode::Global: emit(Op::ADDR_G, static_cast<uint32_t>(place.offset)); break;
    case Place::Mode::Instance: emit(Op::ADDR_I, static_cast<uint32_t>(place.offset)); break;
    case Place::Mode::Frame: emit(Op::ADDR_F, static_cast<uint32_t>(place.offset)); break;
    case Place::Mode::Pointer:
      if (place.offset != 0) {
        emit(Op::PUSH, 0, static_cast<int64_t>(place.offset));
        emit(Op::ADD);
      }
      break;
  }
  out.mode = Place::Mode::Pointer;
  out.offset = 0;
  return out;
}

void BodyCompiler::address_of(const Place& place) { as_pointer(place); }

void BodyCompiler::load(const Place& place) {
  const Scalar scalar = scalar_kind(place.type);
  if (scalar == Scalar::None && place.bit < 0) {
    address_of(place);
    return;
  }
  Place at = place;
  if (at.mode == Place::Mode::Pointer && at.offset != 0) at = as_pointer(at);
  emit(load_op(place.bit >= 0 && scalar == Scalar::None ? Scalar::U64 : scalar, at.mode),
       static_cast<uint32_t>(at.offset));
  if (place.bit >= 0) emit(Op::BIT_GET, static_cast<uint32_t>(place.bit));
}

void BodyCompiler::store(const Place& place, const Type* value_type) {
  if (!place.type) {
    fail(SyntaxNode(), "internal error: a store without a type");
    return;
  }
  const Scalar scalar = scalar_kind(place.type);
  if (scalar == Scalar::None) {
    const Type* storage = Layouts::storage_type(place.type);
    if (storage && storage->kind == TypeKind::String) {
      emit(Op::STR_COPY, storage->length);
    } else if (storage && storage->kind == TypeKind::WString) {
      emit(Op::WSTR_COPY, storage->length);
    } else {
      uint64_t size = lowering_.layouts().of(place.type).size;
      if (value_type) size = std::min(size, lowering_.layouts().of(value_type).size);
      emit(Op::COPY, static_cast<uint32_t>(size));
    }
    return;
  }
  emit(store_op(scalar, place.mode), static_cast<uint32_t>(place.offset));
}

std::optional<Place> BodyCompiler::place(SyntaxNode node) {
  const std::string_view kind = node.kind();
  if (kind == "parenthesized_expression" && node.named_child_count() >= 1) return place(node.named_child(0));
  if (auto special = special_place(node)) return special;  // IL's current result, SFC's step.X
  set_position(node);
  const ExprInfo in = info(node);
  if (kind == "identifier" || kind == "global_reference") return identifier_place(node, in);
  if (kind == "member_expression") return member_place(node, in);
  if (kind == "index_expression") return index_place(node);
  if (kind == "dereference_expression") return deref_place(node, in);
  if (kind == "direct_variable") {
    // %QX0.0, %MW4 written in code: the process image.
    std::string why;
    auto at = lowering_.image_address(node.text(), &why);
    if (!at) {
      fail(node, why);
      return std::nullopt;
    }
    return Place{Place::Mode::Global, at->address, at->type, at->bit, nullptr};
  }
  return std::nullopt;
}

std::optional<Place> BodyCompiler::identifier_place(SyntaxNode node, const ExprInfo& in) {
  const Symbol* symbol = in.symbol;
  if (!symbol) {
    const std::string_view name = node.kind() == "global_reference" ? node.child_by_field("name").text() : node.text();
    if (check::names_equal(name, "THIS") || check::names_equal(name, "SUPER")) {
      // THIS is a pointer to the running instance: THIS^ dereferences it.
      return std::nullopt;
    }
    return std::nullopt;
  }
  // The POU's own name in its body: the function's (method's, accessor's) result.
  if (check::is_pou_kind(symbol->kind)) {
    if (symbol == pou_ || (pou_->owner == symbol && symbol->kind == SymbolKind::Property)) {
      const Type* result = Layouts::result_type(pou_);
      if (!result) return std::nullopt;
      return Place{Place::Mode::Frame, lowering_.layouts().pou(pou_).result_offset, result, -1, symbol};
    }
    if (symbol->kind == SymbolKind::Program) {
      return Place{Place::Mode::Global, lowering_.program_instance(symbol), symbol->type, -1, symbol};
    }
    return std::nullopt;
  }
  if (symbol->kind != SymbolKind::Variable) return std::nullopt;
  Place place = variable_place(symbol);
  if (!place.type) return std::nullopt;
  return place;
}

std::optional<Place> BodyCompiler::member_place(SyntaxNode node, const ExprInfo& in) {
  SyntaxNode object = node.child_by_field("object");
  SyntaxNode member = node.child_by_field("member");
  const ExprInfo object_info = info(object);
  // GVL.x, Namespace.x: the global itself.
  if (object_info.names_namespace || object_info.names_type) {
    if (in.symbol && in.symbol->kind == SymbolKind::Variable) return variable_place(in.symbol);
    return std::nullopt;
  }
  // Bit access: w.3, w.cBit.
  const Type* object_type = Layouts::storage_type(object_info.type);
  const bool integer_object = object_type && (object_type->kind == TypeKind::Bit || object_type->kind == TypeKind::SignedInt ||
                                              object_type->kind == TypeKind::UnsignedInt);
  if (integer_object && member) {
    std::optional<__int128> bit;
    if (member.kind() == "integer_literal") {
      bit = check::parse_integer_literal(member.text());
    } else if (auto constant = lowering_.model().constant_value(member, pou_); constant && constant->is_integer()) {
      bit = constant->integer;
    }
    if (bit) {
      auto base = place(object);
      if (!base) return std::nullopt;
      base->bit = static_cast<int>(*bit);
      base->type = object_info.type;
      return base;
    }
  }
  const Symbol* field = in.symbol;
  if (!field || field->kind != SymbolKind::Variable) return std::nullopt;
  // PLC_PRG.x from elsewhere: the program's instance.
  if (object_info.symbol && object_info.symbol->kind == SymbolKind::Program) {
    lowering_.layouts().pou(object_info.symbol);
    Place place{Place::Mode::Global, lowering_.program_instance(object_info.symbol) + lowering_.layouts().offset(field),
                field->type, -1, field};
    if (Layouts::held_by_reference(field)) {
      emit(Op::LD_I64_G, static_cast<uint32_t>(place.offset));
      place = Place{Place::Mode::Pointer, 0, field->type, -1, field};
    }
    return place;
  }
  auto base = place(object);
  if (!base) return std::nullopt;
  if (object_type) lowering_.layouts().of(object_type);
  Place out = *base;
  out.offset += lowering_.layouts().offset(field);
  out.type = field->type;
  out.symbol = field;
  out.bit = -1;
  if (Layouts::held_by_reference(field)) {
    Place slot = out;
    if (slot.mode == Place::Mode::Pointer && slot.offset != 0) slot = as_pointer(slot);
    emit(load_op(Scalar::U64, slot.mode), static_cast<uint32_t>(slot.offset));
    out = Place{Place::Mode::Pointer, 0, field->type, -1, field};
    if (field->type && field->type->kind == TypeKind::Reference) out.type = field->type->element;
  }
  return out;
}

std::optional<Place> BodyCompiler::index_place(SyntaxNode node) {
  SyntaxNode object = node.child_by_field("object");
  const std::vector<SyntaxNode> indices = node.children_by_field("index");
  const ExprInfo object_info = info(object);
  const Type* type = Layouts::storage_type(object_info.type);
  if (!type) return std::nullopt;
  const Type* index_type = elementary("LINT");
  if (type->kind == TypeKind::Pointer) {
    // p[i]: CODESYS indexes a pointer like an array starting at 0.
    value(object);
    const uint64_t size = lowering_.layouts().of(type->element).size;
    for (SyntaxNode index : indices) {
      value(index, index_type);
      emit(Op::PUSH, 0, static_cast<int64_t>(size));
      emit(Op::MUL);
      emit(Op::ADD);
    }
    return Place{Place::Mode::Pointer, 0, type->element, -1, nullptr};
  }
  if (type->kind != TypeKind::Array && type->kind != TypeKind::String && type->kind != TypeKind::WString) {
    return std::nullopt;
  }
  auto base = place(object);
  if (!base) return std::nullopt;
  Place at = as_pointer(*base);
  size_t next = 0;
  while (next < indices.size()) {
    type = Layouts::storage_type(type);
    if (type->kind == TypeKind::String || type->kind == TypeKind::WString) {
      // s[i]: the i-th character's code (CODESYS, from 0).
      const bool wide = type->kind == TypeKind::WString;
      value(indices[next++], index_type);
      emit(Op::INDEX, lowering_.dimension(check::ArrayDimension{0, type->length, false, true}, wide ? 2 : 1));
      at.type = wide ? elementary("WORD") : elementary("BYTE");
      return at;
    }
    if (type->kind != TypeKind::Array) {
      fail(node, "too many indexes for this array");
      return std::nullopt;
    }
    const uint64_t element_size = lowering_.layouts().of(type->element).size;
    // Strides: the last dimension varies fastest.
    std::vector<uint64_t> strides(type->dimensions.size());
    uint64_t stride = element_size;
    for (size_t d = type->dimensions.size(); d-- > 0;) {
      strides[d] = stride;
      const auto& dimension = type->dimensions[d];
      stride *= static_cast<uint64_t>(std::max<int64_t>(0, dimension.upper - dimension.lower + 1));
    }
    for (size_t d = 0; d < type->dimensions.size() && next < indices.size(); ++d) {
      const check::ArrayDimension& dimension = type->dimensions[d];
      if (dimension.open) {
        // ARRAY[*]: bounds and strides from the slot, at run time.
        const Symbol* parameter = object.kind() == "identifier" ? object_info.symbol : nullptr;
        if (next != d || !parameter || Layouts::open_dimensions(parameter) == 0) {
          fail(node, "rung indexes an ARRAY[*] parameter only through its own name");
          return std::nullopt;
        }
        value(indices[next++], index_type);
        if (const Symbol* bounds = check_function("CheckBounds")) {
          call_check_computed(bounds, index_type,
                              std::vector<std::function<void()>>{[&] { push_bound(object, d, false); },
                                                        [&] { push_bound(object, d, true); }});
        }
        push_bound(object, d, false);
        push_bound(object, d, true);
        emit(Op::BOUNDS);
        emit(Op::PUSH, 0, static_cast<int64_t>(element_size));
        for (size_t k = d + 1; k < type->dimensions.size(); ++k) {
          push_bound(object, k, true);
          push_bound(object, k, false);
          emit(Op::SUB);
          emit(Op::PUSH, 0, 1);
          emit(Op::ADD);
          emit(Op::MUL);
        }
        emit(Op::MUL);
        emit(Op::ADD);
        continue;
      }
      value(indices[next++], index_type);
      if (const Symbol* bounds = check_function("CheckBounds")) {
        call_check(bounds, index_type, {dimension.lower, dimension.upper});
      }
      emit(Op::INDEX, lowering_.dimension(dimension, strides[d]));
    }
    type = type->element;
  }
  at.type = type;
  at.symbol = nullptr;
  return at;
}

std::optional<Place> BodyCompiler::deref_place(SyntaxNode node, const ExprInfo& in) {
  SyntaxNode operand = node.child_by_field("operand");
  const ExprInfo operand_info = info(operand);
  // THIS^ and SUPER^: the running instance.
  const std::string_view text = operand.text();
  if (operand.kind() == "identifier" && !operand_info.symbol &&
      (check::names_equal(text, "THIS") || check::names_equal(text, "SUPER"))) {
    emit(Op::ADDR_I, 0);
    return Place{Place::Mode::Pointer, 0, in.type, -1, nullptr};
  }
  const Type* pointer_type = value(operand);
  if (const Symbol* check = check_function("CheckPointer")) {
    // CODESYS: CheckPointer(ptToTest, iSize, iGran, bWrite) on every dereference; the pointer used
    // is its result.
    Layouts& layouts = lowering_.layouts();
    call_check(check, pointer_type,
               {static_cast<int64_t>(layouts.of(in.type).size), static_cast<int64_t>(layouts.granularity(in.type)),
                writing_ ? 1 : 0});
  }
  return Place{Place::Mode::Pointer, 0, in.type, -1, nullptr};
}

}  // namespace rung::run
