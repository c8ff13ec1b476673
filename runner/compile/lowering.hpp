// Internals of runner/compile: the project-wide state of one compilation (Lowering) and the
// compiler of one callable's body (BodyCompiler, split over compile_*.cpp by concern).
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "checker/semantic/body_checker.hpp"
#include "runner/compile/compile.hpp"
#include "runner/compile/layout.hpp"
#include "runner/stdlib/datetime.hpp"
#include "runner/vm/program.hpp"

namespace rung::run {

using check::ExprInfo;
using check::Symbol;
using check::SymbolKind;
using check::Type;
using check::TypeKind;

inline Scalar scalar_kind(const Type* type) { return Layouts::scalar_of(type); }

// How a TIME, DATE, TOD or DT type counts (milliseconds, seconds, nanoseconds).
TimeUnit time_unit_of(const Type* type);

// A POU's name with its owners' (FB_Motor.Start): how callables are named in errors and dumps.
std::string qualified_name(const Symbol* pou);

// Where a variable lives, as a body sees it.
struct Storage {
  enum class Kind : uint8_t { Global, Instance, Frame, None };
  Kind kind = Kind::None;
  uint64_t offset = 0;
  int bit = -1;  // a BOOL at a bit address (AT %IX0.3)
};

// Where a direct address (%IX0.3, %MW4, %QD1) lives in the process image: its byte address and,
// for bit addresses, the bit; nullopt with `error` set when it cannot be placed.
struct ImageAddress {
  uint64_t address = 0;
  int bit = -1;
  const Type* type = nullptr;  // BOOL, BYTE, WORD, DWORD or LWORD by the size letter
};

class Lowering {
 public:
  Lowering(const check::ProjectModel& model, Program& program, Layouts& layouts);

  const check::ProjectModel& model() const { return model_; }
  const check::Profile& profile() const { return model_.profile(); }
  Program& program() { return program_; }
  Layouts& layouts() { return layouts_; }

  // The callable of a POU (compiled later, from the queue). Interfaces' and stubs' methods get a
  // callable without code, for their frame layout.
  uint32_t callable_for(const Symbol* pou);
  // Compiles every queued callable (the queue grows while it runs).
  void compile_queue();

  // A global variable's, VAR_STAT's or program instance's address (allocated and initialised on
  // first use).
  uint64_t global_address(const Symbol* variable);
  uint64_t program_instance(const Symbol* program);
  // The process image (%I, %Q and %M areas, kImageAreaBytes each) holds located variables.
  static constexpr uint64_t kImageAreaBytes = 65536;
  std::optional<ImageAddress> image_address(std::string_view text, std::string* error);
  // Where `variable` lives for code running in `callable_pou`.
  Storage storage_of(const Symbol* variable, const Symbol* callable_pou);

  // Class ids (instance headers) and method slots for dynamic dispatch.
  uint32_t class_id(const Symbol* pou);
  uint32_t method_slot(std::string_view name);
  void build_vtables();

  // Constant data in the image (string literals).
  uint64_t constant_bytes(const std::string& bytes, uint64_t alignment);
  uint32_t dimension(const check::ArrayDimension& dimension, uint64_t stride);
  uint32_t native(NativeFn function, std::string_view name);
  uint32_t message(std::string text);

  // Initial values (compile_init.cpp): writes a variable's initial bytes at `at` of `bytes`.
  void write_variable_initial(std::vector<uint8_t>& bytes, uint64_t at, const Symbol* variable);
  void write_default(std::vector<uint8_t>& bytes, uint64_t at, const Type* type, int depth = 0);
  void write_initializer(std::vector<uint8_t>& bytes, uint64_t at, const Type* type, SyntaxNode value,
                         const Symbol* scope, int depth = 0);
  void write_constant(std::vector<uint8_t>& bytes, uint64_t at, const Type* type, const check::ConstValue& value);
  void write_instance(std::vector<uint8_t>& bytes, uint64_t at, const Symbol* pou, int depth);

  // The init callable of a program or global list (kNoCallable when it needs none); each call
  // adds a run of it with THIS = `instance` to the program's start.
  uint32_t init_callable(const Symbol* owner, uint64_t instance);
  // Whether `variable`'s initial value is computed in code (not a constant).
  bool computed_initial(const Symbol* variable) const;

