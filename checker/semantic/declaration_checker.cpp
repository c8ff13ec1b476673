#include "checker/semantic/declaration_checker.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <map>

#include "checker/semantic/address_checker.hpp"
#include "checker/semantic/body_checker.hpp"
#include "checker/semantic/configuration_checker.hpp"
#include "checker/semantic/initializer_checker.hpp"
#include "checker/semantic/limits_checker.hpp"
#include "checker/semantic/name_checker.hpp"
#include "parser/diagnostic_codes.hpp"

namespace rung::check {
namespace {

using ast::VarSection;

// Which sections each kind of POU may declare (IEC 61131-3 table 13 and CODESYS V3).
bool section_allowed(SymbolKind kind, VarSection section, const Profile& profile) {
  switch (section) {
    case VarSection::Var:
    case VarSection::Unknown: return kind != SymbolKind::Interface;
    case VarSection::Input:
      if (kind == SymbolKind::Program) return profile.program_parameters;
      return kind != SymbolKind::GlobalList && kind != SymbolKind::Action && kind != SymbolKind::Transition;
    case VarSection::InOut:
    case VarSection::Output:
      if (kind == SymbolKind::Program) return profile.program_parameters;
      if (kind == SymbolKind::Function) return profile.function_outputs_and_externals;
      return kind != SymbolKind::GlobalList && kind != SymbolKind::Action && kind != SymbolKind::Transition;
    case VarSection::Temp:
      // A function's variables live for one call anyway (CODESYS C0174, IEC).
      return kind != SymbolKind::GlobalList && kind != SymbolKind::Interface && kind != SymbolKind::Function;
    case VarSection::Stat:
      return kind == SymbolKind::Function || kind == SymbolKind::Method || kind == SymbolKind::FunctionBlock;
    case VarSection::Inst: return kind == SymbolKind::Method;
    case VarSection::Global:
      return kind == SymbolKind::GlobalList || kind == SymbolKind::Configuration || kind == SymbolKind::Resource;
    case VarSection::External:
      if (kind == SymbolKind::Function) return profile.function_outputs_and_externals;
      return kind != SymbolKind::GlobalList && kind != SymbolKind::Interface;
    case VarSection::Config:
    case VarSection::Access:
      return kind == SymbolKind::Configuration || kind == SymbolKind::Resource || kind == SymbolKind::GlobalList;
  }
  return true;
}

class DeclarationChecker {
 public:
  DeclarationChecker(const ProjectModel& model, SourceId source, std::vector<Diagnostic>& out)
      : model_(model), source_(source), out_(out) {}

  void run() {
    for (const Symbol* symbol : model_.source(source_).symbols.top_level) check_symbol(*symbol);
  }

 private:
  void report(std::string_view code, std::string message, TextRange range, std::string help = {},
              std::vector<DiagnosticLabel> labels = {}) {
    out_.push_back(make_diagnostic(code, std::move(message), range, std::move(help), std::move(labels)));
  }

  void check_symbol(const Symbol& symbol) {
    if (is_pou_kind(symbol.kind) || symbol.kind == SymbolKind::GlobalList) check_variables(symbol);
    if (symbol.kind == SymbolKind::GlobalList) check_program_globals(symbol);
    if (symbol.kind == SymbolKind::DataType) check_type(symbol);
    if (symbol.kind == SymbolKind::FunctionBlock || symbol.kind == SymbolKind::Class) check_interfaces(symbol);
    if (is_pou_kind(symbol.kind)) {
      check_bases(symbol);
      check_pou_interface(symbol);
    }
    for (const Symbol* member : symbol.ordered) {
      if (is_pou_kind(member->kind)) check_symbol(*member);
      if (member->kind == SymbolKind::DataType) check_type(*member);  // POU-local TYPE (OpenPCS)
    }
  }

