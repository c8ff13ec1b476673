// The usage rules: unused variables, parameters, POUs and types (L070-L073), shadowing (L074),
// reads before writes (L075), outputs and in-outs never written (L076, L078), values written but
// never read (L077) and functions that write globals (L079). All but L074 read one analysis of
// where each name is read and written (usage_analysis.hpp), built once per file and lint run.
#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <set>

#include "checker/lint/rule_groups.hpp"
#include "checker/lint/usage_flow.hpp"
#include "checker/lint/usage_project.hpp"
#include "checker/semantic/builtins.hpp"

namespace rung::lint {
namespace {

using ast::VarSection;
using check::Symbol;
using check::SymbolKind;

std::string_view pou_word(const Symbol& pou) {
  switch (pou.kind) {
    case SymbolKind::Program: return "PROGRAM";
    case SymbolKind::Function: return "FUNCTION";
    case SymbolKind::FunctionBlock: return "FUNCTION_BLOCK";
    case SymbolKind::Class: return "CLASS";
    case SymbolKind::Method: return "METHOD";
    case SymbolKind::Action: return "ACTION";
    case SymbolKind::Property: return "PROPERTY";
    case SymbolKind::Transition: return "TRANSITION";
    case SymbolKind::Interface: return "INTERFACE";
    case SymbolKind::DataType: return "TYPE";
    default: return "POU";
  }
}

// The variables `pou` declares itself (its members' are theirs), in declaration order.
template <typename Visit>
void for_each_variable(const Symbol& pou, Visit&& visit) {
  for (const Symbol* member : pou.ordered) {
    if (member->kind == SymbolKind::Variable && !member->name.empty()) visit(*member);
  }
}

// FUNCTION and METHOD variables start from their declared value on every call.
bool is_temporary_pou(const Symbol& pou) {
  return pou.kind == SymbolKind::Function || pou.kind == SymbolKind::Method;
}

bool is_temporary(const Symbol& pou, const Symbol& variable) {
  return variable.section == VarSection::Temp || (is_temporary_pou(pou) && variable.section == VarSection::Var);
}

// Declarations without code of their own: interface members, abstract methods, prototypes, and
// blocks whose body and members are all missing (an export that kept only the declaration).
bool has_no_code(const Symbol& pou) {
  if (pou.kind == SymbolKind::Interface || (pou.owner && pou.owner->kind == SymbolKind::Interface)) return true;
  if (pou.has(check::kAbstract)) return true;
  if (pou.node && pou.node.child_by_field("body")) return false;
  return std::none_of(pou.ordered.begin(), pou.ordered.end(),
                      [](const Symbol* member) { return check::is_pou_kind(member->kind); });
}

// CODESYS "POUs for implicit checks": the compiler calls them on every array access, division,
// subrange assignment or pointer dereference once they exist (CODESYS textbook L5547-6267).
bool is_implicit_check(const Symbol& pou) {
  static constexpr std::string_view kChecks[] = {
      "CheckBounds",   "CheckRangeSigned", "CheckRangeUnsigned", "CheckLRangeSigned", "CheckLRangeUnsigned",
      "CheckPointer",  "CheckDivInt",      "CheckDivDInt",       "CheckDivLInt",      "CheckDivReal",
      "CheckDivLReal", "CheckDivByte",     "CheckDivWord",       "CheckDivDWord"};
  return pou.kind == SymbolKind::Function &&
         std::any_of(std::begin(kChecks), std::end(kChecks),
                     [&](std::string_view check) { return check::names_equal(check, pou.name); });
}

// A POU whose parameters are not its author's choice: an implicit check function, or a method
// that implements an interface method or redefines a base block's, is a property accessor, or is
// one of the FB_init/FB_reinit/FB_exit methods the runtime calls with a fixed signature.
bool has_fixed_signature(const check::ProjectModel& model, const Symbol& pou) {
  if (is_implicit_check(pou)) return true;
  if (pou.kind != SymbolKind::Method) return false;
  if (pou.has(check::kOverride)) return true;
  for (std::string_view system : {"FB_init", "FB_reinit", "FB_exit"}) {
    if (check::names_equal(pou.name, system)) return true;
  }
  const Symbol* owner = pou.owner;
  if (!owner || owner->kind == SymbolKind::Property) return owner != nullptr;
  if (owner->base && model.find_member(owner->base, pou.name)) return true;
  for (const Symbol* interface : owner->interfaces) {
    if (model.find_member(interface, pou.name)) return true;
  }
  return false;
}

// What the code of `pou` (its body, members, and blocks that extend it, in any file) does with
// one of its variables: the union of the flags of those uses.
uint16_t flags_inside(ProjectUsage& usage, const check::ProjectModel& model, const Symbol& variable,
                      const Symbol& pou) {
  uint16_t flags = 0;
  std::set<check::SourceId> files{pou.source};
  for (const Symbol* derived : usage.derived_of(model, &pou)) files.insert(derived->source);
  for (const check::SourceId id : files) {
    const FileUsage& file = usage.file(model, id);
    for (const uint32_t index : file.uses_of(&variable)) {
      if (is_within_or_derived(file.uses[index].scope, &pou)) flags |= file.uses[index].flags;
    }
  }
  return flags;
}

// --- L070 unused-variable ---------------------------------------------------------------------

// Removing the declaration's line(s), when the declaration has them to itself (a trailing //
// comment goes with it) and nothing else hangs on it: one name, no AT address, no attribute.
std::optional<Fix> declaration_removal(const LintContext& context, const Symbol& variable) {
  const SyntaxNode declaration = variable.node;
  if (!declaration || declaration.kind() != "var_declaration" || declaration.has_error()) return std::nullopt;
  if (variable.location_node || !variable.attributes.empty()) return std::nullopt;
  if (ast::VarDeclaration(declaration).names().size() != 1) return std::nullopt;
  const std::string_view text = context.text();
  uint32_t begin = declaration.begin();
  while (begin > 0 && text[begin - 1] != '\n') {
    if (text[begin - 1] != ' ' && text[begin - 1] != '\t') return std::nullopt;
    --begin;
  }
  size_t end = declaration.end();
  while (end < text.size() && (text[end] == ' ' || text[end] == '\t' || text[end] == '\r')) ++end;
  if (text.substr(end, 2) == "//") end = std::min(text.find('\n', end), text.size());
  if (end < text.size() && text[end] != '\n') return std::nullopt;
  if (end < text.size()) ++end;
  return Fix{fmt::format("remove the declaration of '{}'", variable.name),
             {TextEdit{{begin, static_cast<uint32_t>(end)}, ""}}};
}

// An instance whose block runs code when it is created or removed (FB_init, FB_exit), or whose
// block extends one rung cannot see (a library's): declaring it may be all its use, e.g. a
// TcUnit test suite registers itself from its base block's FB_init.
bool declaring_has_effects(const check::ProjectModel& model, const Symbol& variable) {
  const check::Type* type = check::underlying(model.type_of(&variable));
  for (int depth = 0; type && type->kind == check::TypeKind::Array && type->element && depth < 8; ++depth) {
    type = check::underlying(type->element);
  }
  if (!type || type->kind != check::TypeKind::Pou || !type->declaration) return false;
  const Symbol* block = type->declaration;
  return model.find_member(block, "FB_init") || model.find_member(block, "FB_exit") || model.has_unresolved_base(block);
}

// An instance's variables can be read from outside (CODESYS allows instance.local and PRG.local)
// and blocks that extend it use them as their own.
bool reachable_from_outside(const Symbol& pou) {
  return pou.kind == SymbolKind::FunctionBlock || pou.kind == SymbolKind::Program || pou.kind == SymbolKind::Class;
}

void check_unused_variable(LintContext& context) {
  ProjectUsage& usage = project_usage(context);
  const check::ProjectModel& model = context.model();
  const FileUsage& file = usage.file(model, context.source_id());
  for (const Symbol* pou : context.pous()) {
    if (file.embeds_foreign_code(*pou)) continue;
    for_each_variable(*pou, [&](const Symbol& variable) {
      if (file.inactive_names.contains(variable.name)) return;  // used where other defines compile
      const VarSection section = variable.section;
      if (section != VarSection::Var && section != VarSection::Temp && section != VarSection::Stat &&
          section != VarSection::Inst) {
        return;
      }
      // Attributes may hand the variable to the runtime or a tool ('instance-path', OPC UA
      // symbols); SFCInit, SFCReset ... are read by the SFC engine.
      if (!variable.attributes.empty() || check::find_builtin(variable.name)) return;
      if (declaring_has_effects(model, variable)) return;
      if (!file.uses_of(&variable).empty()) return;
      if (reachable_from_outside(*pou) &&
          (usage.maybe_named_unresolved(model, variable.name) ||
           usage.any_use(model, &variable, [](const Use&, check::SourceId) { return true; }))) {
        return;
      }
      context.report("L070", fmt::format("'{}' is declared but never used", variable.name), variable.name_range,
                     variable.location_node
                         ? "remove it (it is mapped to an address: check that the I/O is really unused)"
                         : "remove the declaration: an unused variable misleads the reader and costs memory",
                     declaration_removal(context, variable));
    });
  }
}

// --- L071 unused-parameter, L076 output-never-written, L078 in-out-never-written -----------------

void check_unused_parameter(LintContext& context) {
  ProjectUsage& usage = project_usage(context);
  const check::ProjectModel& model = context.model();
  const FileUsage& file = usage.file(model, context.source_id());
  for (const Symbol* pou : context.pous()) {
    if (has_no_code(*pou) || has_fixed_signature(model, *pou) || file.embeds_foreign_code(*pou)) continue;
    for_each_variable(*pou, [&](const Symbol& variable) {
      if (file.inactive_names.contains(variable.name)) return;  // used where other defines compile
      if (variable.section != VarSection::Input && variable.section != VarSection::InOut) return;
      if (check::names_equal(variable.name, "EN")) return;
      const uint16_t flags = flags_inside(usage, model, variable, *pou);
      // A VAR_IN_OUT that is only written hands a result back by reference: that is a use.
      const uint16_t used = variable.section == VarSection::InOut ? (kUseMayRead | kUseMayWrite) : kUseMayRead;
      if (flags & used) return;
      const bool in_out = variable.section == VarSection::InOut;
      context.report(
          "L071",
          fmt::format("{} '{}' of '{}' is never {}{}", ast::var_section_name(variable.section), variable.name,
                      pou->name, in_out ? "used" : "read", (flags & kUseWrite) ? " (only written)" : ""),
          variable.name_range,
          "use it or remove it: a caller's value for it changes nothing, which is rarely what the "
          "caller expects");
    });
  }
}

void check_output_never_written(LintContext& context) {
  ProjectUsage& usage = project_usage(context);
  const check::ProjectModel& model = context.model();
  const FileUsage& file = usage.file(model, context.source_id());
  for (const Symbol* pou : context.pous()) {
    if (has_no_code(*pou) || file.embeds_foreign_code(*pou)) continue;
    for_each_variable(*pou, [&](const Symbol& variable) {
      if (file.inactive_names.contains(variable.name)) return;  // used where other defines compile
      // An output with an initial value and no write is a constant the author chose (a version).
      if (variable.section != VarSection::Output || variable.has(check::kHasInitializer)) return;
      if (check::names_equal(variable.name, "ENO")) return;
      if (flags_inside(usage, model, variable, *pou) & kUseMayWrite) return;
      context.report("L076", fmt::format("output '{}' of '{}' is never written", variable.name, pou->name),
                     variable.name_range, "assign it, or remove it: callers always read its default value");
    });
  }
}

void check_in_out_never_written(LintContext& context) {
  ProjectUsage& usage = project_usage(context);
  const check::ProjectModel& model = context.model();
  const FileUsage& file = usage.file(model, context.source_id());
  const project::Profile profile = model.profile().id;
  const bool has_constant_in_out = profile == project::Profile::Codesys || profile == project::Profile::Twincat;
  for (const Symbol* pou : context.pous()) {
    if (has_no_code(*pou) || has_fixed_signature(model, *pou) || file.embeds_foreign_code(*pou)) continue;
    for_each_variable(*pou, [&](const Symbol& variable) {
      if (file.inactive_names.contains(variable.name)) return;  // used where other defines compile
      if (variable.section != VarSection::InOut || variable.has(check::kConstant)) return;
      const uint16_t flags = flags_inside(usage, model, variable, *pou);
      if (!(flags & kUseMayRead) || (flags & kUseMayWrite)) return;  // unused: L071
      context.report(
          "L078", fmt::format("VAR_IN_OUT '{}' of '{}' is only read, never written", variable.name, pou->name),
          variable.name_range,
          has_constant_in_out
              ? "declare it in VAR_IN_OUT CONSTANT: still passed by reference (the reason to pass a large STRUCT, "
                "ARRAY or STRING this way), and callers see it is not changed; a small value can be a VAR_INPUT"
              : "declare it VAR_INPUT, unless it is passed by reference for speed (a large STRUCT, ARRAY or "
                "STRING): callers then see it is not changed");
    });
  }
}

// --- L072 unused-pou, L073 unused-type ------------------------------------------------------------

// Whether code outside `symbol` (not itself, not its members) names it somewhere in the project.
bool used_outside(ProjectUsage& usage, const check::ProjectModel& model, const Symbol& symbol) {
  return usage.any_use(model, &symbol, [&](const Use& use, check::SourceId) { return !is_within(use.scope, &symbol); });
}

void check_unused_pou(LintContext& context) {
  ProjectUsage& usage = project_usage(context);
  const check::ProjectModel& model = context.model();
  if (!usage.has_program(model)) return;  // a library: its POUs are for other projects
  const bool has_configuration = usage.has_configuration(model);
  for (const Symbol* pou : context.source().symbols.top_level) {
    const SymbolKind kind = pou->kind;
    if (pou->name.empty()) continue;
    if (kind != SymbolKind::Function && kind != SymbolKind::FunctionBlock && kind != SymbolKind::Class &&
        !(kind == SymbolKind::Program && has_configuration)) {
      continue;
    }
    if (is_implicit_check(*pou)) continue;
    if (used_outside(usage, model, *pou) || usage.maybe_named_unresolved(model, pou->name)) continue;
    std::string message;
    if (kind == SymbolKind::Function) {
      message = fmt::format("FUNCTION '{}' is never called", pou->name);
    } else if (kind == SymbolKind::Program) {
      message = fmt::format("PROGRAM '{}' is never called and no TASK runs it", pou->name);
    } else {
      message = fmt::format("{} '{}' is never instantiated or extended", pou_word(*pou), pou->name);
    }
    context.report("L072", std::move(message), pou->name_range,
                   "remove it, or use it: code that never runs still has to be read and maintained (in a "
                   "library project, switch the rule off: [lint.rules] L072 = \"off\")");
  }
}

void check_unused_type(LintContext& context) {
  ProjectUsage& usage = project_usage(context);
  const check::ProjectModel& model = context.model();
  if (!usage.has_program(model)) return;  // a library: its types are for other projects
  for (const Symbol& type : context.source().symbols.storage) {
    if (type.kind != SymbolKind::DataType || type.name.empty()) continue;
    if (type.owner && !check::is_pou_kind(type.owner->kind)) continue;
    if (used_outside(usage, model, type) || usage.maybe_named_unresolved(model, type.name)) continue;
    // An enumeration is used when one of its values is, written without the type's name.
    bool value_used = false;
    for (const Symbol* value : type.ordered) {
      if (value->kind == SymbolKind::EnumValue && used_outside(usage, model, *value)) {
        value_used = true;
        break;
      }
    }
    if (value_used) continue;
    context.report("L073", fmt::format("TYPE '{}' is never used", type.name), type.name_range,
                   "remove it, or use it (in a library project, switch the rule off: [lint.rules] L073 = \"off\")");
  }
}

// --- L074 shadowing -------------------------------------------------------------------------------

std::string where_declared(const check::ProjectModel& model, const Symbol& symbol) {
  const Document& document = *model.source(symbol.source).document;
  return fmt::format("{}:{}", std::filesystem::path(document.path()).filename().string(),
                     document.position_of_tree_offset(symbol.name_range.begin).line);
}

// The block a method (or a property accessor) belongs to.
const Symbol* owning_block(const Symbol& pou) {
  const Symbol* owner = pou.owner;
  while (owner && (owner->kind == SymbolKind::Property || owner->kind == SymbolKind::Method)) owner = owner->owner;
  return owner;
}

// What a local called like `variable` hides, described for the message; empty when nothing.
std::string hidden_by(const check::ProjectModel& model, const Symbol& pou, const Symbol& variable) {
  const bool checker_reports = model.profile().unique_names;  // OpenPCS: an error of `rung check`
  if (pou.kind == SymbolKind::Method) {
    const Symbol* block = owning_block(pou);
    const Symbol* member = block ? model.find_member(block, variable.name) : nullptr;
    if (member && member->kind == SymbolKind::Variable && member != &variable) {
      return fmt::format("the variable '{}' of '{}' ({})", member->name, block->name, where_declared(model, *member));
    }
  }
  if (const Symbol* global = model.find_global_variable(variable.name);
      global && !checker_reports && !global->has(check::kLibrary)) {
    return fmt::format("the global variable '{}' ({})", global->name, where_declared(model, *global));
  }
  if (const Symbol* global = model.find_global(variable.name);
      global && global != &pou && !global->has(check::kLibrary) &&
      !(checker_reports && global->kind != SymbolKind::GlobalList)) {
    if (global->kind == SymbolKind::GlobalList) {
      return fmt::format("the global variable list '{}' ({})", global->name, where_declared(model, *global));
    }
    return fmt::format("the {} '{}' ({})", pou_word(*global), global->name, where_declared(model, *global));
  }
  if (const auto* values = model.find_enum_values(variable.name)) {
    for (const Symbol* value : *values) {
      if (value->has(check::kLibrary) || !value->owner) continue;
      return fmt::format("the value '{}' of '{}' ({})", value->name, value->owner->name, where_declared(model, *value));
    }
  }
  return {};
}

void check_shadowing(LintContext& context) {
  const check::ProjectModel& model = context.model();
  for (const Symbol* pou : context.pous()) {
    for_each_variable(*pou, [&](const Symbol& variable) {
      const VarSection section = variable.section;
      // A VAR_EXTERNAL repeats its global's name on purpose.
      if (section == VarSection::External || section == VarSection::Global || section == VarSection::Config ||
          section == VarSection::Access) {
        return;
      }
      const std::string hidden = hidden_by(model, *pou, variable);
      if (hidden.empty()) return;
      context.report("L074", fmt::format("'{}' hides {}", variable.name, hidden), variable.name_range,
                     fmt::format("rename it: inside '{}' the name means this declaration, so code meant for the "
                                 "other one silently uses it",
                                 pou->name));
    });
  }
}

// --- L075 read-before-write, L077 written-never-read ---------------------------------------------

// Types whose "no value yet" the flow analysis can follow: elementary values, strings, enums,
// pointers. Structures and arrays are filled member by member, references bound with REF=.
bool is_traceable(const check::ProjectModel& model, const Symbol& variable) {
  const check::Type* type = check::underlying(model.type_of(&variable));
  if (!type) return false;
  switch (type->kind) {
    case check::TypeKind::Bool:
    case check::TypeKind::Bit:
    case check::TypeKind::SignedInt:
    case check::TypeKind::UnsignedInt:
    case check::TypeKind::Real:
    case check::TypeKind::Duration:
    case check::TypeKind::Date:
    case check::TypeKind::TimeOfDay:
    case check::TypeKind::DateTime:
    case check::TypeKind::String:
    case check::TypeKind::WString:
    case check::TypeKind::Char:
    case check::TypeKind::WChar:
    case check::TypeKind::Enum:
    case check::TypeKind::Subrange:
    case check::TypeKind::Pointer: return true;
    default: return false;
  }
}

void check_read_before_write(LintContext& context) {
  ProjectUsage& usage = project_usage(context);
  const check::ProjectModel& model = context.model();
  const FileUsage& file = usage.file(model, context.source_id());
  for (const Symbol* pou : context.pous()) {
    if (file.embeds_foreign_code(*pou)) continue;
    std::vector<const Symbol*> candidates;
    for_each_variable(*pou, [&](const Symbol& variable) {
      if (file.inactive_names.contains(variable.name)) return;  // used where other defines compile
      if (!is_temporary(*pou, variable) || variable.has(check::kHasInitializer) || variable.has(check::kConstant) ||
          variable.location_node || !is_traceable(model, variable)) {
        return;
      }
      candidates.push_back(&variable);
    });
    for (const EarlyRead& read : reads_before_write(model, *pou, file, candidates)) {
      context.report(
          "L075", fmt::format("'{}' is read before any value is written to it", read.variable->name), read.where,
          fmt::format("{} '{}' starts from its default value on every call, not from the previous call's value: "
                      "assign it first, or give it an initial value in its declaration if the default is meant",
                      ast::var_section_name(read.variable->section), read.variable->name));
    }
  }
}

void check_written_never_read(LintContext& context) {
  ProjectUsage& usage = project_usage(context);
  const check::ProjectModel& model = context.model();
  const FileUsage& file = usage.file(model, context.source_id());
  for (const Symbol* pou : context.pous()) {
    if (file.embeds_foreign_code(*pou)) continue;
    for_each_variable(*pou, [&](const Symbol& variable) {
      if (file.inactive_names.contains(variable.name)) return;  // used where other defines compile
      if (!is_temporary(*pou, variable) || variable.location_node || !variable.attributes.empty()) return;
      // Writing through a reference (r := 5 after r REF= x) changes x: that is its use.
      const check::Type* type = check::underlying(model.type_of(&variable));
      if (type && type->kind == check::TypeKind::Reference) return;
      uint16_t flags = 0;
      bool assigned = false;  // by the code itself, not only as a call's `=> x` that the call may require
      for (const uint32_t index : file.uses_of(&variable)) {
        const Use& use = file.uses[index];
        flags |= use.flags;
        assigned = assigned || ((use.flags & kUseWrite) && !(use.flags & kUseOutputTarget));
      }
      if (!assigned || (flags & kUseMayRead)) return;
      context.report("L077", fmt::format("'{}' is written but its value is never read", variable.name),
                     variable.name_range,
                     "remove it with its assignments, or use the value (a forgotten use is the usual cause)");
    });
  }
}

// --- L079 function-writes-global ------------------------------------------------------------------

void check_function_writes_global(LintContext& context) {
  ProjectUsage& usage = project_usage(context);
  const check::ProjectModel& model = context.model();
  const FileUsage& file = usage.file(model, context.source_id());
  for (const Symbol* pou : context.pous()) {
    if (pou->kind != SymbolKind::Function || !pou->node) continue;
    std::set<const Symbol*> reported;
    for (const Use& use : file.uses_in(pou->node.range())) {
      const Symbol* global = use.symbol;
      if (global->kind != SymbolKind::Variable || global->section != VarSection::Global) continue;
      if (!is_within(use.scope, pou) || reported.count(global)) continue;
      std::string what;
      if (use.flags & kUseWrite) {
        what = fmt::format("writes the global variable '{}'", global->name);
      } else if (use.flags & kUseInOut) {
        what = fmt::format("passes the global variable '{}' to a VAR_IN_OUT", global->name);
      } else if (use.flags & kUseCall) {
        what = fmt::format("calls the global instance '{}'", global->name);
      } else {
        continue;
      }
      reported.insert(global);
      context.report("L079", fmt::format("FUNCTION '{}' {}", pou->name, what), use.range,
                     "a FUNCTION should only compute its result from its inputs: pass the variable as VAR_IN_OUT "
                     "or return the value, so that every call shows the effect");
    }
  }
}

}  // namespace

void add_usage_rules(std::vector<Rule>& rules) {
  rules.push_back({"L070", "unused-variable", true, true, check_unused_variable});
  rules.push_back({"L071", "unused-parameter", true, false, check_unused_parameter});
  rules.push_back({"L072", "unused-pou", true, false, check_unused_pou});
  rules.push_back({"L073", "unused-type", true, false, check_unused_type});
  rules.push_back({"L074", "shadowing", true, false, check_shadowing});
  rules.push_back({"L075", "read-before-write", true, false, check_read_before_write});
  rules.push_back({"L076", "output-never-written", true, false, check_output_never_written});
  rules.push_back({"L077", "written-never-read", true, false, check_written_never_read});
  rules.push_back({"L078", "in-out-never-written", true, false, check_in_out_never_written});
  rules.push_back({"L079", "function-writes-global", true, false, check_function_writes_global});
}

}  // namespace rung::lint
