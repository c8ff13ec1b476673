#include "checker/query/rename.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <unordered_set>

#include "checker/query/container_names.hpp"
#include "checker/query/implementations.hpp"
#include "checker/query/position.hpp"
#include "checker/query/references.hpp"
#include "checker/query/resolve.hpp"
#include "checker/semantic/builtins.hpp"
#include "parser/keywords.hpp"

namespace rung::check::query {
namespace {

std::string file_name(const Document& document) {
  return std::filesystem::path(document.path()).filename().string();
}

// "FB_Motor.st:12": where a symbol is declared, for messages.
std::string where(const ProjectModel& model, const Symbol& symbol) {
  const Document& document = *model.source(symbol.source).document;
  return fmt::format("{}:{}", file_name(document), document.position_of_tree_offset(symbol.name_range.begin).line);
}

std::string_view spelled(const ProjectModel& model, const Location& location) {
  const std::string_view text = model.source(location.source).document->file_text();
  if (location.range.begin > location.range.end || location.range.end > text.size()) return {};
  return text.substr(location.range.begin, location.range.end - location.range.begin);
}

// What the cursor is on when it is on no name.
std::string describe_no_name(SyntaxNode root, uint32_t tree_offset) {
  SyntaxNode node = root.descendant_for_range(tree_offset, tree_offset + 1);
  if ((!node || node == root) && tree_offset > 0) node = root.descendant_for_range(tree_offset - 1, tree_offset);
  for (SyntaxNode at = node; at && at != root; at = at.parent()) {
    const std::string_view kind = at.kind();
    if (kind == "comment") return "this is a comment";
    if (kind == "pragma") return "this is a pragma";
    if (kind.ends_with("_literal")) return "this is a literal";
  }
  if (node && !node.is_named() && keywords::is_reserved(node.text())) {
    return fmt::format("'{}' is a keyword", node.text());
  }
  return "there is no name at this position";
}

// Why a name that refers to nothing cannot be renamed.
std::string describe_unresolved(NameUse use, std::string_view name) {
  if (use == NameUse::Other) {
    return fmt::format("'{}' is a label, step, task, resource or namespace, which rung does not rename", name);
  }
  if (keywords::is_reserved(name)) return fmt::format("'{}' is a keyword", name);
  if (find_builtin(name)) return fmt::format("'{}' is built into the compilers", name);
  return fmt::format("'{}' is not declared in the project", name);
}

// Why `symbol` cannot be renamed wherever it is used ("" when it can).
std::string symbol_refusal(const ProjectModel& model, const Symbol& symbol) {
  const Source& source = model.source(symbol.source);
  if (source.library) {
    return fmt::format("'{}' is declared in the standard library ({})", symbol.name, file_name(*source.document));
  }
  const Location declaration = declaration_location(model, symbol);
  if (names_equal(spelled(model, declaration), symbol.name)) return {};
  if (symbol.kind == SymbolKind::GlobalList && !source.document->container()) {
    return fmt::format("the global variable list '{}' is named after its file {}: rename the file instead", symbol.name,
                       file_name(*source.document));
  }
  return fmt::format("'{}' is named by the XML of {}, not by its code: rename it in the vendor's tool", symbol.name,
                     file_name(*source.document));
}

struct Site {
  SourceId source;
  SyntaxNode name;
  const Symbol* scope;
};

// The name node of a reference found by find_references.
std::optional<Site> site_of(const ProjectModel& model, const Location& location) {
  const Document& document = *model.source(location.source).document;
  const std::optional<uint32_t> tree_offset = document.tree_offset_of(location.range.begin);
  if (!tree_offset || !document.tree()) return std::nullopt;
  const SyntaxNode name = name_at(document.tree()->root(), *tree_offset);
  if (!name) return std::nullopt;
  return Site{location.source, name, scope_at(model, location.source, *tree_offset)};
}

class ClashFinder {
 public:
  ClashFinder(const ProjectModel& model, const std::vector<const Symbol*>& family, std::string_view new_name)
      : model_(model), family_(family.begin(), family.end()), new_name_(new_name) {}

  // Another declaration of the new name in the scope that declares `symbol`.
  std::string in_declaring_scope(const Symbol& symbol) const {
    if (const Symbol* owner = symbol.owner) {
      if (std::string clash = against(model_.find_member(owner, new_name_), owner->name); !clash.empty()) return clash;
      // A block that extends the owner and declares the name itself would hide the renamed member.
      if (owner->kind == SymbolKind::FunctionBlock || owner->kind == SymbolKind::Class ||
          owner->kind == SymbolKind::Interface) {
        for (const Symbol* derived : derived_blocks(model_, *owner)) {
          if (std::string clash = against(derived->own_member(new_name_), derived->name); !clash.empty()) return clash;
        }
      }
      if (owner->kind != SymbolKind::GlobalList || owner->has(kQualifiedOnly)) return {};
    }
    // Global names: POUs, types and lists share one namespace with unqualified global variables.
    if (std::string clash = against(model_.find_global(new_name_), "the project"); !clash.empty()) return clash;
    return against(model_.find_global_variable(new_name_), "the project");
  }

  // Another declaration the new name would mean, or be hidden by, where `site` names the symbol.
  std::string at_site(const Site& site) const {
    if (!site.scope) return {};
    const NameSite use = name_site(model_, site.source, site.name);
    const bool bare = (use.use == NameUse::Expression && use.expression == site.name) ||
                      use.use == NameUse::IlOperator || use.use == NameUse::Declaration;
    if (!bare) return {};
    return against(model_.lookup(site.scope, new_name_), site.scope->name);
  }