  void check_variables(const Symbol& owner) {
    std::vector<SyntaxNode> blocks;
    for (const Symbol* variable : owner.ordered) {
      if (variable->kind != SymbolKind::Variable) continue;
      if (!section_allowed(owner.kind, variable->section, model_.profile())) {
        report(codes::kSectionNotAllowed,
               fmt::format("a {} cannot declare {}", symbol_kind_name(owner.kind),
                           ast::var_section_name(variable->section)),
               variable->name_range,
               owner.kind == SymbolKind::Program && !model_.profile().program_parameters
                   ? "this profile (OpenPCS) allows no parameters in a PROGRAM; use global variables"
                   : std::string());
      }
      check_retain(owner, *variable);
      check_located(owner, *variable);
      check_en_eno(*variable);
      check_variable_type(owner, *variable);
      check_initial_value(model_, owner, *variable, out_);
      if (variable->section == VarSection::External) check_external(*variable);
      SyntaxNode block = variable->node.parent();
      if (block && block.kind() == "var_block" && (blocks.empty() || !(blocks.back() == block))) {
        blocks.push_back(block);
        check_block_qualifiers(ast::VarBlock(block));
      }
    }
  }

  // VAR_GLOBAL written inside a PROGRAM (the collector made it a global list around the program).
  void check_program_globals(const Symbol& list) {
    if (!list.owner || list.owner->kind != SymbolKind::Program || model_.profile().program_globals) return;
    for (const Symbol* variable : list.ordered) {
      report(codes::kSectionNotAllowed, "a program cannot declare VAR_GLOBAL", variable->name_range,
             "declare global variables in a global variable list");
    }
  }

  // RETAIN/PERSISTENT where values cannot be kept.
  void check_retain(const Symbol& owner, const Symbol& variable) {
    if (!variable.has(kRetain) && !variable.has(kPersistent)) return;
    const Profile& profile = model_.profile();
    const bool in_function = owner.kind == SymbolKind::Function || owner.kind == SymbolKind::Method;
    std::string where;
    std::string help = "declare it in a PROGRAM, FUNCTION_BLOCK or global variable list";
    if (variable.section == VarSection::Temp || variable.section == VarSection::InOut ||
        variable.section == VarSection::External) {
      where = fmt::format("{} variables live only during one call or belong to someone else",
                          ast::var_section_name(variable.section));
    } else if (variable.section == VarSection::Input && !profile.retain_inputs) {
      where = "this profile (OpenPCS) keeps only VAR, VAR_OUTPUT and VAR_GLOBAL in retain memory";
    } else if (in_function) {
      where = fmt::format("{} variables live only during one call", symbol_kind_name(owner.kind));
    } else if (variable.location_node && !profile.located_retain) {
      where = "a variable at a direct address lives in the process image, not in retain memory";
      help = "remove the AT address or move the variable to a VAR block without RETAIN";
    } else if (!profile.qualified_instances && instance_block(model_.type_of(&variable))) {
      where = "this profile (OpenPCS) keeps no function block instance in retain memory";
      help = "declare the instance in a VAR block without RETAIN";
    } else if (profile.en_eno_rules && is_en_or_eno(variable)) {
      where = "EN and ENO are never RETAIN";
      help = "declare EN/ENO in a block without RETAIN";
    } else {
      return;
    }
    Diagnostic diagnostic = make_diagnostic(
        codes::kRetainNotAllowed, fmt::format("'{}' cannot be RETAIN/PERSISTENT here: {}", variable.name, where),
        variable.name_range, help);
    // CODESYS compiles RETAIN in a function: it simply has no effect (textbook L3639).
    const bool only_in_function = in_function && variable.section != VarSection::Temp &&
                                  variable.section != VarSection::InOut && variable.section != VarSection::External;
    if (only_in_function && !profile.retain_in_functions_is_error) diagnostic.severity = Severity::Warning;
    out_.push_back(std::move(diagnostic));
  }

