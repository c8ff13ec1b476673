#include "runner/vm/disassemble.hpp"

#include <fmt/format.h>

namespace rung::run {

std::string disassemble(const Program& program) {
  std::string out;
  for (size_t index = 0; index < program.callables.size(); ++index) {
    const Callable& callable = program.callables[index];
    out += fmt::format("callable {} '{}' frame {} bytes, instance {} bytes{}\n", index, callable.name,
                       callable.frame_size, callable.instance_size, callable.compiled ? "" : " (no code)");
    if (!callable.compiled) continue;
    for (uint32_t pc = callable.code_begin; pc < callable.code_end; ++pc) {
      const Instr& instr = program.code[pc];
      std::string operands;
      switch (instr.op) {
        case Op::PUSH: operands = fmt::format("{}", instr.b); break;
        case Op::FRAME:
        case Op::CALL:
          operands = fmt::format("{} ({})", instr.a,
                                 instr.a < program.callables.size() ? program.callables[instr.a].name : "?");
          break;
        case Op::CALL_VIRT:
          operands = fmt::format("slot {} ({})", instr.a,
                                 instr.a < program.slot_names.size() ? program.slot_names[instr.a] : "?");
          break;
        case Op::NATIVE:
          operands = fmt::format("{}", instr.a < program.native_names.size() ? program.native_names[instr.a] : "?");
          break;
        default: operands = fmt::format("{}", instr.a); break;
      }
      if (instr.aux != 0) operands += fmt::format(" aux {}", instr.aux);
      out += fmt::format("  {:6}  {:<10} {}\n", pc, op_name(instr.op), operands);
    }
  }
  return out;
}

}  // namespace rung::run
