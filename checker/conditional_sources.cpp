#include "checker/conditional_sources.hpp"

#include <algorithm>
#include <optional>
#include <string>

#include "checker/project/conditional_compilation.hpp"

namespace rung::check {
namespace {

using project::DeclarationQuestion;

// The parts of a dotted name: "GVL.x" -> {"GVL", "x"}.
std::vector<std::string_view> name_parts(std::string_view name) {
  std::vector<std::string_view> parts;
  size_t begin = 0;
  for (size_t dot = name.find('.'); dot != std::string_view::npos; dot = name.find('.', begin)) {
    parts.push_back(name.substr(begin, dot - begin));
    begin = dot + 1;
  }
  parts.push_back(name.substr(begin));
  return parts;
}

// Answers the questions of one file's conditions from the linked model.
class Oracle {
 public:
  Oracle(const ProjectModel& model, SourceId source) : model_(model), source_(source) {}

  bool answer(const DeclarationQuestion& question) const {
    using Ask = DeclarationQuestion::Ask;
    using Kind = DeclarationQuestion::Kind;
    const Symbol* scope = scope_at(question.at);
    switch (question.kind) {
      case Kind::Variable: {
        const Symbol* variable =
            resolve(scope, question.name, [](const Symbol& s) { return s.kind == SymbolKind::Variable; });
        if (!variable) return false;
        if (question.ask == Ask::HasAttribute) return variable->attribute(question.argument) != nullptr;
        if (question.ask == Ask::HasType) return has_type(*variable, question.argument);
        return true;
      }
      case Kind::Pou: {
        // "POU or action": methods and actions are found through their owner (P.A) or from inside it.
        const Symbol* pou = resolve(scope, question.name, [](const Symbol& s) { return is_pou_kind(s.kind); });
        if (!pou) return false;
        return question.ask != Ask::HasAttribute || pou->attribute(question.argument) != nullptr;
      }
      case Kind::Type: return is_type(question.name);
      case Kind::Task: return configuration_has("task_configuration", question.name);
      case Kind::Resource:
        // CODESYS calls the objects below an application "resources" (the manual's example asks
        // for a global variable list); IEC RESOURCEs of a CONFIGURATION count too.
        if (const Symbol* global = model_.find_global(question.name);
            global && global->kind == SymbolKind::GlobalList) {
          return true;
        }
        return configuration_has("resource_declaration", question.name);
    }
    return false;
  }

 private:
  // The innermost POU of the file whose text holds `offset` (a snippet's unnamed PROGRAM too);
  // nullptr between POUs, where only global names are visible.
  const Symbol* scope_at(uint32_t offset) const {
    const Symbol* best = nullptr;
    for (const Symbol& symbol : model_.source(source_).symbols.storage) {
      if (!is_pou_kind(symbol.kind) || !symbol.node || offset < symbol.node.begin() || offset >= symbol.node.end())
        continue;
      if (!best || symbol.node.end() - symbol.node.begin() < best->node.end() - best->node.begin()) best = &symbol;
    }
    return best;
  }

  // A (dotted) name as code at `scope` would see it; the last part must satisfy `wanted`.
  template <typename Wanted>
  const Symbol* resolve(const Symbol* scope, std::string_view name, Wanted wanted) const {
    const std::vector<std::string_view> parts = name_parts(name);
    const Symbol* symbol = scope ? model_.lookup(scope, parts[0]) : nullptr;
    if (!symbol) symbol = model_.find_global_variable(parts[0]);
    if (!symbol) symbol = model_.find_global(parts[0]);
    for (size_t i = 1; symbol && i < parts.size(); ++i) symbol = model_.find_member(container_of(*symbol), parts[i]);
    return symbol && wanted(*symbol) ? symbol : nullptr;
  }

  // What the members of `symbol` belong to: a variable's type (an FB instance, a struct).
  const Symbol* container_of(const Symbol& symbol) const {
    if (symbol.kind != SymbolKind::Variable) return &symbol;
    const Type* type = underlying(model_.type_of(&symbol));
    return type ? type->declaration : nullptr;
  }