  // AT on a variable of a block or function, CONSTANT on an AT variable.
  void check_located(const Symbol& owner, const Symbol& variable) {
    if (!variable.location_node) return;
    const Profile& profile = model_.profile();
    if (variable.has(kConstant) && !profile.located_constants) {
      report(codes::kQualifierNotAllowed,
             fmt::format("'{}' is at a direct address: in this profile it cannot be CONSTANT", variable.name),
             variable.name_range, "declare it in a VAR block without CONSTANT");
    }
    const bool block_local = owner.kind == SymbolKind::FunctionBlock || owner.kind == SymbolKind::Function ||
                             owner.kind == SymbolKind::Method || owner.kind == SymbolKind::Class;
    if (!block_local) return;
    const std::optional<DirectAddress> address = declared_address(model_, variable);
    if (!address || address->wildcard) return;  // `%I*` is completed per instance (VAR_CONFIG); E505 in functions
    Diagnostic diagnostic = make_diagnostic(
        codes::kSectionNotAllowed,
        fmt::format("a {} cannot declare '{}' at a direct address: {}", symbol_kind_name(owner.kind), variable.name,
                    profile.located_block_locals_are_error ? "only programs and global lists may"
                                                           : "every instance would share it"),
        variable.location_node.range(), "declare it in a PROGRAM or global list and pass it in as an input");
    if (!profile.located_block_locals_are_error) diagnostic.severity = Severity::Warning;
    out_.push_back(std::move(diagnostic));
  }

  static bool is_en_or_eno(const Symbol& variable) {
    return names_equal(variable.name, "EN") || names_equal(variable.name, "ENO");
  }

  // EN is the IEC enable input, ENO the enable output (OpenPCS S1031, S1032).
  void check_en_eno(const Symbol& variable) {
    if (!model_.profile().en_eno_rules || !is_en_or_eno(variable) || !variable.owner ||
        !is_pou_kind(variable.owner->kind)) {
      return;
    }
    const bool en = names_equal(variable.name, "EN");
    const VarSection wanted = en ? VarSection::Input : VarSection::Output;
    if (variable.section != wanted) {
      report(codes::kSectionNotAllowed,
             fmt::format("{} must be declared in {}", en ? "EN" : "ENO", ast::var_section_name(wanted)),
             variable.name_range, en ? "EN is the enable input of the block" : "ENO is the enable output of the block");
    }
    const Type* type = model_.type_of(&variable);
    if (!type->is_unknown() && underlying(type)->kind != TypeKind::Bool) {
      report(codes::kTypeMismatch, fmt::format("{} must be BOOL, not {}", en ? "EN" : "ENO", type->name),
             variable.type_node ? variable.type_node.range() : variable.name_range);
    }
  }

  // CONSTANT on a section that cannot have it, or together with RETAIN.
  void check_block_qualifiers(const ast::VarBlock& block) {
    const Profile& profile = model_.profile();
    const VarSection section = block.section();
    SyntaxNode constant;
    SyntaxNode retain;
    for (SyntaxNode qualifier : block.node().children_of_kind("var_qualifier")) {
      if (names_equal(qualifier.text(), "CONSTANT")) constant = qualifier;
      if (names_equal(qualifier.text(), "RETAIN") || names_equal(qualifier.text(), "PERSISTENT")) retain = qualifier;
    }
    if (!constant) return;
    const bool parameter =
        section == VarSection::Input || section == VarSection::Output || section == VarSection::InOut;
    if ((parameter && !profile.constant_parameters) ||
        (section == VarSection::External && !profile.constant_externals)) {
      report(codes::kQualifierNotAllowed,
             fmt::format("{} cannot be CONSTANT in this profile", ast::var_section_name(section)), constant.range(),
             profile.constant_externals ? "CONSTANT belongs on VAR, VAR_GLOBAL and VAR_EXTERNAL"
                                        : "CONSTANT belongs on VAR and VAR_GLOBAL");
    } else if (retain && !profile.constant_parameters) {
      const SyntaxNode second = retain.begin() > constant.begin() ? retain : constant;
      report(codes::kQualifierNotAllowed,
             fmt::format("a {} block is either CONSTANT or {}, not both", ast::var_section_name(section),
                         upper_name(retain.text())),
             second.range(), "a constant never changes, so it has nothing to retain");
    }
  }

