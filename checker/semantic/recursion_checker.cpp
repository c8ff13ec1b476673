#include "checker/semantic/recursion_checker.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <deque>
#include <set>
#include <string>
#include <unordered_map>

#include "checker/project_model.hpp"
#include "parser/diagnostic_codes.hpp"
#include "parser/parallel_for.hpp"

namespace rung::check {
namespace {

// CODESYS V3 / TwinCAT compile recursive methods (see the header).
bool may_be_in_cycle(const ProjectModel& model, const Symbol* pou) {
  const project::Profile profile = model.profile().id;
  const bool methods_may_recurse = profile == project::Profile::Codesys || profile == project::Profile::Twincat;
  return !(methods_may_recurse && pou->kind == SymbolKind::Method);
}

class EdgeCollector {
 public:
  EdgeCollector(const ProjectModel& model, std::vector<CallEdge>& out) : model_(model), out_(out) {}

  void add_pou(const Symbol* pou) {
    collect_instances(pou);
    if (!pou->node) return;
    if (pou->node.kind() == "source_file") {  // a snippet's statements (file_symbols.cpp)
      for (SyntaxNode child : pou->node.named_children()) {
        if (child.kind() == "statement_list" || child.kind() == "il_body" || child.kind() == "sfc_network") {
          collect_calls(pou, child);
        }
      }
    } else if (SyntaxNode body = pou->node.child_by_field("body")) {
      collect_calls(pou, body);
    }
  }

 private:
  // VAR x : FB_Self; inside FB_Self (or through another block): an instance containing itself.
  void collect_instances(const Symbol* pou) {
    if (pou->kind != SymbolKind::FunctionBlock && pou->kind != SymbolKind::Program && pou->kind != SymbolKind::Class)
      return;
    for (const Symbol* member : pou->ordered) {
      if (member->kind != SymbolKind::Variable || !member->type_node) continue;
      if (member->section == ast::VarSection::InOut || member->section == ast::VarSection::External) continue;
      const Type* type = model_.type_of(member);
      // Arrays of instances contain them too; pointers and references do not.
      for (int depth = 0;
           depth < 16 && type && (type->kind == TypeKind::Array || type->kind == TypeKind::Alias) && type->element;
           ++depth) {
        type = type->element;
      }
      if (type && type->kind == TypeKind::Pou && type->declaration &&
          (type->declaration->kind == SymbolKind::FunctionBlock || type->declaration->kind == SymbolKind::Class)) {
        out_.push_back({pou, type->declaration, member->type_node.range(), true});
      }
    }
  }

  // Every call in the body: F(), fbInstance(), Program(), instance.Method(), Action().
  void collect_calls(const Symbol* pou, SyntaxNode body) {
    walk_preorder(body, [&](SyntaxNode node) {
      if (!node.is_named()) return false;
      if (node.kind() == "call_expression") {
        SyntaxNode function = node.child_by_field("function");
        if (const Symbol* callee = callee_of(pou, function)) out_.push_back({pou, callee, function.range(), false});
      }
      return true;
    });
  }

  const Symbol* pou_of_instance(const Symbol* variable) const {
    const Type* type = underlying(model_.type_of(variable));
    if (type && type->kind == TypeKind::Reference && type->element) type = underlying(type->element);
    if (type && type->kind == TypeKind::Pou) return type->declaration;
    return nullptr;
  }

  const Symbol* callee_of(const Symbol* pou, SyntaxNode function) const {
    if (!function) return nullptr;
    if (function.kind() == "identifier") {
      const Symbol* symbol = model_.lookup(pou, function.text());
      if (!symbol) return nullptr;
      if (symbol->kind == SymbolKind::Variable) return pou_of_instance(symbol);
      if (is_pou_kind(symbol->kind) && symbol->kind != SymbolKind::FunctionBlock) return symbol;
      return nullptr;
    }
    if (function.kind() == "member_expression") {
      // instance.Method() / instance.Action(): a variable of this POU whose type is a block.
      SyntaxNode object = function.child_by_field("object");
      SyntaxNode member = function.child_by_field("member");
      if (!object || !member || object.kind() != "identifier") return nullptr;
      const Symbol* variable = model_.lookup(pou, object.text());
      if (!variable || variable->kind != SymbolKind::Variable) return nullptr;
      const Symbol* block = pou_of_instance(variable);
      if (!block) return nullptr;
      const Symbol* target = model_.find_member(block, member.text());
      return target && is_pou_kind(target->kind) ? target : nullptr;
    }
    return nullptr;
  }

