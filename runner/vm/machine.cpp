// The interpreter loop. One switch over typed instructions; registers live in locals so the
// compiler keeps them in machine registers. Memory accesses through computed addresses (mode P)
// are checked against the memory bounds; direct accesses (modes G, I, F) use offsets the compiler
// proved in range, with THIS checked once per call.
#include "runner/vm/machine.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

namespace rung::run {

std::string_view op_name(Op op) {
  static constexpr std::string_view kNames[] = {
#define RUNG_OPCODE_NAME(name) #name,
      RUNG_OPCODES(RUNG_OPCODE_NAME)
#undef RUNG_OPCODE_NAME
  };
  const auto index = static_cast<size_t>(op);
  return index < std::size(kNames) ? kNames[index] : "?";
}

const Callable* Program::callable_at(uint32_t pc) const {
  for (const Callable& callable : callables) {
    if (callable.compiled && pc >= callable.code_begin && pc < callable.code_end) return &callable;
  }
  return nullptr;
}

namespace {

constexpr size_t kValueSlots = 1u << 16;
constexpr size_t kValueMargin = 1024;  // a callee's expressions never need more
constexpr uint64_t kMaxCallDepth = 10'000;

uint64_t align8(uint64_t value) { return (value + 7) & ~uint64_t{7}; }

template <typename T>
T load(const uint8_t* memory, uint64_t address) {
  T value;
  std::memcpy(&value, memory + address, sizeof(T));
  return value;
}

// A SINT's byte as a 64-bit slot (avoids char-signedness conversions).
int64_t sign_extend8(uint8_t byte) { return static_cast<int64_t>(byte ^ 0x80u) - 0x80; }

template <typename T>
void store(uint8_t* memory, uint64_t address, T value) {
  std::memcpy(memory + address, &value, sizeof(T));
}

// Float to integer with the profile's rounding; out of range saturates (C++ leaves it undefined).
int64_t round_to_integer(double value, RoundRule rule) {
  if (std::isnan(value)) return 0;
  double rounded = value;
  switch (rule) {
    case RoundRule::HalfAwayFromZero: rounded = std::round(value); break;
    case RoundRule::HalfToEven: rounded = std::nearbyint(value); break;
    case RoundRule::Truncate: rounded = std::trunc(value); break;
  }
  if (rounded >= 9223372036854775807.0) return std::numeric_limits<int64_t>::max();
  if (rounded <= -9223372036854775808.0) return std::numeric_limits<int64_t>::min();
  return static_cast<int64_t>(rounded);
}

uint64_t round_to_unsigned(double value, RoundRule rule) {
  if (value >= 9223372036854775808.0) {
    double rounded = rule == RoundRule::Truncate ? std::trunc(value) : std::round(value);
    if (rounded >= 18446744073709551615.0) return std::numeric_limits<uint64_t>::max();
    return static_cast<uint64_t>(rounded);
  }
  // Negative values keep their two's complement bits, as the x86 conversion CODESYS uses does.
  return static_cast<uint64_t>(round_to_integer(value, rule));
}

int64_t integer_power(int64_t base, int64_t exponent) {
  if (exponent < 0) return base == 1 ? 1 : (base == -1 ? (exponent % 2 == 0 ? 1 : -1) : 0);
  uint64_t result = 1;
  uint64_t factor = static_cast<uint64_t>(base);
  auto e = static_cast<uint64_t>(exponent);
  while (e != 0) {
    if (e & 1) result *= factor;
    factor *= factor;
    e >>= 1;
  }
  return static_cast<int64_t>(result);
}

uint64_t rotate(uint64_t value, uint64_t count, unsigned width, bool left) {
  const uint64_t mask = width >= 64 ? ~uint64_t{0} : ((uint64_t{1} << width) - 1);
  value &= mask;
  count %= width;
  if (count == 0) return value;
  const uint64_t moved = left ? (value << count) | (value >> (width - count)) : (value >> count) | (value << (width - count));
  return moved & mask;
}

std::string_view trap_name(TrapKind kind) {
  switch (kind) {
    case TrapKind::DivisionByZero: return "division by zero";
    case TrapKind::IndexOutOfBounds: return "array index out of bounds";
    case TrapKind::NullPointer: return "null pointer dereference";
    case TrapKind::InvalidPointer: return "invalid pointer or reference";
    case TrapKind::StackOverflow: return "stack overflow";
    case TrapKind::Watchdog: return "watchdog";
    case TrapKind::OutOfMemory: return "out of memory";
    case TrapKind::MissingImplementation: return "missing implementation";
    case TrapKind::AbstractCall: return "call of an abstract method";
    case TrapKind::Unsupported: return "not supported";
  }
  return "run-time error";
}

}  // namespace

Machine::Machine(const Program& program) : program_(program) {
  const uint64_t image = align8(std::max<uint64_t>(program.image.size(), kNullGuard));
  stack_begin_ = image;
  stack_end_ = stack_begin_ + align8(program.stack_bytes);
  heap_begin_ = stack_end_;
  heap_top_ = heap_begin_;
  memory_.assign(heap_begin_ + align8(program.heap_bytes), 0);
  std::copy(program.image.begin(), program.image.end(), memory_.begin());
  values_.resize(kValueSlots);
  sp_ = values_.data();
  values_limit_ = values_.data() + kValueSlots - kValueMargin;
}

void Machine::trap(TrapKind kind, std::string message) {
  if (error_) return;
  RunError error;
  error.kind = kind;
  error.message = message.empty() ? std::string(trap_name(kind)) : std::move(message);
  error.stack = call_stack_;
  error.stack.push_back(StackEntry{kNoCallable, current_pc_});
  std::reverse(error.stack.begin(), error.stack.end());
  for (StackEntry& entry : error.stack) {
    if (const Callable* callable = program_.callable_at(entry.pc)) {
      entry.callable = static_cast<uint32_t>(callable - program_.callables.data());
    }
  }
  error_ = std::move(error);
}

uint8_t* Machine::checked(uint64_t address, uint64_t bytes) {
  if (address < kNullGuard) {
    trap(TrapKind::NullPointer, {});
    return nullptr;
  }
  if (!valid(address, bytes)) {
    trap(TrapKind::InvalidPointer, fmt::format("invalid pointer or reference: address 16#{:X} is outside the PLC's memory", address));
    return nullptr;
  }
  return memory_.data() + address;
}

uint64_t Machine::allocate(uint64_t bytes) {
  bytes = align8(std::max<uint64_t>(bytes, 8));
  for (auto it = free_blocks_.begin(); it != free_blocks_.end(); ++it) {
    if (it->second == bytes) {
      const uint64_t address = it->first;
      free_blocks_.erase(it);
      std::memset(memory_.data() + address, 0, bytes);
      live_blocks_.emplace_back(address, bytes);
      return address;
    }
  }
  if (heap_top_ + bytes > memory_.size()) return 0;
  const uint64_t address = heap_top_;
  heap_top_ += bytes;
  std::memset(memory_.data() + address, 0, bytes);
  live_blocks_.emplace_back(address, bytes);
  return address;
}

void Machine::release(uint64_t address) {
  for (auto it = live_blocks_.begin(); it != live_blocks_.end(); ++it) {
    if (it->first == address) {
      free_blocks_.push_back(*it);
      live_blocks_.erase(it);
      return;
    }
  }
}

bool Machine::call(uint32_t callable_index, uint64_t instance) {
  if (error_) return false;
  if (callable_index >= program_.callables.size()) return false;
  const Callable& callable = program_.callables[callable_index];
  if (!callable.compiled) {
    current_pc_ = 0;
    trap(TrapKind::MissingImplementation, fmt::format("'{}' has no implementation", callable.name));
    return false;
  }
  if (instance != 0 && callable.instance_size != 0 && !valid(instance, callable.instance_size)) {
    trap(TrapKind::InvalidPointer, {});
    return false;
  }
  call_instance_ = instance;
  call_stack_.clear();
  return execute(callable_index) && !error_;
}

bool Machine::execute(uint32_t entry) {
  const Callable& first = program_.callables[entry];
  uint8_t* const mem = memory_.data();
  const Instr* const code = program_.code.data();
  const Slot* const values_limit = values_limit_;

  std::vector<Return>& returns = returns_;
  std::vector<uint64_t>& pending = pending_;  // frames opened by FRAME whose CALL has not come yet
  returns.clear();
  pending.clear();
  returns.reserve(64);
  pending.reserve(16);

  uint64_t sp_mem = stack_begin_;
  uint64_t frame = sp_mem;
  if (first.frame_size > stack_end_ - sp_mem) {
    trap(TrapKind::StackOverflow, {});
    return false;
  }
  if (!first.frame_image.empty()) std::memcpy(mem + frame, first.frame_image.data(), first.frame_image.size());
  sp_mem += align8(first.frame_size);
  uint64_t inst = call_instance_;
  uint64_t nframe = 0;
  uint64_t rframe = frame;
  Slot* sp = sp_;
  const Instr* pc = code + first.code_begin;
  uint64_t budget = loop_budget_;

  auto fail = [&](TrapKind kind, std::string message) {
    current_pc_ = static_cast<uint32_t>(pc - code);
    sp_ = sp;
    trap(kind, std::move(message));
  };

#define POP() (*--sp)
#define TOP() (sp[-1])
#define NEXT() \
  ++pc;        \
  continue

  for (;;) {
    const Instr& in = *pc;
    switch (in.op) {
      case Op::PUSH: (sp++)->i = in.b; NEXT();
      case Op::PUSH_F32: {
        float value;
        const auto bits = static_cast<uint32_t>(in.b);
        std::memcpy(&value, &bits, 4);
        (sp++)->f32 = value;
        NEXT();
      }
      case Op::PUSH_F64: {
        double value;
        std::memcpy(&value, &in.b, 8);
        (sp++)->f64 = value;
        NEXT();
      }
      case Op::ADDR_G: (sp++)->u = in.a; NEXT();
      case Op::ADDR_I: (sp++)->u = inst + in.a; NEXT();
      case Op::ADDR_F: (sp++)->u = frame + in.a; NEXT();
      case Op::ADDR_R: (sp++)->u = rframe + in.a; NEXT();
      case Op::ADDR_N: (sp++)->u = nframe + in.a; NEXT();
      case Op::DUP: *sp = sp[-1]; ++sp; NEXT();
      case Op::POP: --sp; NEXT();
      case Op::SWAP: std::swap(sp[-1], sp[-2]); NEXT();
      case Op::OVER: *sp = sp[-2]; ++sp; NEXT();

#define RUNG_LOADS(MODE, BASE)                                                                   \
  case Op::LD_U8_##MODE: (sp++)->i = load<uint8_t>(mem, (BASE) + in.a); NEXT();                   \
  case Op::LD_S8_##MODE: (sp++)->i = sign_extend8(load<uint8_t>(mem, (BASE) + in.a)); NEXT();      \
  case Op::LD_U16_##MODE: (sp++)->i = load<uint16_t>(mem, (BASE) + in.a); NEXT();                 \
  case Op::LD_S16_##MODE: (sp++)->i = load<int16_t>(mem, (BASE) + in.a); NEXT();                  \
  case Op::LD_U32_##MODE: (sp++)->i = load<uint32_t>(mem, (BASE) + in.a); NEXT();                 \
  case Op::LD_S32_##MODE: (sp++)->i = load<int32_t>(mem, (BASE) + in.a); NEXT();                  \
  case Op::LD_I64_##MODE: (sp++)->i = load<int64_t>(mem, (BASE) + in.a); NEXT();                  \
  case Op::LD_F32_##MODE: (sp++)->f32 = load<float>(mem, (BASE) + in.a); NEXT();                  \
  case Op::LD_F64_##MODE: (sp++)->f64 = load<double>(mem, (BASE) + in.a); NEXT();
      RUNG_LOADS(G, 0)
      RUNG_LOADS(I, inst)
      RUNG_LOADS(F, frame)
#undef RUNG_LOADS

#define RUNG_LOAD_P(KIND, TYPE, FIELD, EXTEND)                \
  case Op::LD_##KIND##_P: {                                   \
    const uint64_t address = TOP().u;                         \
    if (!valid(address, sizeof(TYPE))) [[unlikely]] {         \
      fail(address < kNullGuard ? TrapKind::NullPointer : TrapKind::InvalidPointer, {}); \
      return false;                                           \
    }                                                         \
    TOP().FIELD = EXTEND(load<TYPE>(mem, address));           \
    NEXT();                                                   \
  }
      RUNG_LOAD_P(U8, uint8_t, i, )
      RUNG_LOAD_P(S8, uint8_t, i, sign_extend8)
      RUNG_LOAD_P(U16, uint16_t, i, )
      RUNG_LOAD_P(S16, int16_t, i, )
      RUNG_LOAD_P(U32, uint32_t, i, )
      RUNG_LOAD_P(S32, int32_t, i, )
      RUNG_LOAD_P(I64, int64_t, i, )
      RUNG_LOAD_P(F32, float, f32, )
      RUNG_LOAD_P(F64, double, f64, )
#undef RUNG_LOAD_P

#define RUNG_STORES(MODE, BASE)                                                                           \
  case Op::ST_8_##MODE: store<uint8_t>(mem, (BASE) + in.a, static_cast<uint8_t>(POP().u)); NEXT();     \
  case Op::ST_16_##MODE: store<uint16_t>(mem, (BASE) + in.a, static_cast<uint16_t>(POP().u)); NEXT();  \
  case Op::ST_32_##MODE: store<uint32_t>(mem, (BASE) + in.a, static_cast<uint32_t>(POP().u)); NEXT();  \
  case Op::ST_64_##MODE: store<uint64_t>(mem, (BASE) + in.a, POP().u); NEXT();                         \
  case Op::ST_F32_##MODE: store<float>(mem, (BASE) + in.a, POP().f32); NEXT();                         \
  case Op::ST_F64_##MODE: store<double>(mem, (BASE) + in.a, POP().f64); NEXT();
      RUNG_STORES(G, 0)
      RUNG_STORES(I, inst)
      RUNG_STORES(F, frame)
#undef RUNG_STORES

#define RUNG_STORE_P(KIND, TYPE, EXPR)                        \
  case Op::ST_##KIND##_P: {                                   \
    const Slot value = POP();                                 \
    const uint64_t address = POP().u;                         \
    if (!valid(address, sizeof(TYPE))) [[unlikely]] {         \
      fail(address < kNullGuard ? TrapKind::NullPointer : TrapKind::InvalidPointer, {}); \
      return false;                                           \
    }                                                         \
    store<TYPE>(mem, address, EXPR);                          \
    NEXT();                                                   \
  }
      RUNG_STORE_P(8, uint8_t, static_cast<uint8_t>(value.u))
      RUNG_STORE_P(16, uint16_t, static_cast<uint16_t>(value.u))
      RUNG_STORE_P(32, uint32_t, static_cast<uint32_t>(value.u))
      RUNG_STORE_P(64, uint64_t, value.u)
      RUNG_STORE_P(F32, float, value.f32)
      RUNG_STORE_P(F64, double, value.f64)
#undef RUNG_STORE_P

      case Op::BIT_GET: TOP().u = (TOP().u >> in.a) & 1u; NEXT();
      case Op::BIT_SET: {
        const uint64_t bit = POP().u & 1u;
        const uint64_t mask = uint64_t{1} << in.a;
        TOP().u = (TOP().u & ~mask) | (bit << in.a);
        NEXT();
      }

      case Op::COPY: {
        const uint64_t source = POP().u;
        const uint64_t target = POP().u;
        if (!valid(source, in.a) || !valid(target, in.a)) [[unlikely]] {
          fail(std::min(source, target) < kNullGuard ? TrapKind::NullPointer : TrapKind::InvalidPointer, {});
          return false;
        }
        std::memmove(mem + target, mem + source, in.a);
        NEXT();
      }
      case Op::STR_COPY:
      case Op::WSTR_COPY: {
        const uint64_t unit = in.op == Op::STR_COPY ? 1 : 2;
        const uint64_t source = POP().u;
        const uint64_t target = POP().u;
        const uint64_t capacity = in.a;
        if (!valid(target, (capacity + 1) * unit) || !valid(source, unit)) [[unlikely]] {
          fail(std::min(source, target) < kNullGuard ? TrapKind::NullPointer : TrapKind::InvalidPointer, {});
          return false;
        }
        // Length of the source, bounded by the capacity and by memory.
        uint64_t length = 0;
        const uint64_t source_limit = (memory_.size() - source) / unit;
        while (length < capacity && length < source_limit) {
          const uint8_t* at = mem + source + length * unit;
          if (at[0] == 0 && (unit == 1 || at[1] == 0)) break;
          ++length;
        }
        std::memmove(mem + target, mem + source, length * unit);
        std::memset(mem + target + length * unit, 0, unit);
        NEXT();
      }
      case Op::ZERO: {
        const uint64_t target = POP().u;
        if (!valid(target, in.a)) [[unlikely]] {
          fail(TrapKind::InvalidPointer, {});
          return false;
        }
        std::memset(mem + target, 0, in.a);
        NEXT();
      }

      case Op::ADD: sp[-2].u += sp[-1].u; --sp; NEXT();
      case Op::SUB: sp[-2].u -= sp[-1].u; --sp; NEXT();
      case Op::MUL: sp[-2].u *= sp[-1].u; --sp; NEXT();
      case Op::DIV_S:
      case Op::MOD_S: {
        const int64_t divisor = POP().i;
        const int64_t dividend = TOP().i;
        if (divisor == 0) [[unlikely]] {
          fail(TrapKind::DivisionByZero, {});
          return false;
        }
        if (divisor == -1) {
          TOP().u = in.op == Op::DIV_S ? 0 - static_cast<uint64_t>(dividend) : 0;
        } else {
          TOP().i = in.op == Op::DIV_S ? dividend / divisor : dividend % divisor;
        }
        NEXT();
      }
      case Op::DIV_U:
      case Op::MOD_U: {
        const uint64_t divisor = POP().u;
        if (divisor == 0) [[unlikely]] {
          fail(TrapKind::DivisionByZero, {});
          return false;
        }
        TOP().u = in.op == Op::DIV_U ? TOP().u / divisor : TOP().u % divisor;
        NEXT();
      }
      case Op::NEG: TOP().u = 0 - TOP().u; NEXT();
      case Op::ABS_S: if (TOP().i < 0) TOP().u = 0 - TOP().u; NEXT();
      case Op::AND: sp[-2].u &= sp[-1].u; --sp; NEXT();
      case Op::OR: sp[-2].u |= sp[-1].u; --sp; NEXT();
      case Op::XOR: sp[-2].u ^= sp[-1].u; --sp; NEXT();
      case Op::NOT: TOP().u = ~TOP().u; NEXT();
      case Op::BNOT: TOP().u ^= 1u; NEXT();
      case Op::SHL: {
        const uint64_t count = POP().u;
        TOP().u = count >= 64 ? 0 : TOP().u << count;
        NEXT();
      }
      case Op::SHR: {
        const uint64_t count = POP().u;
        TOP().u = count >= 64 ? 0 : TOP().u >> count;
        NEXT();
      }
      case Op::ROL:
      case Op::ROR: {
        const uint64_t count = POP().u;
        TOP().u = rotate(TOP().u, count, in.aux, in.op == Op::ROL);
        NEXT();
      }
      case Op::EXPT_I: {
        const int64_t exponent = POP().i;
        TOP().i = integer_power(TOP().i, exponent);
        NEXT();
      }
      case Op::WRAP_S8: TOP().i = sign_extend8(static_cast<uint8_t>(TOP().u)); NEXT();
      case Op::WRAP_U8: TOP().u = static_cast<uint8_t>(TOP().u); NEXT();
      case Op::WRAP_S16: TOP().i = static_cast<int16_t>(TOP().u); NEXT();
      case Op::WRAP_U16: TOP().u = static_cast<uint16_t>(TOP().u); NEXT();
      case Op::WRAP_S32: TOP().i = static_cast<int32_t>(TOP().u); NEXT();
      case Op::WRAP_U32: TOP().u = static_cast<uint32_t>(TOP().u); NEXT();
      case Op::TO_BOOL: TOP().u = TOP().u != 0; NEXT();

#define RUNG_COMPARE(OP, FIELD, EXPR) \
  case Op::OP: sp[-2].u = (sp[-2].FIELD EXPR sp[-1].FIELD) ? 1 : 0; --sp; NEXT();
      RUNG_COMPARE(EQ, u, ==)
      RUNG_COMPARE(NE, u, !=)
      RUNG_COMPARE(LT_S, i, <)
      RUNG_COMPARE(LE_S, i, <=)
      RUNG_COMPARE(GT_S, i, >)
      RUNG_COMPARE(GE_S, i, >=)
      RUNG_COMPARE(LT_U, u, <)
      RUNG_COMPARE(LE_U, u, <=)
      RUNG_COMPARE(GT_U, u, >)
      RUNG_COMPARE(GE_U, u, >=)
#undef RUNG_COMPARE
      case Op::MIN_S: sp[-2].i = std::min(sp[-2].i, sp[-1].i); --sp; NEXT();
      case Op::MAX_S: sp[-2].i = std::max(sp[-2].i, sp[-1].i); --sp; NEXT();
      case Op::MIN_U: sp[-2].u = std::min(sp[-2].u, sp[-1].u); --sp; NEXT();
      case Op::MAX_U: sp[-2].u = std::max(sp[-2].u, sp[-1].u); --sp; NEXT();

#define RUNG_FLOAT_OPS(SUFFIX, FIELD)                                                             \
  case Op::ADD_##SUFFIX: sp[-2].FIELD = sp[-2].FIELD + sp[-1].FIELD; --sp; NEXT();                \
  case Op::SUB_##SUFFIX: sp[-2].FIELD = sp[-2].FIELD - sp[-1].FIELD; --sp; NEXT();                \
  case Op::MUL_##SUFFIX: sp[-2].FIELD = sp[-2].FIELD * sp[-1].FIELD; --sp; NEXT();                \
  case Op::DIV_##SUFFIX: sp[-2].FIELD = sp[-2].FIELD / sp[-1].FIELD; --sp; NEXT();                \
  case Op::NEG_##SUFFIX: TOP().FIELD = -TOP().FIELD; NEXT();                                      \
  case Op::ABS_##SUFFIX: TOP().FIELD = std::fabs(TOP().FIELD); NEXT();                            \
  case Op::EQ_##SUFFIX: sp[-2].u = sp[-2].FIELD == sp[-1].FIELD; --sp; NEXT();                    \
  case Op::NE_##SUFFIX: sp[-2].u = sp[-2].FIELD != sp[-1].FIELD; --sp; NEXT();                    \
  case Op::LT_##SUFFIX: sp[-2].u = sp[-2].FIELD < sp[-1].FIELD; --sp; NEXT();                     \
  case Op::LE_##SUFFIX: sp[-2].u = sp[-2].FIELD <= sp[-1].FIELD; --sp; NEXT();                    \
  case Op::GT_##SUFFIX: sp[-2].u = sp[-2].FIELD > sp[-1].FIELD; --sp; NEXT();                     \
  case Op::GE_##SUFFIX: sp[-2].u = sp[-2].FIELD >= sp[-1].FIELD; --sp; NEXT();                    \
  case Op::MIN_##SUFFIX: sp[-2].FIELD = std::min(sp[-2].FIELD, sp[-1].FIELD); --sp; NEXT();       \
  case Op::MAX_##SUFFIX: sp[-2].FIELD = std::max(sp[-2].FIELD, sp[-1].FIELD); --sp; NEXT();
      RUNG_FLOAT_OPS(F32, f32)
      RUNG_FLOAT_OPS(F64, f64)
#undef RUNG_FLOAT_OPS

      case Op::S64_TO_F32: TOP().f32 = static_cast<float>(TOP().i); NEXT();
      case Op::U64_TO_F32: TOP().f32 = static_cast<float>(TOP().u); NEXT();
      case Op::S64_TO_F64: TOP().f64 = static_cast<double>(TOP().i); NEXT();
      case Op::U64_TO_F64: TOP().f64 = static_cast<double>(TOP().u); NEXT();
      case Op::F32_TO_F64: TOP().f64 = static_cast<double>(TOP().f32); NEXT();
      case Op::F64_TO_F32: TOP().f32 = static_cast<float>(TOP().f64); NEXT();
      case Op::F32_TO_S64: TOP().i = round_to_integer(TOP().f32, static_cast<RoundRule>(in.a)); NEXT();
      case Op::F64_TO_S64: TOP().i = round_to_integer(TOP().f64, static_cast<RoundRule>(in.a)); NEXT();
      case Op::F32_TO_U64: TOP().u = round_to_unsigned(TOP().f32, static_cast<RoundRule>(in.a)); NEXT();
      case Op::F64_TO_U64: TOP().u = round_to_unsigned(TOP().f64, static_cast<RoundRule>(in.a)); NEXT();

      case Op::JMP: pc = code + in.a; continue;
      case Op::JMP_BACK:
        if (--budget == 0) [[unlikely]] {
          fail(TrapKind::Watchdog,
               "watchdog: the cycle did not end (an endless loop?); raise the limit with --loop-limit if it is real work");
          return false;
        }
        pc = code + in.a;
        continue;
      case Op::JZ:
        if (POP().u == 0) {
          pc = code + in.a;
          continue;
        }
        NEXT();
      case Op::JNZ:
        if (POP().u != 0) {
          pc = code + in.a;
          continue;
        }
        NEXT();
      case Op::JZ_KEEP:
        if (TOP().u == 0) {
          pc = code + in.a;
          continue;
        }
        --sp;
        NEXT();
      case Op::JNZ_KEEP:
        if (TOP().u != 0) {
          pc = code + in.a;
          continue;
        }
        --sp;
        NEXT();

      case Op::INDEX: {
        const int64_t index = POP().i;
        const Dimension& dimension = program_.dimensions[in.a];
        if (index < dimension.lower || index > dimension.upper) [[unlikely]] {
          fail(TrapKind::IndexOutOfBounds, fmt::format("array index {} is outside {}..{}", index, dimension.lower,
                                                       dimension.upper));
          return false;
        }
        TOP().u += static_cast<uint64_t>(index - dimension.lower) * dimension.stride;
        NEXT();
      }
      case Op::BOUNDS: {
        const int64_t upper = POP().i;
        const int64_t lower = POP().i;
        const int64_t index = TOP().i;
        if (index < lower || index > upper) [[unlikely]] {
          fail(TrapKind::IndexOutOfBounds, fmt::format("array index {} is outside {}..{}", index, lower, upper));
          return false;
        }
        TOP().i = index - lower;
        NEXT();
      }
      case Op::CHECK_PTR: {
        const uint64_t address = TOP().u;
        if (!valid(address, in.a)) [[unlikely]] {
          fail(address < kNullGuard ? TrapKind::NullPointer : TrapKind::InvalidPointer, {});
          return false;
        }
        NEXT();
      }

      case Op::FRAME: {
        const Callable& callee = program_.callables[in.a];
        const uint64_t size = align8(callee.frame_size);
        if (size > stack_end_ - sp_mem || returns.size() >= kMaxCallDepth) [[unlikely]] {
          fail(TrapKind::StackOverflow, fmt::format("stack overflow calling '{}' (recursion too deep?)", callee.name));
          return false;
        }
        pending.push_back(nframe);
        nframe = sp_mem;
        if (!callee.frame_image.empty()) std::memcpy(mem + nframe, callee.frame_image.data(), callee.frame_image.size());
        sp_mem += size;
        NEXT();
      }
      case Op::CALL:
      case Op::CALL_VIRT: {
        const uint64_t this_address = POP().u;
        uint32_t target = in.a;
        if (in.op == Op::CALL_VIRT) {
          if (!valid(this_address, kInstanceHeaderBytes)) [[unlikely]] {
            fail(this_address < kNullGuard ? TrapKind::NullPointer : TrapKind::InvalidPointer,
                 this_address < kNullGuard ? "method call through a NULL interface or pointer" : "");
            return false;
          }
          const uint32_t class_id = load<uint32_t>(mem, this_address);
          target = class_id < program_.vtables.size() && in.a < program_.vtables[class_id].size()
                       ? program_.vtables[class_id][in.a]
                       : kNoCallable;
          if (target == kNoCallable) [[unlikely]] {
            fail(TrapKind::InvalidPointer, fmt::format("the object has no method '{}' (a dangling interface or pointer?)",
                                                       in.a < program_.slot_names.size() ? program_.slot_names[in.a] : "?"));
            return false;
          }
        }
        const Callable& callee = program_.callables[target];
        if (!callee.compiled) [[unlikely]] {
          fail(TrapKind::MissingImplementation,
               fmt::format("'{}' has no implementation: it is declared in a stub library without a body", callee.name));
          return false;
        }
        if (in.op == Op::CALL_VIRT) {
          // FRAME opened the declared method's frame; the implementation's locals may differ.
          const uint64_t size = align8(callee.frame_size);
          if (size > stack_end_ - nframe) [[unlikely]] {
            fail(TrapKind::StackOverflow, {});
            return false;
          }
          sp_mem = std::max(sp_mem, nframe + size);
          if (callee.frame_image.size() > callee.param_bytes) {
            std::memcpy(mem + nframe + callee.param_bytes, callee.frame_image.data() + callee.param_bytes,
                        callee.frame_image.size() - callee.param_bytes);
          }
        }
        if (callee.instance_size != 0 && !valid(this_address, callee.instance_size)) [[unlikely]] {
          fail(this_address < kNullGuard ? TrapKind::NullPointer : TrapKind::InvalidPointer, {});
          return false;
        }
        if (sp >= values_limit) [[unlikely]] {
          fail(TrapKind::StackOverflow, {});
          return false;
        }
        call_stack_.push_back(StackEntry{kNoCallable, static_cast<uint32_t>(pc - code)});
        returns.push_back(Return{pc + 1, inst, frame});
        inst = this_address;
        frame = nframe;
        nframe = pending.back();
        pending.pop_back();
        pc = code + callee.code_begin;
        continue;
      }
      case Op::NATIVE: {
        sp_ = sp;
        current_pc_ = static_cast<uint32_t>(pc - code);
        program_.natives[in.a](*this, in);
        if (error_) [[unlikely]] return false;
        sp = sp_;
        NEXT();
      }
      case Op::RET: {
        sp_mem = frame;
        rframe = frame;
        if (returns.empty()) {
          sp_ = sp;
          return true;
        }
        const Return back = returns.back();
        returns.pop_back();
        call_stack_.pop_back();
        pc = back.pc;
        inst = back.inst;
        frame = back.frame;
        continue;
      }
      case Op::TRAP: {
        fail(static_cast<TrapKind>(in.a), in.b >= 0 && static_cast<size_t>(in.b) < program_.messages.size()
                                                ? program_.messages[static_cast<size_t>(in.b)]
                                                : std::string());
        return false;
      }
      case Op::HALT:
      case Op::kCount:
        fail(TrapKind::Unsupported, "internal error: the program ran past its end");
        return false;
    }
  }
#undef POP
#undef TOP
#undef NEXT
}

}  // namespace rung::run