  // The function block a type holds an instance of, if any (arrays of instances included).
  static const Symbol* instance_block(const Type* type) {
    const Type* base = underlying(type);
    while (base->kind == TypeKind::Array && base->element) base = underlying(base->element);
    if (base->kind == TypeKind::Pou && base->declaration &&
        (base->declaration->kind == SymbolKind::FunctionBlock || base->declaration->kind == SymbolKind::Class)) {
      return base->declaration;
    }
    return nullptr;
  }

  // The POU-local TYPE a type is built from, if any (arrays, pointers and references included).
  static const Symbol* local_type_in(const Type* type) {
    for (int depth = 0; type && depth < 16; ++depth) {
      if (type->declaration && type->declaration->kind == SymbolKind::DataType && type->declaration->owner &&
          is_pou_kind(type->declaration->owner->kind)) {
        return type->declaration;
      }
      if (type->kind != TypeKind::Array && type->kind != TypeKind::Pointer && type->kind != TypeKind::Reference) break;
      type = type->element;
    }
    return nullptr;
  }

  void check_variable_type(const Symbol& owner, const Symbol& variable) {
    const Type* type = model_.type_of(&variable);
    const Type* base = underlying(type);
    if (base->kind == TypeKind::Array) {
      for (const ArrayDimension& dimension : base->dimensions) {
        if (dimension.open && variable.section != VarSection::InOut && variable.section != VarSection::Input &&
            variable.section != VarSection::Output) {
          report(codes::kInvalidArrayBounds, "ARRAY[*] is only allowed for VAR_IN_OUT (and inputs/outputs) parameters",
                 variable.name_range);
        } else if (!dimension.open && dimension.known && dimension.lower > dimension.upper) {
          report(codes::kInvalidArrayBounds,
                 fmt::format("array bounds {}..{}: the lower bound is above the upper bound", dimension.lower,
                             dimension.upper),
                 variable.name_range);
        }
      }
    }
    if ((base->kind == TypeKind::String || base->kind == TypeKind::WString) &&
        base->length > model_.profile().max_string_length && model_.profile().max_string_length > 0 &&
        variable.type_node && variable.type_node.child_by_field("length")) {
      // Only a warning: targets differ; rung.toml [target] max_string_length sets the limit.
      report(codes::kStringTooLong,
             fmt::format("STRING({}) is longer than the target's maximum of {}", base->length,
                         model_.profile().max_string_length),
             variable.type_node.range());
    }
    if (base->kind == TypeKind::Pou && base->declaration && base->declaration->has(kAbstract) &&
        variable.section != VarSection::InOut) {
      report(codes::kAbstractInstance,
             fmt::format("'{}' is ABSTRACT: it cannot be instantiated", base->declaration->name), variable.name_range,
             "declare an instance of a function block that EXTENDS it");
    }
    if (base->kind == TypeKind::Pou && base->declaration && base->declaration->kind == SymbolKind::Program) {
      report(codes::kWrongKindOfName, fmt::format("'{}' is a PROGRAM, not a type", base->declaration->name),
             variable.type_node.range(), "a program has one instance; call it by name");
    }
    check_subrange(variable.type_node, type);
    check_instance_placement(owner, variable, type);
    check_generic_type(owner, variable);
    if (const Symbol* local = local_type_in(type);
        local && variable.type_node &&
        (variable.section == VarSection::Input || variable.section == VarSection::Output ||
         variable.section == VarSection::InOut || variable.section == VarSection::Global ||
         variable.section == VarSection::External)) {
      report(codes::kLocalTypeInInterface,
             fmt::format("'{}' is a type local to '{}': a {} must have a type other POUs know", local->name,
                         local->owner->name, ast::var_section_name(variable.section)),
             variable.type_node.range(), "declare the type in a TYPE block outside the POU");
    }
  }