  const ProjectModel& model_;
  std::vector<CallEdge>& out_;
};

std::vector<CallEdge> edges_of_source(const ProjectModel& model, SourceId id) {
  std::vector<CallEdge> edges;
  const Source& source = model.source(id);
  if (source.library) return edges;
  const std::vector<const Symbol*> pous = pous_of(source.symbols);
  EdgeCollector collector(model, edges);
  for (const Symbol* pou : pous) collector.add_pou(pou);
  return edges;
}

// Strongly connected components (Tarjan, iterative) of one kind of edge.
class Components {
 public:
  Components(const std::unordered_map<const Symbol*, std::vector<const CallEdge*>>& graph) : graph_(graph) {
    for (const auto& [node, edges] : graph_) {
      if (!index_.count(node)) visit(node);
    }
  }
  int component(const Symbol* node) const {
    auto found = component_.find(node);
    return found == component_.end() ? -1 : found->second;
  }

 private:
  void visit(const Symbol* root) {
    struct Frame {
      const Symbol* node;
      size_t next_edge;
    };
    std::vector<Frame> frames{{root, 0}};
    enter(root);
    while (!frames.empty()) {
      Frame& frame = frames.back();
      const auto found = graph_.find(frame.node);
      const std::vector<const CallEdge*>* edges = found == graph_.end() ? nullptr : &found->second;
      if (edges && frame.next_edge < edges->size()) {
        const Symbol* next = (*edges)[frame.next_edge++]->to;
        if (!index_.count(next)) {
          enter(next);
          frames.push_back({next, 0});
        } else if (on_stack_.count(next)) {
          low_[frame.node] = std::min(low_[frame.node], index_[next]);
        }
        continue;
      }
      const Symbol* node = frame.node;
      frames.pop_back();
      if (!frames.empty()) low_[frames.back().node] = std::min(low_[frames.back().node], low_[node]);
      if (low_[node] == index_[node]) {
        const Symbol* member = nullptr;
        do {
          member = stack_.back();
          stack_.pop_back();
          on_stack_.erase(member);
          component_[member] = components_;
        } while (member != node);
        ++components_;
      }
    }
  }
  void enter(const Symbol* node) {
    index_[node] = low_[node] = counter_++;
    stack_.push_back(node);
    on_stack_.insert(node);
  }

