// Standard functions the compiler turns into instructions or natives: the IEC operators written
// as functions (ADD, SHL, MAX, SEL, MUX, GT ...), type conversions (<A>_TO_<B>, TO_<B>, TRUNC,
// BCD), numeric functions, string functions, and CODESYS operators (ADR, SIZEOF, __NEW, TIME()).
// Library blocks that ST can express are written in ST in library/ instead and compiled like user
// code.
#include <fmt/format.h>

#include "checker/symbols/names.hpp"
#include "runner/compile/lowering.hpp"
#include "runner/stdlib/natives.hpp"

namespace rung::run {
namespace {

bool is_string_type(const Type* type) {
  return type && (type->kind == TypeKind::String || type->kind == TypeKind::WString);
}

bool is_float_type(const Type* type) {
  const Scalar scalar = scalar_kind(type);
  return scalar == Scalar::F32 || scalar == Scalar::F64;
}

bool is_signed_type(const Type* type) {
  const Scalar scalar = scalar_kind(type);
  return scalar == Scalar::S8 || scalar == Scalar::S16 || scalar == Scalar::S32 || scalar == Scalar::I64;
}

TextKind text_kind_of(const Type* type) {
  type = Layouts::storage_type(type);
  if (!type) return TextKind::Signed;
  if (type->kind == TypeKind::Enum) type = type->element;
  if (!type) return TextKind::Signed;
  switch (type->kind) {
    case TypeKind::Bool: return TextKind::Bool;
    case TypeKind::Real: return type->bits == 32 ? TextKind::Real : TextKind::LReal;
    case TypeKind::Duration: return type->long_variant ? TextKind::LTime : TextKind::Time;
    case TypeKind::Date: return type->long_variant ? TextKind::LDate : TextKind::Date;
    case TypeKind::TimeOfDay: return type->long_variant ? TextKind::LTimeOfDay : TextKind::TimeOfDay;
    case TypeKind::DateTime: return type->long_variant ? TextKind::LDateAndTime : TextKind::DateAndTime;
    case TypeKind::SignedInt: return TextKind::Signed;
    default: return TextKind::Unsigned;
  }
}

// The arguments' value nodes in the callee's parameter order (formal calls may name them in any
// order; extensible inputs IN3, IN4 ... follow the declared ones).
std::vector<SyntaxNode> ordered_values(const check::ProjectModel& model, const Symbol* callee,
                                       const std::vector<check::CallArgument>& arguments) {
  std::vector<SyntaxNode> values;
  bool named = false;
  for (const check::CallArgument& argument : arguments) named = named || argument.name;
  if (!named || !callee) {
    for (const check::CallArgument& argument : arguments) {
      if (!argument.output) values.push_back(argument.value);
    }
    return values;
  }
  std::vector<const Symbol*> inputs;
  for (const Symbol* member : callee->ordered) {
    if (member->kind == SymbolKind::Variable &&
        (member->section == ast::VarSection::Input || member->section == ast::VarSection::InOut)) {
      inputs.push_back(member);
    }
  }
  std::vector<std::pair<std::string, SyntaxNode>> extra;
  values.assign(inputs.size(), SyntaxNode());
  size_t position = 0;
  for (const check::CallArgument& argument : arguments) {
    if (argument.output) continue;
    if (!argument.name) {
      if (position < values.size()) values[position] = argument.value;
      ++position;
      continue;
    }
    bool placed = false;
    for (size_t i = 0; i < inputs.size(); ++i) {
      if (check::names_equal(inputs[i]->name, argument.name.text())) {
        values[i] = argument.value;
        placed = true;
      }
    }
    if (!placed) extra.emplace_back(check::upper_name(argument.name.text()), argument.value);
  }
  (void)model;
  std::sort(extra.begin(), extra.end(), [](const auto& a, const auto& b) {
    return a.first.size() != b.first.size() ? a.first.size() < b.first.size() : a.first < b.first;
  });
  for (auto& [name, value] : extra) values.push_back(value);
  while (!values.empty() && !values.back()) values.pop_back();
  return values;
}

// Conversion function names: the target type after the last "_TO_" (or "TO_" at the start).
std::string conversion_target(const std::string& upper) {
  const size_t at = upper.rfind("_TO_");
  if (at != std::string::npos) return upper.substr(at + 4);
  if (upper.starts_with("TO_")) return upper.substr(3);
  return {};
}

}  // namespace

std::optional<const Type*> BodyCompiler::builtin_call(std::string_view name, SyntaxNode call_node, const Symbol* callee,
                                                      const std::vector<check::CallArgument>& arguments,
                                                      const ExprInfo& call_info) {
  const std::string upper = check::upper_name(name);
  const std::vector<SyntaxNode> args = ordered_values(lowering_.model(), callee, arguments);
  const Type* result = call_info.type;
  check::TypeArena& types = lowering_.model().types();
  auto arg_type = [&](size_t i) { return i < args.size() && args[i] ? info(args[i]).type : nullptr; };
  auto need = [&](size_t count) {
    if (args.size() >= count) {
      for (size_t i = 0; i < count; ++i) {
        if (!args[i]) return false;
      }
      return true;
    }
    return false;
  };
  auto native_call = [&](NativeFn function, std::string_view native_name, int64_t b = 0, uint16_t aux = 0) {
    emit(Op::NATIVE, lowering_.native(function, native_name), b, aux);
  };
  // A string result goes to a temporary of the result's capacity (at least 255 characters: the
  // standard functions' STRING(255) results in CODESYS).
  auto string_destination = [&](bool wide) -> const Type* {
    const Type* declared = Layouts::storage_type(result);
    const uint32_t length = declared && is_string_type(declared) ? std::max<uint32_t>(declared->length, 255) : 255;
    const Type* type = types.string_type(wide, length);
    emit(Op::ADDR_F, static_cast<uint32_t>(temporary(type)));
    return type;
  };
  const Type* lint = elementary("LINT");
  const Type* lreal = elementary("LREAL");

  // --- conversions ---------------------------------------------------------------------------
  const std::string target_name = conversion_target(upper);
  const bool trunc = upper == "TRUNC" || upper.starts_with("TRUNC_") || upper.find("_TRUNC_") != std::string::npos;
  if ((!target_name.empty() || trunc) && need(1)) {
    const Type* from = Layouts::storage_type(arg_type(0));
    const Type* to = Layouts::storage_type(result);
    if (!to || to->is_unknown() || !from) return std::nullopt;
    const bool bcd_to = upper.find("BCD_TO_") != std::string::npos;
    const bool to_bcd = upper.find("_TO_BCD") != std::string::npos;
    if (bcd_to || to_bcd) {
      value(args[0], from);
      if (bcd_to) {
        native_call(native_from_bcd, "FROM_BCD", 0, static_cast<uint16_t>(from->bits));
        convert(elementary("ULINT"), to);
      } else {
        convert(from, elementary("ULINT"));
        native_call(native_to_bcd, "TO_BCD", 0, static_cast<uint16_t>(to->bits));
      }
      return to;
    }
    if (is_string_type(to)) {
      const bool wide = to->kind == TypeKind::WString;
      const Type* dst = string_destination(wide);
      if (is_string_type(from)) {
        if (from->kind == to->kind) {
          emit(Op::DUP);
          value(args[0]);
          emit(wide ? Op::WSTR_COPY : Op::STR_COPY, Layouts::storage_type(dst)->length);
          return dst;
        }
        value(args[0]);
        native_call(wide ? native_string_to_wstring : native_wstring_to_string, wide ? "STRING_TO_WSTRING" : "WSTRING_TO_STRING",
                    Layouts::storage_type(dst)->length);
        return dst;
      }
      value(args[0], from);
      native_call(wide ? native_to_wstring : native_to_string, wide ? "TO_WSTRING" : "TO_STRING",
                  Layouts::storage_type(dst)->length, static_cast<uint16_t>(text_kind_of(from)));
      return dst;
    }
    if (is_string_type(from)) {
      value(args[0]);
      const TextKind kind = text_kind_of(to);
      native_call(from->kind == TypeKind::WString ? native_wstring_to : native_string_to,
                  from->kind == TypeKind::WString ? "WSTRING_TO" : "STRING_TO", 0, static_cast<uint16_t>(kind));
      const Type* parsed = kind == TextKind::Signed ? lint : kind == TextKind::Unsigned ? elementary("ULINT") : to;
      convert(parsed, to);
      return to;
    }
    // Points in time: DT_TO_DATE keeps the day, DT_TO_TOD the time of day.
    const bool from_point = from->kind == TypeKind::DateTime || from->kind == TypeKind::Date;
    if (from_point && (to->kind == TypeKind::Date || to->kind == TypeKind::TimeOfDay)) {
      value(args[0], from);
      convert(from, elementary("LDT"));  // nanoseconds
      const int64_t day = int64_t{86400} * 1'000'000'000;
      emit(Op::PUSH, 0, day);
      emit(to->kind == TypeKind::Date ? Op::DIV_S : Op::MOD_S);
      if (to->kind == TypeKind::Date) {
        emit(Op::PUSH, 0, day);
        emit(Op::MUL);
      }
      convert(to->kind == TypeKind::Date ? elementary("LDATE") : elementary("LTOD"), to);
      return to;
    }
    value(args[0], from);
    if (trunc && is_float_type(from)) {
      // Toward zero, whatever the profile's rounding.
      if (scalar_kind(from) == Scalar::F32) emit(Op::F32_TO_F64);
      native_call(native_trunc_lreal, "TRUNC_LREAL");
      convert(lreal, to);
      return to;
    }
    // Durations and integers: TIME counts milliseconds, LTIME nanoseconds (no scaling);
    // between TIME and LTIME convert() scales.
    const bool timed_from = from->kind == TypeKind::Duration || from->kind == TypeKind::Date ||
                            from->kind == TypeKind::TimeOfDay || from->kind == TypeKind::DateTime;
    const bool timed_to = to->kind == TypeKind::Duration || to->kind == TypeKind::Date ||
                          to->kind == TypeKind::TimeOfDay || to->kind == TypeKind::DateTime;
    if (timed_from != timed_to) {
      // Reinterpret the count in the other type: go through the counting integer.
      const Type* count = timed_from ? (scalar_kind(from) == Scalar::U64 ? elementary("ULINT") : elementary("UDINT"))
                                     : nullptr;
      if (count) {
        convert(elementary("ULINT"), to);
        return to;
      }
      convert(from, scalar_kind(to) == Scalar::U64 ? elementary("ULINT") : elementary("UDINT"));
      return to;
    }
    convert(from, to);
    return to;
  }

  // --- arithmetic, logic and selection as functions --------------------------------------------
  auto fold = [&](Op integer_signed, Op integer_unsigned, Op f32, Op f64) -> const Type* {
    const Type* type = arithmetic_type(result);
    for (size_t i = 0; i < args.size(); ++i) {
      value(args[i], type);
      if (i == 0) continue;
      const Scalar scalar = scalar_kind(type);
      if (scalar == Scalar::F32) {
        emit(f32);
      } else if (scalar == Scalar::F64) {
        emit(f64);
      } else {
        emit(is_signed_type(type) ? integer_signed : integer_unsigned);
      }
    }
    convert(type, result);
    return result;
  };
  if ((upper == "ADD" || upper == "MUL" || upper == "SUB" || upper == "DIV" || upper == "MOD") && need(2)) {
    if (upper == "ADD") return fold(Op::ADD, Op::ADD, Op::ADD_F32, Op::ADD_F64);
    if (upper == "MUL") return fold(Op::MUL, Op::MUL, Op::MUL_F32, Op::MUL_F64);
    if (upper == "SUB") return fold(Op::SUB, Op::SUB, Op::SUB_F32, Op::SUB_F64);
    if (upper == "DIV") return fold(Op::DIV_S, Op::DIV_U, Op::DIV_F32, Op::DIV_F64);
    return fold(Op::MOD_S, Op::MOD_U, Op::HALT, Op::HALT);
  }
  if ((upper == "MAX" || upper == "MIN") && need(1)) {
    const bool max = upper == "MAX";
    return fold(max ? Op::MAX_S : Op::MIN_S, max ? Op::MAX_U : Op::MIN_U, max ? Op::MAX_F32 : Op::MIN_F32,
                max ? Op::MAX_F64 : Op::MIN_F64);
  }
  if (upper == "LIMIT" && need(3)) {
    const Type* type = arithmetic_type(result);
    const Scalar scalar = scalar_kind(type);
    const bool single = scalar == Scalar::F32;
    const bool real = single || scalar == Scalar::F64;
    value(args[0], type);  // MN
    value(args[1], type);  // IN
    value(args[2], type);  // MX
    emit(real ? (single ? Op::MIN_F32 : Op::MIN_F64) : (is_signed_type(type) ? Op::MIN_S : Op::MIN_U));
    emit(real ? (single ? Op::MAX_F32 : Op::MAX_F64) : (is_signed_type(type) ? Op::MAX_S : Op::MAX_U));
    convert(type, result);
    return result;
  }
  if ((upper == "AND" || upper == "OR" || upper == "XOR") && need(2)) {
    for (size_t i = 0; i < args.size(); ++i) {
      value(args[i], result);
      if (i > 0) emit(upper == "AND" ? Op::AND : (upper == "OR" ? Op::OR : Op::XOR));
    }
    return result;
  }
  if (upper == "NOT" && need(1)) {
    value(args[0], result);
    if (Layouts::storage_type(result)->kind == TypeKind::Bool) {
      emit(Op::BNOT);
    } else {
      emit(Op::NOT);
      convert(lint, result);
    }
    return result;
  }
  if (upper == "MOVE" && need(1)) return value(args[0], result);
  if ((upper == "SHL" || upper == "SHR" || upper == "ROL" || upper == "ROR") && need(2)) {
    const Type* in_type = Layouts::storage_type(arg_type(0));
    if (!in_type || in_type->bits == 0) return std::nullopt;
    const unsigned width = std::max<unsigned>(in_type->bits, 1);
    // SHR of a signed integer (SINT, INT, DINT: a CODESYS extension, IEC 61131-3 shifts ANY_BIT only)
    // is an arithmetic shift, filled with the sign bit (CODESYS V3 textbook, SHR example; CODESYS
    // 2.3 online help, operator SHR): the value stays sign-extended to 64 bits and the count is
    // capped at 64 - width, which already fills every bit of the type with the sign.
    const bool arithmetic = upper == "SHR" && is_signed_type(in_type) && width < 64;
    value(args[0], in_type);
    if (width < 64 && !arithmetic) {
      emit(Op::PUSH, 0, static_cast<int64_t>((uint64_t{1} << width) - 1));
      emit(Op::AND);
    }
    value(args[1], lint);
    if (arithmetic) {
      emit(Op::PUSH, 0, static_cast<int64_t>(64 - width));
      emit(Op::MIN_U);
    }
    if (upper == "SHL") emit(Op::SHL);
    if (upper == "SHR") emit(Op::SHR);
    if (upper == "ROL") emit(Op::ROL, 0, 0, static_cast<uint16_t>(width));
    if (upper == "ROR") emit(Op::ROR, 0, 0, static_cast<uint16_t>(width));
    convert(elementary("ULINT"), in_type);
    convert(in_type, result);
    return result;
  }
  if (upper == "SEL" && need(3)) {
    value_as_bool(args[0]);
    const uint32_t take_first = emit(Op::JZ);
    value(args[2], result);
    const uint32_t done = emit(Op::JMP);
    patch(take_first, here());
    value(args[1], result);
    patch(done, here());
    return result;
  }
  if (upper == "MUX" && need(2)) {
    const uint64_t selector = temporary(lint);
    value(args[0], lint);
    emit(Op::ST_64_F, static_cast<uint32_t>(selector));
    std::vector<uint32_t> to_end;
    for (size_t i = 1; i < args.size(); ++i) {
      emit(Op::LD_I64_F, static_cast<uint32_t>(selector));
      emit(Op::PUSH, 0, static_cast<int64_t>(i - 1));
      emit(Op::EQ);
      const uint32_t next = emit(Op::JZ);
      value(args[i], result);
      to_end.push_back(emit(Op::JMP));
      patch(next, here());
    }
    // K out of range: CODESYS returns the last input; rung stops with a clear error instead.
    emit(Op::TRAP, static_cast<uint32_t>(TrapKind::IndexOutOfBounds),
         lowering_.message(fmt::format("MUX: K is outside 0..{}", args.size() - 2)));
    for (uint32_t jump : to_end) patch(jump, here());
    return result;
  }
  if ((upper == "GT" || upper == "GE" || upper == "EQ" || upper == "LE" || upper == "LT" || upper == "NE") && need(2)) {
    const std::string_view op = upper == "GT"   ? ">"
                                : upper == "GE" ? ">="
                                : upper == "EQ" ? "="
                                : upper == "LE" ? "<="
                                : upper == "LT" ? "<"
                                                : "<>";
    for (size_t i = 0; i + 1 < args.size(); ++i) {
      comparison(op, args[i], args[i + 1]);
      if (i > 0) emit(Op::AND);
    }
    return bool_type();
  }
  if (upper == "ABS" && need(1)) {
    const Type* type = arithmetic_type(result);
    value(args[0], type);
    const Scalar scalar = scalar_kind(type);
    emit(scalar == Scalar::F32 ? Op::ABS_F32 : scalar == Scalar::F64 ? Op::ABS_F64 : Op::ABS_S);
    convert(type, result);
    return result;
  }
  struct Math {
    const char* name;
    NativeFn function;
  };
  static constexpr Math kMath[] = {
      {"SQRT", native_sqrt}, {"LN", native_ln},     {"LOG", native_log},   {"EXP", native_exp},
      {"SIN", native_sin},   {"COS", native_cos},   {"TAN", native_tan},   {"ASIN", native_asin},
      {"ACOS", native_acos}, {"ATAN", native_atan},
  };
  for (const Math& math : kMath) {
    if (upper == math.name && need(1)) {
      value(args[0], lreal);
      native_call(math.function, math.name);
      const Type* out = is_float_type(result) ? result : lreal;
      convert(lreal, out);
      return out;
    }
  }
  if (upper == "ATAN2" && need(2)) {
    value(args[0], lreal);
    value(args[1], lreal);
    native_call(native_atan2, "ATAN2");
    convert(lreal, result);
    return result;
  }
  if (upper == "EXPT" && need(2)) {
    const Type* out = is_float_type(result) ? result : lreal;
    value(args[0], lreal);
    value(args[1], lreal);
    native_call(native_expt_lreal, "EXPT_LREAL");
    convert(lreal, out);
    return out;
  }

  // --- time and date (library/iec/time.st): the generic ones; the others have ST bodies -----------
  if ((upper == "MUL_TIME" || upper == "DIV_TIME" || upper == "MUL_LTIME" || upper == "DIV_LTIME") && need(2)) {
    // What `IN1 * IN2` and `IN1 / IN2` mean: an integer factor scales the count (milliseconds,
    // nanoseconds), a REAL one is applied in LREAL and rounded as REAL_TO_<int> rounds.
    const Type* duration = elementary(upper.find("LTIME") != std::string::npos ? "LTIME" : "TIME");
    const bool multiply = upper.starts_with("MUL");
    if (is_float_type(Layouts::storage_type(arg_type(1)))) {
      value(args[0], lreal);
      value(args[1], lreal);
      emit(multiply ? Op::MUL_F64 : Op::DIV_F64);
      convert(lreal, duration);
      return duration;
    }
    value(args[0], duration);
    value(args[1], duration);
    emit(multiply ? Op::MUL : Op::DIV_U);
    convert(elementary("ULINT"), duration);
    return duration;
  }
  if ((upper == "CONCAT_DATE" && need(3)) || (upper == "CONCAT_TOD" && need(4)) || (upper == "CONCAT_DT" && need(7))) {
    const size_t count = upper == "CONCAT_DATE" ? 3 : upper == "CONCAT_TOD" ? 4 : 7;
    for (size_t i = 0; i < count; ++i) value(args[i], lint);
    const DateField what = count == 3 ? DateField::Date : count == 4 ? DateField::TimeOfDay : DateField::DateAndTime;
    native_call(native_concat_date_time, "CONCAT_DATE_TIME", 0, static_cast<uint16_t>(what));
    const Type* out = elementary(count == 3 ? "DATE" : count == 4 ? "TOD" : "DT");
    convert(elementary("ULINT"), out);
    return out;
  }

  // --- strings ----------------------------------------------------------------------------------
  struct StringFunction {
    const char* name;
    const char* wide_name;
    NativeFn narrow;
    NativeFn wide;
    int arguments;        // string arguments first, then integers
    int string_arguments;
    bool returns_string;
  };
  static constexpr StringFunction kStrings[] = {
      {"LEN", "WLEN", native_len, native_wlen, 1, 1, false},
      {"LEFT", "WLEFT", native_left, native_wleft, 2, 1, true},
      {"RIGHT", "WRIGHT", native_right, native_wright, 2, 1, true},
      {"MID", "WMID", native_mid, native_wmid, 3, 1, true},
      {"INSERT", "WINSERT", native_insert, native_winsert, 3, 2, true},
      {"DELETE", "WDELETE", native_delete, native_wdelete, 3, 1, true},
      {"REPLACE", "WREPLACE", native_replace, native_wreplace, 4, 2, true},
      {"FIND", "WFIND", native_find, native_wfind, 2, 2, false},
  };
  for (const StringFunction& function : kStrings) {
    const bool named_wide = upper == function.wide_name;
    if (upper != function.name && !named_wide) continue;
    if (!need(static_cast<size_t>(function.arguments))) return std::nullopt;
    const Type* first = Layouts::storage_type(arg_type(0));
    const bool wide = named_wide || (first && first->kind == TypeKind::WString);
    const Type* dst = function.returns_string ? string_destination(wide) : nullptr;
    for (int i = 0; i < function.arguments; ++i) {
      if (i < function.string_arguments) {
        value(args[static_cast<size_t>(i)]);
      } else {
        value(args[static_cast<size_t>(i)], lint);
      }
    }
    native_call(wide ? function.wide : function.narrow, wide ? function.wide_name : function.name,
                dst ? Layouts::storage_type(dst)->length : 0);
    if (!function.returns_string) {
      convert(lint, result);
      return result;
    }
    return dst;
  }
  if ((upper == "CONCAT" || upper == "WCONCAT") && need(1)) {
    const Type* first = Layouts::storage_type(arg_type(0));
    const bool wide = upper == "WCONCAT" || (first && first->kind == TypeKind::WString);
    const Type* dst = string_destination(wide);
    const uint32_t length = Layouts::storage_type(dst)->length;
    // Copy the first into the destination, then append the others one by one.
    emit(Op::DUP);
    value(args[0]);
    emit(wide ? Op::WSTR_COPY : Op::STR_COPY, length);
    for (size_t i = 1; i < args.size(); ++i) {
      emit(Op::DUP);
      value(args[i]);
      native_call(wide ? native_wconcat : native_concat, wide ? "WCONCAT" : "CONCAT", length);
    }
    (void)call_node;
    return dst;
  }

  // --- CODESYS operators --------------------------------------------------------------------------
  if ((upper == "ADR" || upper == "REF" || upper == "ADRINST") && need(1)) {
    auto target = place(args[0]);
    if (!target) {
      fail(args[0], fmt::format("{} needs a variable", upper));
      return result;
    }
    address_of(*target);
    return result;
  }
  if ((upper == "SIZEOF" || upper == "XSIZEOF") && need(1)) {
    const ExprInfo in = info(args[0]);
    const Type* type = in.type;
    if (in.names_type && in.symbol && in.symbol->type) type = in.symbol->type;
    const uint64_t size = lowering_.layouts().of(type).size;
    emit(Op::PUSH, 0, static_cast<int64_t>(size));
    convert(elementary("ULINT"), result);
    return result;
  }
  if ((upper == "LOWER_BOUND" || upper == "UPPER_BOUND") && need(2)) {
    // LOWER_BOUND(arr, 1): the first dimension's bound; a constant for a fixed array, the caller's
    // array's bound for an ARRAY[*] parameter.
    const auto dimension = lowering_.model().constant_value(args[1], pou_);
    if (!dimension || !dimension->is_integer() || dimension->integer < 1 ||
        !push_bound(args[0], static_cast<size_t>(dimension->integer - 1), upper == "UPPER_BOUND")) {
      fail(call_node, fmt::format("{} needs an array and the constant number of one of its dimensions", upper));
      emit(Op::PUSH, 0, 0);
    }
    convert(lint, result);
    return result;
  }
  if (upper == "TIME" && args.empty()) {
    native_call(native_time_ms, "TIME");
    return elementary("TIME");
  }
  if (upper == "__LTIME" && args.empty()) {
    native_call(native_time_ns, "__LTIME");
    return elementary("LTIME");
  }
  if (upper == "__ISVALIDREF" && need(1)) {
    const ExprInfo in = info(args[0]);
    if (!in.symbol || !Layouts::held_by_reference(in.symbol)) {
      emit(Op::PUSH, 0, 1);
      return bool_type();
    }
    const Storage storage = lowering_.storage_of(in.symbol, pou_);
    const Op load = storage.kind == Storage::Kind::Global     ? Op::LD_I64_G
                    : storage.kind == Storage::Kind::Instance ? Op::LD_I64_I
                                                              : Op::LD_I64_F;
    emit(load, static_cast<uint32_t>(storage.offset));
    emit(Op::PUSH, 0, static_cast<int64_t>(kNullGuard));
    emit(Op::GE_U);
    return bool_type();
  }
  if (upper == "__NEW" && need(1)) {
    const ExprInfo in = info(args[0]);
    const Type* type = in.names_type ? (in.symbol && in.symbol->type ? in.symbol->type : in.type) : nullptr;
    if (!type) {
      fail(args[0], "__NEW needs a type");
      return result;
    }
    const uint64_t size = lowering_.layouts().of(type).size;
    if (args.size() > 1) {
      value(args[1], lint);
      emit(Op::PUSH, 0, static_cast<int64_t>(size));
      emit(Op::MUL);
    } else {
      emit(Op::PUSH, 0, static_cast<int64_t>(size));
    }
    native_call(native_new, "__NEW");
    // A new FB instance starts from its type's template: header and initial values.
    const Type* storage = Layouts::storage_type(type);
    if (storage && (storage->kind == TypeKind::Pou || storage->kind == TypeKind::Struct) && args.size() == 1) {
      std::vector<uint8_t> image;
      lowering_.write_default(image, 0, type);
      image.resize(size, 0);
      const uint64_t at = lowering_.constant_bytes(std::string(image.begin(), image.end()), 8);
      emit(Op::DUP);
      emit(Op::ADDR_G, static_cast<uint32_t>(at));
      emit(Op::COPY, static_cast<uint32_t>(size));
      // Then built as a declared instance is: members, computed values, FB_init (CODESYS calls
      // FB_init from __NEW).
      const Symbol* block = storage->kind == TypeKind::Pou ? storage->declaration : nullptr;
      if (block && lowering_.needs_init(block)) {
        const uint64_t temp = temporary(elementary("LWORD"));
        emit(Op::DUP);
        emit(Op::ST_64_F, static_cast<uint32_t>(temp));
        construct_instance(block, [&] { emit(Op::LD_I64_F, static_cast<uint32_t>(temp)); }, SyntaxNode());
      }
    }
    return result;
  }
  if (upper == "__DELETE" && need(1)) {
    // An FB instance gets its FB_exit first (CODESYS calls it from __DELETE).
    const Type* pointer = Layouts::storage_type(arg_type(0));
    const Type* target = pointer && pointer->kind == TypeKind::Pointer ? Layouts::storage_type(pointer->element) : nullptr;
    const Symbol* block = target && target->kind == TypeKind::Pou ? target->declaration : nullptr;
    value(args[0]);
    if (block && lowering_.needs_exit(block)) {
      const uint64_t temp = temporary(elementary("LWORD"));
      emit(Op::ST_64_F, static_cast<uint32_t>(temp));
      emit(Op::LD_I64_F, static_cast<uint32_t>(temp));
      const uint32_t skip = emit(Op::JZ);
      destruct_instance(block, [&] { emit(Op::LD_I64_F, static_cast<uint32_t>(temp)); });
      patch(skip, here());
      emit(Op::LD_I64_F, static_cast<uint32_t>(temp));
    }
    native_call(native_delete_block, "__DELETE");
    return lowering_.model().types().void_type();
  }
  return std::nullopt;
}

}  // namespace rung::run
