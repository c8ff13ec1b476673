#include "checker/lint/usage_flow.hpp"

#include <algorithm>
#include <unordered_map>

namespace rung::lint {
namespace {

constexpr int kMaxNesting = 200;  // deeper bodies are left alone (the stack stays bounded)

// Which candidates are definitely assigned on every path that reaches a point.
struct State {
  std::vector<char> assigned;
  bool reachable = true;
};

State unreachable_state() {
  return State{.reachable = false};
}

// Where two paths meet: assigned on both. An unreachable path (after RETURN) adds nothing.
State join(const State& a, const State& b) {
  if (!a.reachable) return b;
  if (!b.reachable) return a;
  State out = a;
  for (size_t i = 0; i < out.assigned.size(); ++i) out.assigned[i] = a.assigned[i] && b.assigned[i];
  return out;
}

bool writes(const Use& use) {
  return (use.flags & (kUseWrite | kUseInOut | kUseAddress)) != 0;
}

// A read of the value: passing to a VAR_IN_OUT or taking the address is not (the callee or the
// pointer may be what assigns it).
bool reads(const Use& use) {
  return (use.flags & kUseRead) != 0 && (use.flags & (kUseInOut | kUseAddress)) == 0;
}

class DefiniteAssignment {
 public:
  DefiniteAssignment(const check::ProjectModel& model, const check::Symbol& pou, const FileUsage& usage,
                     std::span<const check::Symbol* const> candidates)
      : model_(model), pou_(pou), usage_(usage), candidates_(candidates.begin(), candidates.end()) {
    for (size_t i = 0; i < candidates_.size(); ++i) index_.emplace(candidates_[i], static_cast<int>(i));
    suppressed_.assign(candidates_.size(), 0);
    reported_.assign(candidates_.size(), 0);
  }

  std::vector<EarlyRead> run(SyntaxNode body) {
    State state{.assigned = std::vector<char>(candidates_.size(), 0)};
    statement_list(body, state, 0);
    if (gave_up_) return {};
    std::sort(found_.begin(), found_.end(),
              [](const EarlyRead& a, const EarlyRead& b) { return a.where.begin < b.where.begin; });
    return found_;
  }

 private:
  int index_of(const check::Symbol* symbol) const {
    auto found = index_.find(symbol);
    return found == index_.end() ? -1 : found->second;
  }

  // The reads of the names in `range`, then their writes: `x := x + 1` reads x first, and a
  // call's outputs are written after its inputs are read.
  void uses(TextRange range, State& state, bool check_reads = true) {
    const std::span<const Use> inside = usage_.uses_in(range);
    if (check_reads && state.reachable) {
      for (const Use& use : inside) {
        const int index = index_of(use.symbol);
        if (index < 0 || !reads(use) || use.scope != &pou_) continue;
        if (state.assigned[index] || suppressed_[index] || reported_[index]) continue;
        reported_[index] = 1;
        found_.push_back({candidates_[index], use.range});
      }
    }
    for (const Use& use : inside) {
      const int index = index_of(use.symbol);
      if (index >= 0 && writes(use) && state.reachable) state.assigned[index] = 1;
    }
  }

  void uses(SyntaxNode node, State& state, bool check_reads = true) {
    if (node) uses(node.range(), state, check_reads);
  }

  void statement_list(SyntaxNode list, State& state, int depth) {
    if (!list) return;
    for (SyntaxNode child : list.named_children()) {
      if (!child.is_extra()) statement(child, state, depth + 1);
    }
  }

  void statement(SyntaxNode node, State& state, int depth) {
    if (depth > kMaxNesting) {
      gave_up_ = true;
      return;
    }
    switch (ast::statement_kind(node)) {
      case ast::StatementKind::If: return if_statement(node, state, depth);
      case ast::StatementKind::Case: return case_statement(node, state, depth);
      case ast::StatementKind::For: return for_statement(node, state, depth);
      case ast::StatementKind::While: {
        uses(node.child_by_field("condition"), state);
        State after_body = loop_body(node, node.child_by_field("body"), state, depth);
        static_cast<void>(after_body);  // the loop may run zero times: the state before it stays
        return;
      }
      case ast::StatementKind::Repeat: return repeat_statement(node, state, depth);
      case ast::StatementKind::Exit:
      case ast::StatementKind::Continue: leave_iteration(state); return;
      case ast::StatementKind::Return:
        if (SyntaxNode condition = node.child_by_field("condition")) {
          uses(condition, state);  // RETURN (bDone): leaves only when the condition holds
        } else {
          state.reachable = false;
        }
        return;
      case ast::StatementKind::Try: return try_statement(node, state, depth);
      case ast::StatementKind::Empty:
      case ast::StatementKind::Jump:
      case ast::StatementKind::Label: return;
      default: return uses(node, state);
    }
  }

  void if_statement(SyntaxNode node, State& state, int depth) {
    uses(node.child_by_field("condition"), state);
    State merged = state;
    statement_list(node.child_by_field("body"), merged, depth);
    bool has_else = false;
    for (SyntaxNode clause : node.named_children()) {
      if (clause.kind() == "elsif_clause") {
        uses(clause.child_by_field("condition"), state);
        State branch = state;
        statement_list(clause.child_by_field("body"), branch, depth);
        merged = join(merged, branch);
      } else if (clause.kind() == "else_clause") {
        has_else = true;
        State branch = state;
        statement_list(clause.child_by_field("body"), branch, depth);
        merged = join(merged, branch);
      }
    }
    if (!has_else) merged = join(merged, state);  // no branch taken
    state = std::move(merged);
  }