  bool is_type(std::string_view name) const {
    if (model_.types().elementary(name)) return true;
    const Symbol* symbol = model_.find_global(name);
    if (!symbol) return false;
    switch (symbol->kind) {
      case SymbolKind::DataType:
      case SymbolKind::FunctionBlock:
      case SymbolKind::Class:
      case SymbolKind::Interface: return true;
      default: return false;
    }
  }

  // hastype(variable: v, T): T an elementary type (any STRING(n) is a STRING), an ANY_* category
  // or a user type.
  bool has_type(const Symbol& variable, std::string_view type_name) const {
    const Type* type = model_.type_of(&variable);
    if (!type || type->is_unknown()) return false;
    const TypeArena& types = model_.types();
    if (const Type* category = types.generic(type_name)) return generic_accepts(category->generic, type);
    const Type* plain = underlying(type);
    if (const Type* elementary = types.elementary(type_name)) {
      if (elementary->kind == TypeKind::String || elementary->kind == TypeKind::WString)
        return plain->kind == elementary->kind;
      return plain == elementary;
    }
    const Symbol* declared = model_.find_global(type_name);
    return declared && model_.type_of(declared) == type;
  }

  // Whether a CONFIGURATION of the project declares a task or resource of that name.
  bool configuration_has(std::string_view node_kind, std::string_view name) const {
    for (SourceId id = 0; id < model_.source_count(); ++id) {
      for (const Symbol* top : model_.source(id).symbols.top_level) {
        if (top->kind != SymbolKind::Configuration) continue;
        std::vector<SyntaxNode> stack{top->node};
        while (!stack.empty()) {
          SyntaxNode node = stack.back();
          stack.pop_back();
          if (node.kind() == node_kind) {
            SyntaxNode declared = node.child_by_field("name");
            if (declared && names_equal(declared.text(), name)) return true;
          }
          for (uint32_t i = 0; i < node.named_child_count(); ++i) stack.push_back(node.named_child(i));
        }
      }
    }
    return false;
  }

  const ProjectModel& model_;
  SourceId source_;
};

// A file's conditional pragmas in its source text (the text as written, before any rewrite).
std::vector<project::ConditionalPragma> pragmas_of(const Document& document) {
  if (document.tree()->text() == document.source_text()) return project::find_conditional_pragmas(*document.tree());
  // Already rewritten, or read with only its first branches: the source text has them all.
  const SyntaxTree tree = SyntaxTree::parse(std::string(document.source_text()));
  return project::find_conditional_pragmas(tree);
}

}  // namespace

std::vector<SourceId> compile_conditionally(ProjectModel& model) {
  struct Candidate {
    SourceId id;
    std::vector<project::ConditionalPragma> pragmas;
  };
  std::vector<Candidate> candidates;
  for (SourceId id = 0; id < model.source_count(); ++id) {
    const Source& source = model.source(id);
    if (source.library || !source.document->tree()) continue;
    if (!project::may_have_conditional_pragmas(source.document->source_text())) continue;
    std::vector<project::ConditionalPragma> pragmas = pragmas_of(*source.document);
    if (!pragmas.empty()) candidates.push_back({id, std::move(pragmas)});
  }
  std::vector<SourceId> rewritten;
  for (int round = 0; round < kMaxConditionalRounds && !candidates.empty(); ++round) {
    // Every file is evaluated against the same linked model before any is replaced: replacing a
    // file frees its symbols, which the model's index points at until the next link().
    std::vector<std::pair<SourceId, std::string>> changes;
    for (const Candidate& candidate : candidates) {
      const Document& document = *model.source(candidate.id).document;
      const Oracle oracle(model, candidate.id);
      project::ConditionalResult result =
          project::evaluate_conditionals(document.source_text(), candidate.pragmas, model.profile().defines,
                                         [&](const DeclarationQuestion& question) { return oracle.answer(question); });
      if (result.text != document.tree()->text()) changes.emplace_back(candidate.id, std::move(result.text));
    }
    if (changes.empty()) break;
    for (auto& [id, text] : changes) {
      model.update_source(id, std::make_unique<Document>(model.source(id).document->reread(std::move(text))));
      if (std::find(rewritten.begin(), rewritten.end(), id) == rewritten.end()) rewritten.push_back(id);
    }
    model.link();
  }
  return rewritten;
}

}  // namespace rung::check