  // Function block instances where this profile has no room for them (E212): in a FUNCTION
  // (no state between calls), as STRUCT members or ARRAY elements (OpenPCS), in VAR CONSTANT.
  void check_instance_placement(const Symbol& owner, const Symbol& variable, const Type* type) {
    const Symbol* block = instance_block(type);
    if (!block || !variable.type_node) return;
    const Profile& profile = model_.profile();
    if (owner.kind == SymbolKind::Function && !profile.instances_in_functions &&
        variable.section != VarSection::InOut && variable.section != VarSection::Input) {
      report(codes::kInvalidCallTarget,
             fmt::format("a FUNCTION cannot hold the function block instance '{}': it keeps no state between calls",
                         variable.name),
             variable.type_node.range(), "declare the instance in the caller and pass it as VAR_IN_OUT");
    } else if (!profile.instances_in_data &&
               (owner.kind == SymbolKind::DataType || underlying(type)->kind == TypeKind::Array)) {
      report(codes::kInvalidCallTarget,
             fmt::format("'{}' holds instances of '{}': in this profile function block instances are not {}",
                         variable.name, block->name,
                         owner.kind == SymbolKind::DataType ? "STRUCT members" : "ARRAY elements"),
             variable.type_node.range(), "declare each instance as a variable of its own");
    } else if (variable.has(kConstant) && !profile.qualified_instances) {
      report(codes::kQualifierNotAllowed,
             fmt::format("the function block instance '{}' cannot be CONSTANT: its state changes with every call",
                         variable.name),
             variable.name_range, "declare the instance in a VAR block without CONSTANT");
    }
  }

  // ANY_INT and friends name groups of types: only standard functions may take them (IEC,
  // OpenPCS S5035); a user FUNCTION has one signature.
  void check_generic_type(const Symbol& owner, const Symbol& variable) {
    if (model_.profile().generic_parameters || !variable.type_node || variable.has(kLibrary)) return;
    SyntaxNode type_node = variable.type_node;
    if (type_node.kind() != "type_name" && type_node.kind() != "identifier") return;
    if (!model_.types().generic(type_node.text())) return;
    report(codes::kWrongKindOfName,
           fmt::format("'{}' is a generic type: '{}' in {} '{}' needs a data type", type_node.text(), variable.name,
                       symbol_kind_name(owner.kind), owner.name),
           type_node.range(), "choose one type (INT, DINT, ...); only standard functions are generic");
  }

  // What a POU declares as a whole: its result type, an input at all, EN with ENO.
  void check_pou_interface(const Symbol& pou) {
    const Profile& profile = model_.profile();
    if (pou.kind == SymbolKind::Function && pou.type_node && !profile.instances_in_data &&
        instance_block(pou.result_type)) {
      report(codes::kInvalidCallTarget, fmt::format("FUNCTION '{}' cannot return a function block instance", pou.name),
             pou.type_node.range(), "return a data type; pass the instance as VAR_IN_OUT");
    }
    if (pou.kind == SymbolKind::Function && profile.function_needs_input && !pou.has(kLibrary)) {
      const bool has_input = std::any_of(pou.ordered.begin(), pou.ordered.end(), [](const Symbol* member) {
        return member->kind == SymbolKind::Variable && member->section == VarSection::Input;
      });
      if (!has_input) {
        report(codes::kFunctionWithoutInput, fmt::format("FUNCTION '{}' has no VAR_INPUT", pou.name), pou.name_range,
               "a function in this profile (OpenPCS) takes at least one input");
      }
    }
    if (profile.en_eno_rules) {
      const Symbol* eno = pou.own_member("ENO");
      if (eno && eno->kind == SymbolKind::Variable && !pou.own_member("EN")) {
        report(codes::kEnoWithoutEn, fmt::format("'{}' declares ENO but no EN", pou.name), eno->name_range,
               "declare EN : BOOL in VAR_INPUT, or remove ENO");
      }
    }
  }

