// L005 name-too-short and L006 name-case-mismatch: names that say little, and names written with
// other upper/lower case than where they are declared.
#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <mutex>
#include <set>
#include <tuple>
#include <unordered_map>
#include <unordered_set>

#include "checker/lint/naming_rules.hpp"
#include "checker/lint/structure_pou.hpp"
#include "checker/query/resolve.hpp"

namespace rung::lint::naming {
namespace {

using check::Symbol;

// Upper-case names of the FOR loop counters in the POU's own body (`nodes`: its file's nodes).
std::set<std::string> for_counters(const NodeList& nodes, const Symbol& pou) {
  static const TSFieldId kVariable = NodeList::field_id("variable");
  std::set<std::string> counters;
  for (SyntaxNode body : bodies_of(pou)) {
    nodes.walk(nodes.index_of(body), [&](uint32_t i) {
      if (nodes.is_extra(i)) return false;
      if (nodes.kind(i) == "for_statement") {
        if (const uint32_t variable = nodes.child_by_field(i, kVariable); variable != NodeList::kNone) {
          counters.insert(check::upper_name(nodes.text(variable)));
        }
      }
      return nodes.has_children(i);
    });
  }
  return counters;
}

// The names programmers use for loop counters and indices everywhere: short by tradition.
bool is_counter_name(std::string_view name) {
  for (std::string_view counter : {"i", "j", "k", "n"}) {
    if (check::names_equal(name, counter)) return true;
  }
  return false;
}

// Parameter names of the IEC 61131-3 standard function blocks and functions (TON: IN, PT, Q, ET;
// CTUD: CU, CD, R, LD, PV, QU, QD, CV; SR/RS: S1, R, S, R1; R_TRIG: CLK; LIMIT: MN, MX; SEL: G;
// MUX: K; MID: L, P; SHL: N; EN/ENO). A POU that mirrors a standard interface keeps its names.
bool is_standard_parameter_name(std::string_view name) {
  for (std::string_view standard : {"IN", "PT", "Q",  "ET",  "CU", "CD", "R", "LD", "PV", "QU", "QD", "CV", "S1",
                                    "S",  "R1", "Q1", "CLK", "MN", "MX", "G", "K",  "L",  "P",  "N",  "EN", "ENO"}) {
    if (check::names_equal(name, standard)) return true;
  }
  return false;
}

bool is_parameter(const Symbol& variable) {
  return variable.section == ast::VarSection::Input || variable.section == ast::VarSection::Output ||
         variable.section == ast::VarSection::InOut;
}

}  // namespace

bool LoopCounters::contains(const Symbol& variable) {
  const Symbol* owner = variable.owner;
  if (!owner || !check::is_pou_kind(owner->kind)) return false;
  auto found = by_pou_.find(owner);
  if (found == by_pou_.end()) found = by_pou_.emplace(owner, for_counters(nodes_, *owner)).first;
  return found->second.count(check::upper_name(variable.name)) > 0;
}

void check_name_too_short(LintContext& context) {
  const int64_t minimum = context.threshold("min_name_length", 3);
  const auto too_short = [&](std::string_view name) {
    return !name.empty() && static_cast<int64_t>(name.size()) < minimum;
  };
  const std::string help = fmt::format(
      "a name that says what the value or POU is explains the code without comments (FOR loop counters and "
      "the standard parameter names IN, PT, Q ... are exempt); rung.toml [lint.thresholds] min_name_length = {} sets "
      "the minimum",
      minimum);
  const auto report = [&](std::string_view what, std::string_view name, TextRange range) {
    context.report("L005", fmt::format("{} '{}' is shorter than {} characters", what, name, minimum), range, help);
  };

  LoopCounters counters(context.nodes());
  for (const Symbol* variable : named_variables(context)) {
    if (!too_short(variable->name) || is_counter_name(variable->name) || counters.contains(*variable)) continue;
    if (is_parameter(*variable) && is_standard_parameter_name(variable->name)) continue;
    report("variable", variable->name, variable->name_range);
  }
  for (const Symbol* pou : context.pous()) {
    if (too_short(pou->name) && !signature_is_given(context.model(), *pou)) {
      report(pou_kind_label(*pou), pou->name, pou->name_range);
    }
  }
  if (const SyntaxNode root = context.root()) {
    for (const ast::TypeDeclaration& type : ast::outline(root).types) {
      const SyntaxNode name = type.node().child_by_field("name");
      if (name && !name.is_missing() && too_short(name.text())) report("type", name.text(), name.range());
    }
  }
}

namespace {

// What a name resolves to depends on its scope, how it is used, and the expression around it
// (obj.name, E#name): resolutions are cached under all three, so each distinct name of a POU is
// looked up once.
using ResolutionKey = std::tuple<const Symbol*, int, std::string, uint32_t>;

bool opens_scope(const Symbol& symbol) {
  return check::is_pou_kind(symbol.kind) || symbol.kind == check::SymbolKind::DataType ||
         symbol.kind == check::SymbolKind::GlobalList || symbol.kind == check::SymbolKind::Configuration;
}

// The scope around each name of a walk in text order: the innermost declaration that contains it,
// as query::scope_at finds it, kept on a stack instead of searched for every name (scope_at looks
// through every top-level declaration of the file).
class ScopeTracker {
 public:
  explicit ScopeTracker(const check::FileSymbols& symbols) {
    for (const Symbol* top : symbols.top_level) add(*top);
    std::sort(scopes_.begin(), scopes_.end(), [](const Symbol* a, const Symbol* b) {
      if (a->node.begin() != b->node.begin()) return a->node.begin() < b->node.begin();
      return a->node.end() > b->node.end();  // the outer one first
    });
  }