  // FB instances' life cycle (compile_lifecycle.cpp). An instance of `block` needs code when it is
  // created if a variable of it (or of its base) has a computed initial value or is an instance
  // that needs code, or when the block or a base has FB_init; when it is removed if FB_exit is
  // declared in it, a base or a member instance.
  bool needs_construction(const Symbol* block);
  bool needs_init(const Symbol* block);
  // Whether the FB instance (or array of instances) `variable` declares needs code when created:
  // its block does, or the declaration gives arguments (`t : TON(PT := T#1S)`).
  bool instance_needs_init(const Symbol* variable);
  bool needs_exit(const Symbol* block);
  // The callable that builds one instance of `block` at THIS: its base's part, its member
  // instances (each built, then its FB_init), its computed initial values. kNoCallable if none.
  uint32_t constructor_for(const Symbol* block);
  // The callable that calls FB_exit on one instance of `block` at THIS and on its members.
  uint32_t destructor_for(const Symbol* block);
  // The exit callable of a program or global list (FB_exit of its instances), run when the run
  // ends (Program::exit_calls).
  void exit_callable(const Symbol* owner, uint64_t instance);
  // A POU's own FB_init / FB_exit method (not inherited); nullptr when it declares none.
  const Symbol* own_method(const Symbol* block, std::string_view name) const;
  // The function block type `variable` holds (directly or as array elements); nullptr otherwise.
  const Symbol* instance_block(const Symbol* variable) const;

  void error(const Symbol* where, SyntaxNode node, std::string message);
  std::vector<CompileError>& errors() { return errors_; }

  std::vector<GlobalList> global_lists();

 private:
  uint64_t allocate(uint64_t size, uint64_t alignment);

  const check::ProjectModel& model_;
  Program& program_;
  Layouts& layouts_;
  std::unordered_map<const Symbol*, uint32_t> callables_;
  std::vector<uint32_t> queue_;
  size_t queue_next_ = 0;
  std::unordered_map<const Symbol*, uint64_t> globals_;
  std::vector<const Symbol*> global_order_;
  std::unordered_map<const Symbol*, uint32_t> class_ids_;
  std::vector<const Symbol*> classes_;
  std::unordered_map<std::string, uint32_t> slots_;
  std::unordered_map<std::string, uint32_t> natives_;
  std::unordered_map<std::string, uint64_t> constants_;
  std::vector<CompileError> errors_;
  uint64_t image_areas_ = 0;  // %I area; %Q and %M follow
  std::unordered_map<const Symbol*, uint32_t> init_callables_;
  std::unordered_map<const Symbol*, uint32_t> exit_callables_;
  std::unordered_map<const Symbol*, uint32_t> constructors_;
  std::unordered_map<const Symbol*, uint32_t> destructors_;
  std::unordered_map<const Symbol*, bool> needs_construction_;
  std::unordered_map<const Symbol*, bool> needs_exit_;
};

// A place in memory an expression names; Pointer means its address is on the value stack (plus
// `offset`).
struct Place {
  enum class Mode : uint8_t { Global, Instance, Frame, Pointer };
  Mode mode = Mode::Global;
  uint64_t offset = 0;
  const Type* type = nullptr;
  int bit = -1;  // x.3
  const Symbol* symbol = nullptr;
};

class BodyCompiler {
 public:
  BodyCompiler(Lowering& lowering, uint32_t callable_index);
  void compile();
  // Stores one variable's computed initial value (Lowering::computed_initial).
  void runtime_initial_value(const Symbol* variable);
  // Init and construct callables, and the start of every call (compile_lifecycle.cpp): the
  // computed initial values and FB instances of `owner`'s variables, in declaration order; those
  // kept in the instance or globally (`per_call` false) or those in the call's frame (true).
  void initialize_variables(const Symbol* owner, bool per_call);
  // One FB instance at the address `push_address` pushes: built, then its FB_init (base first)
  // with `arguments` (the declaration's `fb : FB_X(a := 1)`; an FB without FB_init takes them
  // as input values).
  void construct_instance(const Symbol* block, const std::function<void()>& push_address, SyntaxNode arguments);
  // FB_exit of one instance (derived first), then its members'.
  void destruct_instance(const Symbol* block, const std::function<void()>& push_address);

  // --- emission --------------------------------------------------------------------------------
  uint32_t emit(Op op, uint32_t a = 0, int64_t b = 0, uint16_t aux = 0);
  uint32_t here() const;
  void patch(uint32_t at, uint32_t target);
  void set_position(SyntaxNode node) { position_ = node ? node.begin() : position_; }

