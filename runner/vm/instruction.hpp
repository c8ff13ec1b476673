// The runner's intermediate form: typed instructions with precomputed offsets, executed by the
// interpreter in machine.cpp over one flat, byte-addressed memory image.
//
// The value stack holds 64-bit slots. Integers of every width travel sign- or zero-extended to 64
// bits (the compiler inserts WRAP_* where the IEC type's width must cut), REAL travels as a float,
// LREAL as a double, and strings, structures, arrays and FB instances travel as their address.
//
// Addressing modes, in the opcode's suffix:
//   G  absolute (globals, program instances, constants)      a = address
//   I  relative to the running POU's instance (THIS)         a = offset
//   F  relative to the running call's frame (locals, temps)  a = offset
//   P  through an address popped from the stack (checked against the memory bounds)
#pragma once

#include <cstdint>
#include <string_view>

namespace rung::run {

#define RUNG_LOAD_KINDS(X) X(U8) X(S8) X(U16) X(S16) X(U32) X(S32) X(I64) X(F32) X(F64)
#define RUNG_STORE_KINDS(X) X(8) X(16) X(32) X(64) X(F32) X(F64)

// clang-format off
#define RUNG_OPCODES(X)                                                                                 \
  /* constants and addresses */                                                                        \
  X(PUSH) X(PUSH_F32) X(PUSH_F64) X(ADDR_G) X(ADDR_I) X(ADDR_F) X(ADDR_R)                              \
  X(DUP) X(POP) X(SWAP) X(OVER)                                                                        \
  /* loads: LD_<kind>_<mode> */                                                                        \
  X(LD_U8_G) X(LD_S8_G) X(LD_U16_G) X(LD_S16_G) X(LD_U32_G) X(LD_S32_G) X(LD_I64_G) X(LD_F32_G) X(LD_F64_G) \
  X(LD_U8_I) X(LD_S8_I) X(LD_U16_I) X(LD_S16_I) X(LD_U32_I) X(LD_S32_I) X(LD_I64_I) X(LD_F32_I) X(LD_F64_I) \
  X(LD_U8_F) X(LD_S8_F) X(LD_U16_F) X(LD_S16_F) X(LD_U32_F) X(LD_S32_F) X(LD_I64_F) X(LD_F32_F) X(LD_F64_F) \
  X(LD_U8_P) X(LD_S8_P) X(LD_U16_P) X(LD_S16_P) X(LD_U32_P) X(LD_S32_P) X(LD_I64_P) X(LD_F32_P) X(LD_F64_P) \
  /* stores: ST_<kind>_<mode>; P pops the value, then the address */                                  \
  X(ST_8_G) X(ST_16_G) X(ST_32_G) X(ST_64_G) X(ST_F32_G) X(ST_F64_G)                                    \
  X(ST_8_I) X(ST_16_I) X(ST_32_I) X(ST_64_I) X(ST_F32_I) X(ST_F64_I)                                    \
  X(ST_8_F) X(ST_16_F) X(ST_32_F) X(ST_64_F) X(ST_F32_F) X(ST_F64_F)                                    \
  X(ST_8_P) X(ST_16_P) X(ST_32_P) X(ST_64_P) X(ST_F32_P) X(ST_F64_P)                                    \
  /* bits of a word: BIT_GET a=bit; BIT_SET a=bit pops value and word, pushes the new word */          \
  X(BIT_GET) X(BIT_SET)                                                                                \
  /* memory blocks: COPY a=bytes (pops src, dst); STR_COPY a=capacity in characters (pops src, dst),   \
     WSTR_COPY the same for WSTRING; ZERO a=bytes (pops dst) */                                        \
  X(COPY) X(STR_COPY) X(WSTR_COPY) X(ZERO)                                                             \
  /* integer arithmetic on 64-bit slots */                                                             \
  X(ADD) X(SUB) X(MUL) X(DIV_S) X(DIV_U) X(MOD_S) X(MOD_U) X(NEG) X(ABS_S)                              \
  X(AND) X(OR) X(XOR) X(NOT) X(BNOT) X(SHL) X(SHR) X(ROL) X(ROR) X(EXPT_I)                              \
  X(WRAP_S8) X(WRAP_U8) X(WRAP_S16) X(WRAP_U16) X(WRAP_S32) X(WRAP_U32) X(TO_BOOL)                      \
  X(EQ) X(NE) X(LT_S) X(LE_S) X(GT_S) X(GE_S) X(LT_U) X(LE_U) X(GT_U) X(GE_U)                           \
  X(MIN_S) X(MAX_S) X(MIN_U) X(MAX_U)                                                                  \
  /* REAL (F32) and LREAL (F64) */                                                                     \
  X(ADD_F32) X(SUB_F32) X(MUL_F32) X(DIV_F32) X(NEG_F32) X(ABS_F32)                                     \
  X(EQ_F32) X(NE_F32) X(LT_F32) X(LE_F32) X(GT_F32) X(GE_F32) X(MIN_F32) X(MAX_F32)                     \
  X(ADD_F64) X(SUB_F64) X(MUL_F64) X(DIV_F64) X(NEG_F64) X(ABS_F64)                                     \
  X(EQ_F64) X(NE_F64) X(LT_F64) X(LE_F64) X(GT_F64) X(GE_F64) X(MIN_F64) X(MAX_F64)                     \
  /* conversions; a = rounding rule for float to integer (RoundRule) */                                \
  X(S64_TO_F32) X(U64_TO_F32) X(S64_TO_F64) X(U64_TO_F64) X(F32_TO_F64) X(F64_TO_F32)                   \
  X(F32_TO_S64) X(F64_TO_S64) X(F32_TO_U64) X(F64_TO_U64)                                              \
  /* control flow: a = target instruction */                                                           \
  X(JMP) X(JMP_BACK) X(JZ) X(JNZ) X(JZ_KEEP) X(JNZ_KEEP)                                               \
  /* arrays: INDEX a = dimension table entry; pops index and base address, pushes element address;   \
     BOUNDS (ARRAY[*]: bounds known at run time) pops upper and lower, checks the index below them,    \
     replaces it by index - lower */                                                                   \
  X(INDEX) X(BOUNDS) X(CHECK_PTR)                                                                      \
  /* calls: FRAME a = callable (opens its frame, initialised); ADDR_N a = offset in that new frame;   \
     CALL a = callable (pops the instance address, 0 for functions); CALL_VIRT a = method slot;       \
     NATIVE a = built-in; RET */                                                                       \
  X(FRAME) X(ADDR_N) X(CALL) X(CALL_VIRT) X(NATIVE) X(RET)                                             \
  X(TRAP)                                                                                              \
  X(HALT)
// clang-format on

enum class Op : uint16_t {
#define RUNG_OPCODE_ENUM(name) name,
  RUNG_OPCODES(RUNG_OPCODE_ENUM)
#undef RUNG_OPCODE_ENUM
      kCount
};

std::string_view op_name(Op op);

// How a float becomes an integer (profile: REAL_TO_INT on .5 ties).
enum class RoundRule : uint32_t {
  HalfAwayFromZero,  // CODESYS, TwinCAT, IEC: 2.5 -> 3, -2.5 -> -3
  HalfToEven,        // banker's rounding: 2.5 -> 2, 3.5 -> 4
  Truncate,          // TRUNC: toward zero
};

// What a TRAP reports.
enum class TrapKind : uint32_t {
  DivisionByZero,
  IndexOutOfBounds,
  NullPointer,
  InvalidPointer,
  StackOverflow,
  Watchdog,
  OutOfMemory,
  MissingImplementation,
  AbstractCall,
  Unsupported,
};

struct Instr {
  Op op = Op::HALT;
  uint16_t aux = 0;  // a second small operand (bit width of ROL/ROR, ...)
  uint32_t a = 0;    // offset, address, target, callable, table entry
  int64_t b = 0;     // an immediate value
};
static_assert(sizeof(Instr) == 16);

}  // namespace rung::run
