#include "checker/semantic/declaration_checker.hpp"

#include <fmt/format.h>

#include <map>

#include "checker/semantic/body_checker.hpp"
#include "parser/diagnostic_codes.hpp"

namespace rung::check {
namespace {

using ast::VarSection;

// Which sections each kind of POU may declare (IEC 61131-3 table 13 and CODESYS V3).
bool section_allowed(SymbolKind kind, VarSection section, const Profile& profile) {
  switch (section) {
    case VarSection::Var:
    case VarSection::Unknown:
      return kind != SymbolKind::Interface;
    case VarSection::Input:
    case VarSection::InOut:
      if (kind == SymbolKind::Program) return profile.program_parameters;
      return kind != SymbolKind::GlobalList && kind != SymbolKind::Action && kind != SymbolKind::Transition;
    case VarSection::Output:
      if (kind == SymbolKind::Program) return profile.program_parameters;
      return kind != SymbolKind::GlobalList && kind != SymbolKind::Action && kind != SymbolKind::Transition;
    case VarSection::Temp:
      return kind != SymbolKind::GlobalList && kind != SymbolKind::Interface;
    case VarSection::Stat:
      return kind == SymbolKind::Function || kind == SymbolKind::Method || kind == SymbolKind::FunctionBlock;
    case VarSection::Inst:
      return kind == SymbolKind::Method;
    case VarSection::Global:
      return kind == SymbolKind::GlobalList || kind == SymbolKind::Configuration || kind == SymbolKind::Resource;
    case VarSection::External:
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
    if (symbol.kind == SymbolKind::DataType) check_type(symbol);
    if (symbol.kind == SymbolKind::FunctionBlock || symbol.kind == SymbolKind::Class) check_interfaces(symbol);
    if (is_pou_kind(symbol.kind)) check_bases(symbol);
    for (const Symbol* member : symbol.ordered) {
      if (is_pou_kind(member->kind)) check_symbol(*member);
    }
  }

  void check_variables(const Symbol& owner) {
    for (const Symbol* variable : owner.ordered) {
      if (variable->kind != SymbolKind::Variable) continue;
      if (!section_allowed(owner.kind, variable->section, model_.profile())) {
        report(codes::kSectionNotAllowed,
               fmt::format("a {} cannot declare {}", symbol_kind_name(owner.kind), ast::var_section_name(variable->section)),
               variable->name_range,
               owner.kind == SymbolKind::Program && !model_.profile().program_parameters
                   ? "this profile (OpenPCS) allows no parameters in a PROGRAM; use global variables"
                   : std::string());
      }
      if ((variable->has(kRetain) || variable->has(kPersistent)) &&
          (owner.kind == SymbolKind::Function || owner.kind == SymbolKind::Method ||
           variable->section == VarSection::Temp || variable->section == VarSection::InOut ||
           variable->section == VarSection::External)) {
        report(codes::kRetainNotAllowed,
               fmt::format("'{}' cannot be RETAIN/PERSISTENT here: {} variables live only during one call",
                           variable->name,
                           owner.kind == SymbolKind::Function || owner.kind == SymbolKind::Method
                               ? std::string(symbol_kind_name(owner.kind))
                               : std::string(ast::var_section_name(variable->section))),
               variable->name_range, "declare it in a PROGRAM, FUNCTION_BLOCK or global variable list");
      }
      check_variable_type(owner, *variable);
      if (variable->section == VarSection::External) check_external(*variable);
    }
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
    if (base->kind == TypeKind::Pou && base->declaration && base->declaration->kind == SymbolKind::FunctionBlock &&
        owner.kind == SymbolKind::Function && variable.section != VarSection::InOut &&
        variable.section != VarSection::Input) {
      // IEC: functions have no state, so no FB instances (CODESYS accepts it with a warning).
    }
    // The initial value must fit the type.
    if (SyntaxNode value = variable.node.child_by_field("value"); value && !variable.name.empty()) {
      if (value.kind() == "array_initializer" || value.kind() == "struct_initializer" ||
          value.kind() == "repeated_initializer") {
        return;
      }
      std::vector<Diagnostic> found;
      BodyChecker checker(model_, owner, found);
      ExprInfo info = checker.type_of(value);
      checker.check_conversion(info, type, value);
      // Only the first name of `a, b : INT := 300` reports, once.
      if (variable.node.children_by_field("name").front().range().begin == variable.name_range.begin) {
        out_.insert(out_.end(), found.begin(), found.end());
      }
    }
  }

  void check_external(const Symbol& variable) {
    const Symbol* global = model_.find_global_variable(variable.name);
    if (!global) {
      // A qualified_only list still provides VAR_EXTERNAL targets in CODESYS.
      for (SourceId id = 0; id < model_.source_count() && !global; ++id) {
        for (const Symbol* list : model_.source(id).symbols.global_lists) {
          if (const Symbol* found = list->own_member(variable.name)) global = found;
        }
      }
    }
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
                 fmt::format("'{}' has the same value ({}) as '{}'", value->name, int128_to_string(*number), it->second->name),
                 value->name_range, {}, {{it->second->name_range, "same value here"}});
        }
      }
    }
    if (type->kind == TypeKind::Struct || type->kind == TypeKind::Union) {
      for (const Symbol* field : type_symbol.ordered) {
        if (field->kind == SymbolKind::Variable) check_variable_type(type_symbol, *field);
      }
    }
    check_bases(type_symbol);
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
               fmt::format("a {} cannot extend the {} '{}'", symbol_kind_name(symbol.kind), symbol_kind_name(base->kind),
                           base->name),
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
                   block.interface_nodes[i].range(), fmt::format("add {} {} to {}", member->kind == SymbolKind::Method ? "METHOD" : "PROPERTY", member->name, block.name));
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
}

}  // namespace rung::check
