// A compiled project: every callable's code in one instruction array, the initial memory image,
// and the tables the interpreter and the reports need. Built by runner/compile, executed by
// Machine; read-only while it runs, so one Program serves many machines (rung test runs each test
// on a fresh machine of the same program).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "checker/symbols/symbol.hpp"
#include "runner/vm/instruction.hpp"

namespace rung::run {

class Machine;
// A built-in implemented in C++ (string functions, numeric functions, ...): pops its arguments from
// the machine's value stack and pushes its result. `instr` is the NATIVE instruction (its b and
// aux carry per-call data such as a capacity).
using NativeFn = void (*)(Machine& machine, const Instr& instr);

constexpr uint32_t kNoCallable = UINT32_MAX;
// Addresses 0 .. kNullGuard-1 are never valid, so a NULL pointer and small garbage fault.
constexpr uint64_t kNullGuard = 64;
// Every FB/class instance starts with a header holding its class id (what dynamic dispatch reads),
// the place CODESYS keeps its virtual function table pointer.
constexpr uint32_t kInstanceHeaderBytes = 8;

// Init: a program's or global list's start (computed initial values, FB instances built);
// Construct: one FB instance built (at THIS); Exit and Destruct: the same for FB_exit at the end.
enum class CallableKind : uint8_t {
  Program,
  Function,
  FunctionBlock,
  Method,
  Action,
  PropertyGet,
  PropertySet,
  Init,
  Construct,
  Exit,
  Destruct
};

struct Callable {
  std::string name;  // FB_Motor.Start, TON, PLC_PRG
  CallableKind kind = CallableKind::Function;
  check::SourceId source = check::kNoSource;
  const check::Symbol* symbol = nullptr;
  uint32_t code_begin = 0;
  uint32_t code_end = 0;
  uint32_t frame_size = 0;              // locals, parameters, temps, the result; 8-aligned
  std::vector<uint8_t> frame_image;     // the frame's initial bytes (initial values)
  uint32_t param_bytes = 0;             // the result and parameters at the frame's start
  uint32_t instance_size = 0;           // bytes of THIS the body may touch (checked on CALL)
  bool compiled = false;                // a body exists (a declaration-only stub has none)
};

// One array dimension as INDEX checks it.
struct Dimension {
  int64_t lower = 0;
  int64_t upper = 0;
  uint64_t stride = 0;  // bytes per index step
};

class Program {
 public:
  std::vector<Instr> code;
  std::vector<uint32_t> positions;  // parallel to code: the byte offset in the callable's source tree
  std::vector<Callable> callables;
  std::vector<Dimension> dimensions;
  std::vector<NativeFn> natives;
  std::vector<std::string> native_names;
  // vtables[class id][method slot] = callable (kNoCallable when the class has no such method).
  std::vector<std::vector<uint32_t>> vtables;
  std::vector<std::string> class_names;
  std::vector<std::string> slot_names;
  std::vector<std::string> messages;  // TRAP texts (b = index)

  std::vector<uint8_t> image;  // globals, program instances and constants at their addresses
  uint64_t stack_bytes = 1u << 20;  // call frames
  uint64_t heap_bytes = 1u << 20;   // __NEW

  // Run once before the first cycle, in this order (global lists first): the initial values that
  // are not constants (`p : POINTER TO INT := ADR(x)`), each with THIS = `instance`.
  struct InitCall {
    uint32_t callable = kNoCallable;
    uint64_t instance = 0;
  };
  std::vector<InitCall> init_calls;
  // Run once when the run ends (Engine::finish), programs in reverse order, then global lists:
  // FB_exit of their instances.
  std::vector<InitCall> exit_calls;

  // The callable whose code holds instruction `pc`.
  const Callable* callable_at(uint32_t pc) const;
};

}  // namespace rung::run