  // --- expressions (compile_expr.cpp) -----------------------------------------------------------
  // Pushes the value of `node` converted to `target` (nullptr: its own type); returns the type of
  // what was pushed. Aggregates (strings, structs, arrays, instances) push their address.
  const Type* value(SyntaxNode node, const Type* target = nullptr);
  void value_as_bool(SyntaxNode node) { value(node, bool_type()); }
  // The place `node` names (a variable, member, element, dereference); nullopt if it names none.
  std::optional<Place> place(SyntaxNode node);
  Place variable_place(const Symbol* variable);
  // The variable's own storage: for a VAR_IN_OUT or REFERENCE, the slot holding the address (and,
  // for ARRAY[*], the bounds), not the value it refers to.
  Place slot_place(const Symbol* variable);
  // Pushes (as LINT) the lower or upper bound of dimension `dimension` (from 0) of the array
  // `array` names: a constant for a fixed array, read from the slot for an ARRAY[*] parameter.
  // False when `array` is not an array or its bounds cannot be found.
  bool push_bound(SyntaxNode array, size_t dimension, bool upper);
  void load(const Place& place);
  void address_of(const Place& place);  // pushes the address (Pointer: the offset added)
  // Stores the value on top of the stack (pushed after the place's address, for Pointer places).
  void store(const Place& place, const Type* value_type);
  // Converts the value on top from `from` to `to`.
  void convert(const Type* from, const Type* to);
  void push_constant(const check::ConstValue& value, const Type* type);
  // Reserves a fresh temporary of `type` in the frame; returns its frame offset.
  uint64_t temporary(const Type* type);

  // --- statements (compile_stmt.cpp) ------------------------------------------------------------
  void statement_list(SyntaxNode list);
  void statement(SyntaxNode statement);
  void assignment(SyntaxNode left, SyntaxNode right, std::string_view op);
  // obj.Prop := value: calls the property's SET accessor.
  void property_write(SyntaxNode target, const Symbol* property, SyntaxNode value);

  // --- calls (compile_call.cpp) -----------------------------------------------------------------
  // Compiles a call; pushes the result (if `want_result`) and returns its type (void: none).
  const Type* call(SyntaxNode call, bool want_result);

  // --- built-ins (compile_builtin.cpp) ----------------------------------------------------------
  // Standard functions and operators compiled inline or to natives; nullopt if `name` is none.
  std::optional<const Type*> builtin_call(std::string_view name, SyntaxNode call, const Symbol* callee,
                                          const std::vector<check::CallArgument>& arguments,
                                          const ExprInfo& call_info);

  ExprInfo info(SyntaxNode node) { return checker_.type_of(node); }
  const Type* bool_type() const;
  bool inside_accessor_of(const Symbol* property) const;
  const Type* elementary(std::string_view name) const;
  void fail(SyntaxNode node, std::string message);
  Lowering& lowering() { return lowering_; }
  const Symbol* pou() const { return pou_; }

 private:
  // compile_expr.cpp
  const Type* binary(SyntaxNode node, const ExprInfo& info);
  const Type* unary(SyntaxNode node, const ExprInfo& info);
  const Type* comparison(std::string_view op, SyntaxNode left, SyntaxNode right);
  const Type* arithmetic_type(const Type* type) const;
  std::optional<Place> identifier_place(SyntaxNode node, const ExprInfo& info);
  std::optional<Place> member_place(SyntaxNode node, const ExprInfo& info);
  std::optional<Place> index_place(SyntaxNode node);
  std::optional<Place> deref_place(SyntaxNode node, const ExprInfo& info);
  // For a Place that is not already a pointer: turns it into a Pointer place (address pushed).
  Place as_pointer(const Place& place);

  // Ends the callable's code with RET and records its extent, frame size and initial frame.
  void finish_callable(uint32_t begin, std::vector<uint8_t> frame_image);
  // compile_lifecycle.cpp: the code of Init, Construct, Exit and Destruct callables.
  void compile_lifecycle();
  void exit_members(const Symbol* owner);

  // compile_il.cpp, compile_sfc.cpp
  void il_body(SyntaxNode body);
  void sfc_body(SyntaxNode body);

  // compile_stmt.cpp
  void if_statement(SyntaxNode node);
  void case_statement(SyntaxNode node);
  void for_statement(SyntaxNode node);
  void while_statement(SyntaxNode node);
  void repeat_statement(SyntaxNode node);

