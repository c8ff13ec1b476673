// Where every variable lives in the PLC's memory: sizes and alignments of types, offsets of struct
// fields and of FB/program instance variables, the frames of functions and methods. The rules are
// CODESYS's on 64-bit targets (pack mode 8): each member at its natural alignment, the whole padded
// to its largest member, a BOOL takes a byte, pointers and references 8 bytes, and every FB or
// class instance starts with an 8-byte header (CODESYS's virtual function table pointer).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "checker/project_model.hpp"
#include "runner/vm/instruction.hpp"

namespace rung::run {

struct TypeLayout {
  uint64_t size = 0;
  uint64_t alignment = 1;
};

// How a value of a type travels on the value stack.
enum class Scalar : uint8_t { None, U8, S8, U16, S16, U32, S32, I64, U64, F32, F64 };

// The state an SFC body keeps in its POU's instance, after the POU's variables (compile_sfc.cpp
// reads and writes it): an 8-byte header (byte 0: the chart has started), then per step 16 bytes
// (X, two bytes for the transitions' bookkeeping, T as a TIME at +4, the activation time in ns at
// +8), then per associated action or BOOL variable 96 bytes (its action control state).
struct SfcLayout {
  static constexpr uint64_t kHeaderBytes = 8;
  static constexpr uint64_t kStepBytes = 16;
  static constexpr uint64_t kActionBytes = 96;
  uint64_t offset = 0;               // in the instance
  std::vector<std::string> steps;    // upper-case names, in source order
  std::vector<bool> initial;         // parallel to steps
  std::vector<std::string> actions;  // upper-case names, in the order associations first name them
  uint64_t step_offset(size_t step) const { return offset + kHeaderBytes + kStepBytes * step; }
  uint64_t action_offset(size_t action) const {
    return offset + kHeaderBytes + kStepBytes * steps.size() + kActionBytes * action;
  }
  uint64_t size() const { return kHeaderBytes + kStepBytes * steps.size() + kActionBytes * actions.size(); }
  // The index of a step or action by name; -1 when there is none.
  int step_index(std::string_view name) const;
  int action_index(std::string_view name) const;
};

// A POU's storage: its instance (FB, program, class) and its frame (one call's locals).
struct PouLayout {
  uint64_t instance_size = 0;
  uint64_t instance_alignment = 8;
  uint64_t frame_size = 0;
  std::vector<const check::Symbol*> instance_variables;  // own and inherited, in memory order
  std::vector<const check::Symbol*> frame_variables;     // parameters, locals, temps, the result
  uint64_t result_offset = 0;                            // in the frame (functions, methods, GET)
  uint64_t param_bytes = 0;  // the result and parameters come first: the same offsets in overrides
  std::optional<SfcLayout> sfc;  // a PROGRAM's or FUNCTION_BLOCK's SFC body: its state at the instance's end
};

class Layouts {
 public:
  explicit Layouts(const check::ProjectModel& model) : model_(model) {}

  TypeLayout of(const check::Type* type);
  // The POU's instance and frame. `pou` is a FUNCTION, FUNCTION_BLOCK, PROGRAM, CLASS, METHOD,
  // ACTION or property accessor; methods and accessors have a frame only.
  const PouLayout& pou(const check::Symbol* pou);
  // The offset of a struct field or instance variable in its owner, or of a frame variable in its
  // frame. Only valid after the owner's layout was asked for (of() / pou()).
  uint64_t offset(const check::Symbol* variable) const;
  bool has_offset(const check::Symbol* variable) const { return offsets_.contains(variable); }

  const check::ProjectModel& model() const { return model_; }

  // Types after aliases, subranges and enums: what a value is made of.
  static const check::Type* storage_type(const check::Type* type);
  static Scalar scalar_of(const check::Type* type);
  // Whether a variable is stored as an address of its value (VAR_IN_OUT, REFERENCE TO).
  static bool held_by_reference(const check::Symbol* variable);
  // ARRAY[*] parameters: the number of dimensions whose bounds come with the argument. Their slot
  // holds the address, then per dimension its lower and upper bound (LINT each):
  // kOpenBoundsOffset + 16 * d (lower) and + 8 (upper).
  static size_t open_dimensions(const check::Symbol* variable);
  static constexpr uint64_t kOpenBoundsOffset = 8;
  // Variables kept in an instance (not VAR_TEMP, VAR_STAT, VAR_EXTERNAL, VAR_GLOBAL).
  static bool in_instance(const check::Symbol* variable);
  static bool has_instance_header(const check::Symbol* pou);
  // A function's, method's or property accessor's result type; nullptr when it has none.
  static const check::Type* result_type(const check::Symbol* pou);
  // The size of the largest elementary type inside `type` (CheckPointer's iGran).
  uint64_t granularity(const check::Type* type, int depth = 0);

 private:
  TypeLayout compute(const check::Type* type, int depth);
  TypeLayout struct_layout(const check::Symbol* declaration, bool is_union, int depth);
  TypeLayout variable_layout(const check::Symbol* variable, int depth);

  const check::ProjectModel& model_;
  std::unordered_map<const check::Type*, TypeLayout> types_;
  std::unordered_map<const check::Symbol*, PouLayout> pous_;
  std::unordered_map<const check::Symbol*, uint64_t> offsets_;
};

}  // namespace rung::run