 private:
  std::string against(const Symbol* existing, std::string_view scope_name) const {
    if (!existing || family_.contains(existing) || family_.contains(canonical_symbol(model_, existing))) return {};
    if (model_.source(existing->source).library) {
      return fmt::format("'{}' is already the name of {} '{}' of the standard library ({})", new_name_,
                         symbol_kind_name(existing->kind), existing->name, where(model_, *existing));
    }
    return fmt::format("'{}' is already visible in {}: {} '{}' declared at {}", new_name_, scope_name,
                       symbol_kind_name(existing->kind), existing->name, where(model_, *existing));
  }

  const ProjectModel& model_;
  std::unordered_set<const Symbol*> family_;
  std::string_view new_name_;
};

}  // namespace

std::string identifier_problem(std::string_view name) {
  if (name.empty()) return "the new name is empty";
  if (keywords::is_reserved(name)) return fmt::format("'{}' is a keyword", name);
  // The grammar decides what an identifier is (letters of any script, digits, '_').
  const std::string text = fmt::format("PROGRAM {}\nEND_PROGRAM\n", name);
  const SyntaxTree tree = SyntaxTree::parse(text);
  const SyntaxNode root = tree.root();
  constexpr uint32_t kNameAt = 8;  // after "PROGRAM "
  const SyntaxNode parsed = root ? name_at(root, kNameAt) : SyntaxNode();
  if (!parsed || root.has_error() || parsed.begin() != kNameAt || parsed.end() != kNameAt + name.size() ||
      parsed.kind() != "identifier") {
    return fmt::format("'{}' is not an IEC 61131-3 identifier (letters, digits and '_', starting with a letter or '_')",
                       name);
  }
  if (name.find("__") != std::string_view::npos) {
    return fmt::format("'{}' has two '_' in a row, which IEC 61131-3 does not allow in names", name);
  }
  return {};
}

RenameTarget rename_target(const Workspace& workspace, SourceId source, uint32_t file_offset) {
  const ProjectModel& model = workspace.model();
  RenameTarget target;
  const std::optional<QueryPoint> point = query_point(workspace, source, file_offset);
  if (!point) {
    target.refusal = "there is no code at this position";
    return target;
  }
  if (!point->name) {
    target.refusal = describe_no_name(model.source(source).document->tree()->root(), point->tree_offset);
    return target;
  }
  const Symbol* symbol = resolve_name(model, source, point->name, point->scope);
  if (!symbol) {
    target.refusal = describe_unresolved(name_site(model, source, point->name).use, point->name.text());
    return target;
  }
  target.refusal = symbol_refusal(model, *symbol);
  if (!target.refusal.empty()) return target;
  target.name = location_in_file(model, source, point->name.range());
  const std::string_view at_cursor = spelled(model, target.name);
  if (!names_equal(at_cursor, symbol->name)) {
    target.refusal = fmt::format("'{}' is not written in the code here: rename it where it is declared", symbol->name);
    return target;
  }
  target.symbol = symbol;
  target.placeholder = std::string(at_cursor);
  return target;
}

RenamePlan plan_rename(const Workspace& workspace, const Symbol& symbol, std::string_view new_name) {
  const ProjectModel& model = workspace.model();
  RenamePlan plan;
  if (plan.refusal = identifier_problem(new_name); !plan.refusal.empty()) return plan;
  const std::vector<const Symbol*> family = member_family(model, *canonical_symbol(model, &symbol));
  const ClashFinder clashes(model, family, new_name);
  for (const Symbol* member : family) {
    if (plan.refusal = symbol_refusal(model, *member); !plan.refusal.empty()) return plan;
    if (plan.refusal = clashes.in_declaring_scope(*member); !plan.refusal.empty()) return plan;
    for (const Location& reference : find_references(workspace, member, true)) {
      if (!names_equal(spelled(model, reference), member->name)) {
        const Document& document = *model.source(reference.source).document;
        plan.refusal =
            fmt::format("'{}' at {}:{} is not written in the code: rename it in the vendor's tool", member->name,
                        file_name(document), document.position_of_file_offset(reference.range.begin).line);
        return plan;
      }
      if (const std::optional<Site> site = site_of(model, reference)) {
        if (plan.refusal = clashes.at_site(*site); !plan.refusal.empty()) return plan;
      }
      plan.edits.push_back({reference, std::string(new_name)});
    }
    // TwinCAT keeps the name of an object (POU, DUT, method, ...) in its XML element too.
    if (is_pou_kind(member->kind) || member->kind == SymbolKind::DataType) {
      const Document& declaring = *model.source(member->source).document;
      const Location declaration = declaration_location(model, *member);
      if (const auto attribute = twincat_name_attribute(declaring, declaration.range.begin, member->name)) {
        plan.edits.push_back({Location{member->source, declaring.path(), *attribute}, std::string(new_name)});
      }
    }
  }
  std::sort(plan.edits.begin(), plan.edits.end(), [](const TextEdit& a, const TextEdit& b) {
    return a.location.path != b.location.path ? a.location.path < b.location.path
                                              : a.location.range.begin < b.location.range.begin;
  });
  plan.edits.erase(std::unique(plan.edits.begin(), plan.edits.end(),
                               [](const TextEdit& a, const TextEdit& b) {
                                 return a.location.path == b.location.path &&
                                        a.location.range.begin == b.location.range.begin;
                               }),
                   plan.edits.end());
  return plan;
}

}  // namespace rung::check::query