  void case_statement(SyntaxNode node, State& state, int depth) {
    uses(node.child_by_field("value"), state);
    State merged = unreachable_state();
    bool has_else = false;
    for (SyntaxNode element : node.named_children()) {
      if (element.kind() != "case_element" && element.kind() != "else_clause") continue;
      has_else = has_else || element.kind() == "else_clause";
      State branch = state;
      statement_list(element.child_by_field("body"), branch, depth);
      merged = join(merged, branch);
    }
    if (!has_else) merged = join(merged, state);  // no label matched
    state = std::move(merged);
  }

  void for_statement(SyntaxNode node, State& state, int depth) {
    uses(node.child_by_field("start"), state);
    uses(node.child_by_field("end"), state);
    uses(node.child_by_field("step"), state);
    uses(node.child_by_field("variable"), state, /*check_reads=*/false);  // FOR i := ... assigns i
    State after_body = loop_body(node, node.child_by_field("body"), state, depth);
    if (runs_at_least_once(node)) state = std::move(after_body);
  }

  void repeat_statement(SyntaxNode node, State& state, int depth) {
    // The body runs once before UNTIL is tested; the test sees what the body assigned.
    State after_body = loop_body(node, node.child_by_field("body"), state, depth, node.child_by_field("condition"));
    state = std::move(after_body);
  }

  void try_statement(SyntaxNode node, State& state, int depth) {
    State merged = state;
    statement_list(node.child_by_field("body"), merged, depth);
    for (SyntaxNode clause : node.named_children()) {
      if (clause.kind() == "catch_clause") {
        State branch = state;  // the exception may come before any statement of the body ran
        uses(clause.child_by_field("exception"), branch, /*check_reads=*/false);
        statement_list(clause.child_by_field("body"), branch, depth);
        merged = join(merged, branch);
      } else if (clause.kind() == "finally_clause") {
        statement_list(clause.child_by_field("body"), merged, depth);
      }
    }
    state = std::move(merged);
  }

  // The state when the loop is left after running its body at least once: the end of the body
  // joined with every EXIT and CONTINUE. Reads inside the loop of variables the loop writes are
  // not reported (a previous iteration may have written them). `condition` is REPEAT's UNTIL.
  State loop_body(SyntaxNode loop, SyntaxNode body, const State& before, int depth, SyntaxNode condition = {}) {
    std::vector<int> pushed;
    for (const Use& use : usage_.uses_in(loop.range())) {
      const int index = index_of(use.symbol);
      if (index >= 0 && writes(use)) {
        ++suppressed_[index];
        pushed.push_back(index);
      }
    }
    leaving_.push_back(unreachable_state());
    State inside = before;
    statement_list(body, inside, depth);
    State left = join(inside, leaving_.back());
    leaving_.pop_back();
    if (condition) uses(condition, left);
    for (const int index : pushed) --suppressed_[index];
    return left;
  }

  void leave_iteration(State& state) {
    if (!leaving_.empty()) leaving_.back() = join(leaving_.back(), state);
    state.reachable = false;
  }

  // FOR i := 1 TO 10: constant bounds that let the body run at least once.
  bool runs_at_least_once(SyntaxNode node) const {
    const auto start = model_.constant_value(node.child_by_field("start"), &pou_);
    const auto end = model_.constant_value(node.child_by_field("end"), &pou_);
    if (!start || !end || !start->is_integer() || !end->is_integer()) return false;
    __int128 step = 1;
    if (SyntaxNode step_node = node.child_by_field("step")) {
      const auto value = model_.constant_value(step_node, &pou_);
      if (!value || !value->is_integer() || value->integer == 0) return false;
      step = value->integer;
    }
    return step > 0 ? start->integer <= end->integer : start->integer >= end->integer;
  }

  const check::ProjectModel& model_;
  const check::Symbol& pou_;
  const FileUsage& usage_;
  std::vector<const check::Symbol*> candidates_;
  std::unordered_map<const check::Symbol*, int> index_;
  std::vector<int> suppressed_;  // per candidate: enclosing loops that write it
  std::vector<char> reported_;   // one finding per variable
  std::vector<State> leaving_;   // per enclosing loop: the states at its EXITs and CONTINUEs
  std::vector<EarlyRead> found_;
  bool gave_up_ = false;
};

// Bodies whose paths the statement tree does not show: jumps and labels, and syntax errors.
bool has_untracked_flow(SyntaxNode body) {
  if (body.has_error()) return true;
  bool found = false;
  walk_preorder(body, [&](SyntaxNode node) {
    if (found) return false;
    const std::string_view kind = node.kind();
    if (kind == "jmp_statement" || kind == "label") found = true;
    return !found && node.is_named();
  });
  return found;
}

}  // namespace

std::vector<EarlyRead> reads_before_write(const check::ProjectModel& model, const check::Symbol& pou,
                                          const FileUsage& usage, std::span<const check::Symbol* const> candidates) {
  if (candidates.empty() || !pou.node) return {};
  SyntaxNode body = pou.node.child_by_field("body");
  if (!body || body.kind() != "statement_list" || has_untracked_flow(body)) return {};
  return DefiniteAssignment(model, pou, usage, candidates).run(body);
}

}  // namespace rung::lint