  const std::unordered_map<const Symbol*, std::vector<const CallEdge*>>& graph_;
  std::unordered_map<const Symbol*, int> index_, low_, component_;
  std::set<const Symbol*> on_stack_;
  std::vector<const Symbol*> stack_;
  int counter_ = 0;
  int components_ = 0;
};

// The POUs from `start` back to `target` over `graph`, inside one component.
std::vector<const Symbol*> path_within(const std::unordered_map<const Symbol*, std::vector<const CallEdge*>>& graph,
                                       const Components& components, const Symbol* start, const Symbol* target) {
  const int component = components.component(start);
  std::unordered_map<const Symbol*, const Symbol*> parent{{start, nullptr}};
  std::deque<const Symbol*> queue{start};
  while (!queue.empty()) {
    const Symbol* node = queue.front();
    queue.pop_front();
    if (node == target) {
      std::vector<const Symbol*> chain;
      for (const Symbol* at = node; at; at = parent[at]) chain.push_back(at);
      std::reverse(chain.begin(), chain.end());
      return chain;
    }
    auto found = graph.find(node);
    if (found == graph.end()) continue;
    for (const CallEdge* edge : found->second) {
      if (components.component(edge->to) == component && parent.emplace(edge->to, node).second)
        queue.push_back(edge->to);
    }
  }
  return {};
}

std::string describe_cycle(const Symbol* from, const std::vector<const Symbol*>& path, bool instance) {
  std::string text(from->name);
  for (const Symbol* step : path) text += (instance ? " contains " : " calls ") + std::string(step->name);
  return text;
}

Diagnostic cycle_diagnostic(const CallEdge& edge, const std::vector<const Symbol*>& cycle) {
  const std::string_view name = edge.from->name;
  if (edge.instance) {
    return make_diagnostic(
        codes::kRecursion,
        cycle.size() == 1
            ? fmt::format("'{}' contains an instance of itself", name)
            : fmt::format("'{}' contains an instance of itself ({})", name, describe_cycle(edge.from, cycle, true)),
        edge.where, "an instance cannot contain itself: use a POINTER TO or REFERENCE TO it instead");
  }
  return make_diagnostic(codes::kRecursion,
                         cycle.size() == 1 ? fmt::format("'{}' calls itself: recursion is not allowed", name)
                                           : fmt::format("recursive call: {}", describe_cycle(edge.from, cycle, false)),
                         edge.where, "rewrite the recursion as a loop (FOR/WHILE with an explicit stack of values)");
}

}  // namespace

void RecursionIndex::rebuild(const ProjectModel& model) {
  edges_.assign(model.source_count(), {});
  parallel_for(model.source_count(), model.threads(),
               [&](size_t id) { edges_[id] = edges_of_source(model, static_cast<SourceId>(id)); });
  find_cycles(model);
}

void RecursionIndex::rebuild_source(const ProjectModel& model, SourceId id) {
  rebuild_sources(model, {id});
}

void RecursionIndex::rebuild_sources(const ProjectModel& model, const std::vector<SourceId>& ids) {
  if (edges_.size() != model.source_count()) return rebuild(model);
  // Most body edits (a keystroke) leave the file's calls as they were, only moved: then the
  // cycles are the same, and only this file's diagnostics could hold the old positions. The
  // project-wide search is skipped unless they do.
  const auto same_calls = [](const std::vector<CallEdge>& a, const std::vector<CallEdge>& b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](const CallEdge& x, const CallEdge& y) {
      return x.from == y.from && x.to == y.to && x.instance == y.instance;
    });
  };
  bool unchanged = true;
  for (const SourceId id : ids) {
    std::vector<CallEdge> fresh = edges_of_source(model, id);
    unchanged = unchanged && same_calls(edges_[id], fresh) && (id >= found_.size() || found_[id].empty());
    edges_[id] = std::move(fresh);
  }
  if (!unchanged) find_cycles(model);
}

const std::vector<Diagnostic>& RecursionIndex::diagnostics(SourceId id) const {
  static const std::vector<Diagnostic> kNone;
  return id < found_.size() ? found_[id] : kNone;
}

const std::vector<CallEdge>& RecursionIndex::edges(SourceId id) const {
  static const std::vector<CallEdge> kNone;
  return id < edges_.size() ? edges_[id] : kNone;
}

void RecursionIndex::find_cycles(const ProjectModel& model) {
  found_.assign(edges_.size(), {});
  for (const bool instances : {false, true}) {
    std::unordered_map<const Symbol*, std::vector<const CallEdge*>> graph;
    for (const auto& edges : edges_) {
      for (const CallEdge& edge : edges) {
        if (edge.instance != instances) continue;
        if (!may_be_in_cycle(model, edge.from) || !may_be_in_cycle(model, edge.to)) continue;
        graph[edge.from].push_back(&edge);
      }
    }
    const Components components(graph);
    for (const auto& [from, edges] : graph) {
      std::set<const Symbol*> reported;  // one diagnostic per callee of each POU
      for (const CallEdge* edge : edges) {
        const int component = components.component(from);
        if (component < 0 || components.component(edge->to) != component) continue;
        if (!reported.insert(edge->to).second || from->name.empty()) continue;
        std::vector<const Symbol*> cycle = path_within(graph, components, edge->to, from);
        if (!cycle.empty()) found_[from->source].push_back(cycle_diagnostic(*edge, cycle));
      }
    }
  }
  for (auto& diagnostics : found_) sort_diagnostics(diagnostics);
}

void check_recursion(const ProjectModel& model, SourceId source, std::vector<Diagnostic>& out) {
  const std::vector<Diagnostic>& found = model.recursion_index().diagnostics(source);
  out.insert(out.end(), found.begin(), found.end());
}

}  // namespace rung::check