  // compile_call.cpp
  const Type* function_call(const Symbol* callee, const std::vector<check::CallArgument>& arguments,
                            bool want_result, SyntaxNode call);
  const Type* instance_call(const Symbol* pou_type, const Place& instance, const Symbol* body,
                            const std::vector<check::CallArgument>& arguments, SyntaxNode call);
  const Type* method_call(const Symbol* method, std::optional<Place> object, bool virtual_call,
                          const std::vector<check::CallArgument>& arguments, bool want_result, SyntaxNode call);
  // The object of `obj.Prop` (nullopt for THIS, SUPER or a bare Prop); `found` false after an error.
  std::optional<Place> property_object(SyntaxNode access, bool* super, bool* found);
  // compile_checks.cpp: the project's implicit check function `name`, if this body calls it.
  const Symbol* check_function(std::string_view name) const;
  // Passes the value on top through `function` (with constant extra arguments), leaving its result.
  void call_check(const Symbol* function, const Type* value_type, const std::vector<int64_t>& extra);
  // The same with extra arguments computed at run time: each function pushes one LINT.
  void call_check_computed(const Symbol* function, const Type* value_type,
                           const std::vector<std::function<void()>>& extra);
  // CheckRangeSigned/CheckRangeUnsigned on the value on top, when `target` is a subrange type and
  // the project declares the check.
  void range_check(const Type* target);
  // ARRAY[*] in-outs: after the address, the argument's bounds into the slot's bounds; `bound_slot`
  // returns the Place of one bound (its offset in the slot given) ready for store().
  void bind_open_bounds(SyntaxNode argument, const Symbol* parameter,
                        const std::function<Place(uint64_t offset)>& bound_slot);
  // Pushes the address a VAR_IN_OUT parameter receives for `argument`.
  void in_out_address(SyntaxNode argument, const Symbol* parameter);
  void bind_frame_arguments(const Symbol* callee, const std::vector<check::CallArgument>& arguments);
  void copy_outputs(const Symbol* callee, const std::vector<check::CallArgument>& arguments, bool from_frame,
                    const std::optional<Place>& instance);
  const Type* take_result(const Symbol* callee, bool want_result);

  // --- IL and SFC (compile_il.cpp, compile_sfc.cpp) ------------------------------------------
  // IL's current result (CR): one value-stack slot kept in a frame temporary, its type known here.
  struct IlResult {
    uint64_t slot = 0;
    const Type* type = nullptr;  // what the slot holds
    ExprInfo info;               // the checker's view of it (for the next operator's typing)
    SyntaxNode loaded;           // the operand of the LD that set it, while nothing changed it since
  };
  // An operand of an IL operator: a syntax node, or the result of parentheses (a slot).
  struct IlOperand {
    SyntaxNode node;
    const IlResult* inner = nullptr;
    bool negate = false;
  };
  void il_sequence(SyntaxNode parent);
  void il_instruction(SyntaxNode instruction);
  void il_deferred(SyntaxNode instruction, std::string_view name);
  void il_load(SyntaxNode operand, bool negate);
  void il_combine(std::string_view name, const ExprInfo& operand_info, const IlOperand& operand, SyntaxNode where);
  void il_push_operand(const IlOperand& operand, const Type* target);
  void il_store(SyntaxNode operand, bool negate, int set_value);
  bool il_fb_input(std::string_view name, SyntaxNode operand);
  void il_call(SyntaxNode operand);
  void il_function(SyntaxNode instruction, SyntaxNode op_node);
  void il_set(const Type* type, const ExprInfo& info);
  void il_negate(const Type* type);
  // IL's CR where a function call takes it as first argument (the operator node), SFC's step.X and
  // step.T: places that no declaration names (called first by place()).
  std::optional<Place> special_place(SyntaxNode node);
  // The SFC layout that `step.X` in this body refers to (the POU's or, in an action, its owner's).
  const SfcLayout* sfc_layout_here();
  void sfc_step_macro(SyntaxNode macro);
  IlResult il_;
  SyntaxNode il_first_argument_;
  // --- end of IL and SFC -----------------------------------------------------------------------

  Lowering& lowering_;
  uint32_t callable_index_;
  const Symbol* pou_;
  std::vector<Diagnostic> checker_output_;
  check::BodyChecker checker_;
  uint32_t position_ = 0;
  uint64_t frame_size_ = 0;
  struct Loop {
    std::vector<uint32_t> exits;
    std::vector<uint32_t> continues;
  };
  std::vector<Loop> loops_;
  std::vector<uint32_t> returns_;
  std::unordered_map<std::string, uint32_t> labels_;
  std::vector<std::pair<uint32_t, std::string>> jumps_;
  int depth_ = 0;
  bool writing_ = false;  // compiling an assignment's target (CheckPointer's bWrite)
};

}  // namespace rung::run