  void check_external(const Symbol& variable) {
    // A qualified_only list still provides VAR_EXTERNAL targets in CODESYS: find_linked_global
    // looks into every list.
    const Symbol* global = model_.find_linked_global(variable.name);
    if (!global) {
      report(codes::kExternalWithoutGlobal,
             fmt::format("VAR_EXTERNAL '{}' has no VAR_GLOBAL of that name", variable.name), variable.name_range,
             "declare it in a global variable list, or remove the VAR_EXTERNAL");
      return;
    }
    const Type* mine = model_.type_of(&variable);
    const Type* theirs = model_.type_of(global);
    if (!mine->is_unknown() && !theirs->is_unknown() && underlying(mine) != underlying(theirs) &&
        mine->name != theirs->name) {
      report(codes::kExternalTypeMismatch,
             fmt::format("VAR_EXTERNAL '{}' is {} but the VAR_GLOBAL is {}", variable.name, mine->name, theirs->name),
             variable.name_range);
    }
  }

  void check_type(const Symbol& type_symbol) {
    const Type* type = model_.type_of(&type_symbol);
    if (type->kind == TypeKind::Enum) {
      std::map<__int128, const Symbol*> values;
      for (const Symbol* value : type_symbol.ordered) {
        auto number = model_.enum_value(value);
        if (!number) continue;
        auto [it, inserted] = values.emplace(*number, value);
        if (!inserted) {
          report(codes::kDuplicateEnumValue,
                 fmt::format("'{}' has the same value ({}) as '{}'", value->name, int128_to_string(*number),
                             it->second->name),
                 value->name_range, {}, {{it->second->name_range, "same value here"}});
        }
        check_enum_value_range(*value, *number, type);
      }
    }
    if (type->kind == TypeKind::Alias) check_subrange(type_symbol.type_node, type->element);
    if (type->kind == TypeKind::Struct || type->kind == TypeKind::Union) {
      for (const Symbol* field : type_symbol.ordered) {
        if (field->kind != SymbolKind::Variable) continue;
        check_variable_type(type_symbol, *field);
        check_initial_value(model_, type_symbol, *field, out_);
      }
    }
    check_type_initializer(model_, type_symbol, out_);
    check_bases(type_symbol);
  }

  // An enumerator's number must fit the enumeration's base type (INT unless given).
  void check_enum_value_range(const Symbol& value, __int128 number, const Type* enumeration) {
    const std::optional<IntegerRange> range = enumeration->element ? integer_range(enumeration->element) : std::nullopt;
    if (!range || (number >= range->lower && number <= range->upper)) return;
    SyntaxNode written = value.node.child_by_field("value");
    report(codes::kLiteralOutOfRange,
           fmt::format("'{}' = {} does not fit the base type {} of the enumeration ({}..{})", value.name,
                       int128_to_string(number), enumeration->element->name, int128_to_string(range->lower),
                       int128_to_string(range->upper)),
           written ? written.range() : value.name_range, "choose a smaller value or a wider base type: (...) DINT");
  }

  // INT(-1..36000): the bounds must be values of the base type, the lower one not above the upper.
  void check_subrange(SyntaxNode spec, const Type* type) {
    if (!spec || spec.kind() != "subrange_type" || !type || type->kind != TypeKind::Subrange || !type->element) return;
    SyntaxNode range_node = spec.child_by_field("range");
    if (!range_node) return;
    const std::optional<IntegerRange> range = integer_range(type->element);
    bool fits = true;
    if (range) {
      for (const auto& [bound, field] :
           {std::pair{type->range_lower, "lower"}, std::pair{type->range_upper, "upper"}}) {
        if (bound >= range->lower && bound <= range->upper) continue;
        fits = false;
        SyntaxNode node = range_node.child_by_field(field);
        report(codes::kLiteralOutOfRange,
               fmt::format("the {} bound {} is not a value of {} ({}..{})", field, bound, type->element->name,
                           int128_to_string(range->lower), int128_to_string(range->upper)),
               node ? node.range() : range_node.range(), "choose a bound inside the base type, or a wider base type");
      }
    }
    if (fits && type->range_lower > type->range_upper) {
      report(codes::kInvalidArrayBounds,
             fmt::format("subrange {}..{}: the lower bound is above the upper bound", type->range_lower,
                         type->range_upper),
             range_node.range(), "write the smaller bound first");
    }
  }