  const Symbol* at(uint32_t offset) {
    while (!stack_.empty() && stack_.back()->node.end() <= offset) stack_.pop_back();
    for (; next_ < scopes_.size() && scopes_[next_]->node.begin() <= offset; ++next_) {
      const Symbol* scope = scopes_[next_];
      if (scope->node.end() <= offset) continue;
      while (!stack_.empty() && stack_.back()->node.end() <= scope->node.begin()) stack_.pop_back();
      stack_.push_back(scope);
    }
    return stack_.empty() ? nullptr : stack_.back();
  }

 private:
  void add(const Symbol& symbol) {
    if (!opens_scope(symbol) || !symbol.node) return;
    scopes_.push_back(&symbol);
    for (const Symbol* member : symbol.ordered) add(*member);
  }

  std::vector<const Symbol*> scopes_;  // by start, outer before inner
  size_t next_ = 0;
  std::vector<const Symbol*> stack_;
};

}  // namespace

void check_name_case(LintContext& context) {
  const NodeList& nodes = context.nodes();
  if (nodes.empty()) return;
  const check::ProjectModel& model = context.model();
  const check::SourceId id = context.source_id();
  // Only a name that some project declaration spells otherwise can be reported: the others are
  // passed over without resolving them.
  const ProjectIndex& spellings = context.cache().index(model);
  // Declaring name tokens are where the spelling comes from; they are skipped without asking.
  std::unordered_set<uint32_t> declarations;
  for (const Symbol& symbol : context.source().symbols.storage) declarations.insert(symbol.name_range.begin);

  std::map<ResolutionKey, const Symbol*> resolved;
  ScopeTracker scopes(context.source().symbols);
  nodes.walk(0, [&](uint32_t i) {
    if (nodes.is_extra(i)) return false;
    if (nodes.kind(i) != "identifier") return nodes.has_children(i);
    if (!spellings.spelled_otherwise(nodes.text(i))) return false;
    if (declarations.count(nodes.begin(i)) || nodes.is_missing(i)) return false;
    const SyntaxNode node = nodes.node(i);
    const Symbol* scope = scopes.at(node.begin());
    const check::query::NameSite site = check::query::name_site(model, id, node);
    if (site.use == check::query::NameUse::Declaration || site.use == check::query::NameUse::Other) return false;
    const Symbol* target = nullptr;
    if (site.use == check::query::NameUse::Expression || site.use == check::query::NameUse::TypeName) {
      const SyntaxNode around = site.expression ? site.expression : node;
      ResolutionKey key{scope, static_cast<int>(site.use), check::upper_name(around.text()),
                        node.begin() - around.begin()};
      auto found = resolved.find(key);
      if (found == resolved.end()) {
        found = resolved.emplace(std::move(key), check::query::resolve_name(model, id, node, scope)).first;
      }
      target = found->second;
    } else {
      target = check::query::resolve_name(model, id, node, scope);
    }
    // Library stubs spell standard names their own way (TON, ton): only project declarations
    // set a spelling.
    if (!target || target->name.empty() || target->has(check::kLibrary) || model.source(target->source).library) {
      return false;
    }
    const std::string_view written = node.text();
    if (written == target->name || !check::names_equal(written, target->name)) return false;
    Fix fix{fmt::format("write '{}'", target->name), {TextEdit{node.range(), std::string(target->name)}}};
    context.report("L006", fmt::format("'{}' is declared as '{}'", written, target->name), node.range(),
                   "IEC 61131-3 ignores case, but one spelling per name keeps the code searchable and readable",
                   std::move(fix));
    return false;
  });
}

}  // namespace rung::lint::naming
