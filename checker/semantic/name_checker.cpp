#include "checker/semantic/name_checker.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <unordered_map>

#include "parser/diagnostic_codes.hpp"

namespace rung::check {
namespace {

bool is_pou_or_type(SymbolKind kind) {
  return kind == SymbolKind::DataType || kind == SymbolKind::FunctionBlock || kind == SymbolKind::Interface ||
         kind == SymbolKind::Class || kind == SymbolKind::Program || kind == SymbolKind::Function;
}

class NameChecker {
 public:
  NameChecker(const ProjectModel& model, SourceId source, std::vector<Diagnostic>& out)
      : model_(model), source_(source), out_(out) {}

  void run() {
    check_top_level_names();
    for (const Symbol* symbol : model_.source(source_).symbols.top_level) check_scope(*symbol);
  }

 private:
  void report(std::string_view code, std::string message, TextRange range, std::string help = {},
              std::vector<DiagnosticLabel> labels = {}) {
    out_.push_back(make_diagnostic(code, std::move(message), range, std::move(help), std::move(labels)));
  }

  // POUs and types share one namespace: PROGRAM Motor next to TYPE Motor is a clash. Names of
  // different files are compared when the project is linked; this is the same-file case.
  void check_top_level_names() {
    std::vector<const Symbol*> declared;
    for (const Symbol* symbol : model_.source(source_).symbols.top_level) {
      if (!symbol->name.empty() && is_pou_or_type(symbol->kind)) declared.push_back(symbol);
    }
    // The collector lists POUs before types: the later one in the text is the duplicate.
    std::sort(declared.begin(), declared.end(),
              [](const Symbol* a, const Symbol* b) { return a->name_range.begin < b->name_range.begin; });
    std::unordered_map<std::string_view, const Symbol*, NameHash, NameEqual> seen;
    for (const Symbol* symbol : declared) {
      auto [it, inserted] = seen.emplace(symbol->name, symbol);
      if (inserted) continue;
      report(codes::kDuplicateDeclaration,
             fmt::format("'{}' is already declared as a {}", symbol->name, symbol_kind_name(it->second->kind)),
             symbol->name_range, "POUs and data types share one namespace: rename one of them",
             {{it->second->name_range, "first declared here"}});
    }
  }

  void check_scope(const Symbol& scope) {
    if (is_pou_kind(scope.kind) || scope.kind == SymbolKind::GlobalList) {
      check_variable_names(scope);
      check_enumerators(scope);
    }
    if (scope.base && (scope.kind == SymbolKind::FunctionBlock || scope.kind == SymbolKind::Class)) {
      check_inherited_names(scope);
    }
    for (const Symbol* member : scope.ordered) {
      if (is_pou_kind(member->kind)) check_scope(*member);
    }
  }

  // In one namespace for POUs, types and variables (OpenPCS), a variable named like a POU or a
  // type (S3046) or a local with the name of a global variable (linker L10001). CODESYS lets a
  // local hide them: the textbook's own example 5.69 declares `tof : TOD`.
  void check_variable_names(const Symbol& scope) {
    if (!model_.profile().unique_names) return;
    for (const Symbol* variable : scope.ordered) {
      // A VAR_EXTERNAL repeats the name of its VAR_GLOBAL, which is where a clash is reported.
      if (variable->kind != SymbolKind::Variable || variable->name.empty() ||
          variable->section == ast::VarSection::External) {
        continue;
      }
      if (const Symbol* global = model_.find_global(variable->name);
          global && global != &scope && is_pou_or_type(global->kind)) {
        std::vector<DiagnosticLabel> labels;
        if (global->source == source_) labels.push_back({global->name_range, "declared here"});
        report(codes::kWrongKindOfName,
               fmt::format("'{}' is the name of a {}{}: it cannot also name a variable", variable->name,
                           global->has(kLibrary) ? "standard " : "", symbol_kind_name(global->kind)),
               variable->name_range, "rename the variable", std::move(labels));
        continue;
      }
      if (scope.kind == SymbolKind::GlobalList) continue;
      if (const Symbol* global = model_.find_global_variable(variable->name)) {
        std::vector<DiagnosticLabel> labels;
        if (global->source == source_) labels.push_back({global->name_range, "the global variable"});
        report(codes::kDuplicateDeclaration,
               fmt::format("'{}' is also a global variable: in this profile a local cannot hide it", variable->name),
               variable->name_range, "declare it VAR_EXTERNAL to use the global, or rename the local",
               std::move(labels));
      }
    }
  }

  // `FUNCTION_BLOCK fbB EXTENDS fbA` may not declare a variable fbA already has.
  void check_inherited_names(const Symbol& block) {
    for (const Symbol* variable : block.ordered) {
      if (variable->kind != SymbolKind::Variable || variable->name.empty()) continue;
      const Symbol* inherited = model_.find_member(block.base, variable->name);
      if (!inherited || inherited->kind != SymbolKind::Variable) continue;
      std::vector<DiagnosticLabel> labels;
      if (inherited->source == source_) labels.push_back({inherited->name_range, "inherited from here"});
      report(codes::kDuplicateDeclaration,
             fmt::format("'{}' is already declared in '{}', which '{}' extends", variable->name,
                         inherited->owner ? inherited->owner->name : block.base->name, block.name),
             variable->name_range, "use the inherited variable, or rename this one", std::move(labels));
    }
  }

  // Enumerators of the enumerations declared in one POU (inline in its variables or as its local
  // types) must differ: `red` of two enumerations is ambiguous there (CODESYS textbook, V2 rule).
  void check_enumerators(const Symbol& scope) {
    std::unordered_map<std::string_view, SyntaxNode, NameHash, NameEqual> seen;
    auto add = [&](SyntaxNode enumeration) {
      for (SyntaxNode value : enumeration.children_of_kind("enum_value")) {
        SyntaxNode name = value.child_by_field("name");
        if (!name) continue;
        auto [it, inserted] = seen.emplace(name.text(), name);
        if (inserted) continue;
        report(codes::kDuplicateDeclaration,
               fmt::format("'{}' is already a value of another enumeration in '{}'", name.text(), scope.name),
               name.range(), "rename one of the values, or declare the enumerations as named types",
               {{it->second.range(), "first declared here"}});
      }
    };
    for (const Symbol* member : scope.ordered) {
      if (member->kind == SymbolKind::DataType && member->node.kind() == "enum_type") add(member->node);
      if (member->kind != SymbolKind::Variable || !member->type_node || member->type_node.kind() != "enum_type")
        continue;
      // `a, b : (x, y)` declares one enumeration for both names.
      const std::vector<SyntaxNode> names = member->node.children_by_field("name");
      if (!names.empty() && names.front().range().begin == member->name_range.begin) add(member->type_node);
    }
  }

  const ProjectModel& model_;
  SourceId source_;
  std::vector<Diagnostic>& out_;
};

}  // namespace

void check_names(const ProjectModel& model, SourceId source, std::vector<Diagnostic>& out) {
  NameChecker(model, source, out).run();
}

}  // namespace rung::check