  void check_bases(const Symbol& symbol) {
    for (size_t i = 0; i < symbol.base_nodes.size(); ++i) {
      SyntaxNode node = symbol.base_nodes[i];
      const Symbol* base = i < symbol.bases.size() ? symbol.bases[i] : nullptr;
      if (!base) continue;
      const bool ok = (symbol.kind == SymbolKind::FunctionBlock && base->kind == SymbolKind::FunctionBlock) ||
                      (symbol.kind == SymbolKind::Class && base->kind == SymbolKind::Class) ||
                      (symbol.kind == SymbolKind::Interface && base->kind == SymbolKind::Interface) ||
                      (symbol.kind == SymbolKind::DataType && base->kind == SymbolKind::DataType);
      if (!ok) {
        report(codes::kInvalidInheritance,
               fmt::format("a {} cannot extend the {} '{}'", symbol_kind_name(symbol.kind),
                           symbol_kind_name(base->kind), base->name),
               node.range());
      } else if (base->has(kFinal)) {
        report(codes::kFinalOverride, fmt::format("'{}' is FINAL and cannot be extended", base->name), node.range());
      }
      // A cycle: following the bases comes back here.
      const Symbol* walk = base;
      for (int depth = 0; walk && depth < 40; ++depth, walk = walk->base) {
        if (walk == &symbol) {
          report(codes::kInvalidInheritance, fmt::format("'{}' extends itself through '{}'", symbol.name, base->name),
                 node.range());
          break;
        }
      }
    }
  }

  void check_interfaces(const Symbol& block) {
    if (block.has(kAbstract)) return;
    for (size_t i = 0; i < block.interfaces.size(); ++i) {
      const Symbol* interface = block.interfaces[i];
      if (interface->kind != SymbolKind::Interface) {
        report(codes::kInvalidInheritance, fmt::format("'{}' is not an INTERFACE", interface->name),
               block.interface_nodes[i].range());
        continue;
      }
      std::vector<const Symbol*> pending{interface};
      for (size_t k = 0; k < pending.size() && k < 64; ++k) {
        for (const Symbol* base : pending[k]->bases) pending.push_back(base);
        for (const Symbol* member : pending[k]->ordered) {
          if (member->kind != SymbolKind::Method && member->kind != SymbolKind::Property) continue;
          const Symbol* implementation = model_.find_member(&block, member->name);
          if (!implementation) {
            report(codes::kMissingInterfaceMember,
                   fmt::format("'{}' implements '{}' but has no {} '{}'", block.name, interface->name,
                               symbol_kind_name(member->kind), member->name),
                   block.interface_nodes[i].range(),
                   fmt::format("add {} {} to {}", member->kind == SymbolKind::Method ? "METHOD" : "PROPERTY",
                               member->name, block.name));
          }
        }
      }
    }
  }

  const ProjectModel& model_;
  SourceId source_;
  std::vector<Diagnostic>& out_;
};

}  // namespace

void check_declarations(const ProjectModel& model, SourceId source, std::vector<Diagnostic>& out) {
  DeclarationChecker(model, source, out).run();
  check_names(model, source, out);
  check_limits(model, source, out);
  check_addresses(model, source, out);
  check_configurations(model, source, out);
}

}  // namespace rung::check
