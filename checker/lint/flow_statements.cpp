// Statements that do nothing or never end: L031 empty-statement, L035 self-assignment,
// L042 endless-loop.
#include <algorithm>
#include <string>

#include "checker/lint/flow_rules.hpp"
#include "checker/lint/flow_support.hpp"
#include "checker/query/position.hpp"
#include "checker/semantic/body_checker.hpp"
#include "checker/symbols/names.hpp"
#include "parser/ast.hpp"

namespace rung::lint::flow {
namespace {

// A fix that deletes `node` (its line too when it stands alone there).
Fix removal_fix(const LintContext& context, SyntaxNode node, std::string description) {
  return Fix{std::move(description), {TextEdit{removal_range(context.text(), node.range()), ""}}};
}

// --- L035 ---------------------------------------------------------------------------------------

// Whether writing `target` may do more than store a value: a property's SET (and its GET on the
// right) runs code, so `Prop := Prop;` is not a no-op.
bool accesses_property(check::BodyChecker& checker, SyntaxNode target) {
  bool property = false;
  std::vector<uint32_t> member_names;  // where the member identifiers of `obj.member` begin
  walk_preorder(target, [&](SyntaxNode node) {
    if (property || node.is_extra() || !node.is_named()) return false;
    const ast::ExpressionKind kind = ast::expression_kind(node);
    if (kind == ast::ExpressionKind::Member) {
      if (SyntaxNode member = node.child_by_field("member")) member_names.push_back(member.begin());
    }
    // `obj.member` is typed as a whole; its member identifier alone would be read as a local name.
    const bool typed = kind == ast::ExpressionKind::Member ||
                       (kind == ast::ExpressionKind::Identifier &&
                        std::find(member_names.begin(), member_names.end(), node.begin()) == member_names.end());
    if (typed) {
      const check::ExprInfo info = checker.type_of(node);
      property = info.symbol && info.symbol->kind == check::SymbolKind::Property;
    }
    return !property;
  });
  return property;
}

// --- L042 ---------------------------------------------------------------------------------------

bool is_loop(std::string_view kind) {
  return kind == "for_statement" || kind == "while_statement" || kind == "repeat_statement";
}

// Whether the body of `loop` (node `loop` of `nodes`) can leave it: RETURN or a jump anywhere in
// it, or an EXIT that is not inside a nested loop (there it leaves only the nested one).
bool can_leave(const NodeList& nodes, uint32_t loop) {
  static const TSFieldId kBody = NodeList::field_id("body");
  const uint32_t body = nodes.child_by_field(loop, kBody);
  if (body == NodeList::kNone) return false;
  bool leaves = false;
  for_each_of_kind(nodes, body, "return_statement", [&](uint32_t) { leaves = true; });
  for_each_of_kind(nodes, body, "jmp_statement", [&](uint32_t) { leaves = true; });
  nodes.walk(body, [&](uint32_t i) {
    if (leaves || nodes.is_extra(i) || !nodes.is_named(i)) return false;
    const std::string_view kind = nodes.kind(i);
    leaves = kind == "exit_statement";
    return !leaves && !is_loop(kind);
  });
  return leaves;
}

// TRUE or FALSE, as written (no constant folding: L039 covers constant conditions).
bool is_literal(SyntaxNode condition, std::string_view value) {
  return condition && condition.kind() == "boolean_literal" && check::names_equal(condition.text(), value);
}

}  // namespace

void check_endless_loop(LintContext& context) {
  const NodeList& nodes = context.nodes();
  nodes.walk(0, [&](uint32_t i) {
    if (nodes.is_extra(i)) return false;
    const std::string_view kind = nodes.kind(i);
    if (kind != "while_statement" && kind != "repeat_statement") return true;
    const SyntaxNode node = nodes.node(i);
    const SyntaxNode condition = node.child_by_field("condition");
    const bool endless = (kind == "while_statement" && is_literal(condition, "TRUE")) ||
                         (kind == "repeat_statement" && is_literal(condition, "FALSE"));
    if (endless && !is_broken(node) && !can_leave(nodes, i)) {
      const bool is_while = kind == "while_statement";
      context.report(
          "L042",
          std::string(is_while ? "WHILE TRUE" : "REPEAT ... UNTIL FALSE") + " loop without EXIT or RETURN never ends",
          is_while ? TextRange{node.begin(), condition.end()} : TextRange{node.begin(), node.begin() + 6},
          "the PLC cycle never finishes and the watchdog stops the controller: add an EXIT for when the "
          "work is done, or let the loop run once per cycle");
    }
    return true;
  });
}

void check_empty_statement(LintContext& context) {
  // Branch bodies made only of ';' with a comment in the branch: `99: (* error handling *) ;`
  // is an empty branch on purpose, and strict compilers want the ';' of an empty branch.
  std::vector<uint32_t> skipped;  // begins of such bodies (preorder: found before the body)
  // Statements outside any POU in a file that does not parse are prose or a fragment, not code.
  const SyntaxNode root = context.root();
  if (root && root.has_error()) {
    for (SyntaxNode child : root.named_children()) {
      if (child.kind() == "statement_list") skipped.push_back(child.begin());
    }
  }
  const NodeList& nodes = context.nodes();
  nodes.walk(0, [&](uint32_t i) {
    // Error recovery turns prose and broken code into runs of ';': judge only what parsed.
    if (nodes.is_extra(i) || nodes.is_error(i)) return false;
    const std::string_view kind = nodes.kind(i);
    if (kind == "if_statement" || kind == "case_statement") {
      const SyntaxNode node = nodes.node(i);
      for (const Branch& branch : branches_of(nodes, node)) {
        if (branch.body && is_empty_body(nodes, branch.body) && has_comment_in(nodes, node, branch.span)) {
          skipped.push_back(branch.body.begin());
        }
      }
    } else if (is_loop(kind)) {
      const SyntaxNode node = nodes.node(i);
      const SyntaxNode body = node.child_by_field("body");
      if (body && is_empty_body(nodes, body) && has_comment_in(nodes, node, node.range()))
        skipped.push_back(body.begin());
    }
    if (kind != "statement_list") return true;
    if (nodes.has_error(i) || std::find(skipped.begin(), skipped.end(), nodes.begin(i)) != skipped.end()) {
      return true;
    }
    uint32_t previous = NodeList::kNone;
    nodes.for_each_child(i, [&](uint32_t statement) {
      if (!nodes.is_named(statement) || nodes.is_extra(statement)) return;
      // `lbl: ;` gives a jump label at the end of a list the statement it needs.
      const bool after_label = previous != NodeList::kNone && nodes.kind(previous) == "label";
      previous = statement;
      if (nodes.kind(statement) != "empty_statement" || after_label) return;
      const SyntaxNode node = nodes.node(statement);
      context.report("L031", "stray ';': an empty statement that does nothing", node.range(),
                     "remove the ';' (END_IF; END_CASE; and the like are not empty statements); to leave a branch "
                     "empty on purpose, say so in a comment",
                     removal_fix(context, node, "remove the empty statement"));
    });
    return true;
  });
}

void check_self_assignment(LintContext& context) {
  static const TSFieldId kOperator = NodeList::field_id("operator");
  static const TSFieldId kLeft = NodeList::field_id("left");
  static const TSFieldId kRight = NodeList::field_id("right");
  const NodeList& nodes = context.nodes();
  for_each_of_kind(nodes, 0, "assignment_statement", [&](uint32_t i) {
    const uint32_t op = nodes.child_by_field(i, kOperator);
    const uint32_t left_index = nodes.child_by_field(i, kLeft);
    const uint32_t right_index = nodes.child_by_field(i, kRight);
    if (op == NodeList::kNone || nodes.text(op) != ":=" || !same_tokens(nodes, left_index, right_index)) return;
    const SyntaxNode statement = nodes.node(i);
    if (is_broken(statement)) return;
    const SyntaxNode left = nodes.node(left_index);
    // a[f()] := a[f()] calls f twice: the calls may matter.
    if (contains_call(nodes, left)) return;
    bool located = false;  // %MW10 := %MW10; or x := x; with x AT %MW10
    for_each_of_kind(nodes, left_index, "direct_variable", [&](uint32_t) { located = true; });
    if (const check::Symbol* scope = check::query::scope_at(context.model(), context.source_id(), statement.begin())) {
      std::vector<Diagnostic> ignored;
      check::BodyChecker checker(context.model(), *scope, ignored);
      if (accesses_property(checker, left)) return;
      const check::Symbol* target = checker.type_of(left).symbol;
      located = located || (target && target->location_node);
    }
    // `x := x;` on an AT %... variable is sometimes there to keep the I/O mapped (a compiler may
    // drop what no code uses): report it, but leave its removal to the reader.
    std::optional<Fix> fix;
    if (!contains_comment(nodes, statement) && !located)
      fix = removal_fix(context, statement, "remove the self-assignment");
    context.report("L035", "'" + in_message(left.text()) + "' is assigned to itself", statement.range(),
                   "this does nothing: remove it, or assign the value that was meant", std::move(fix));
  });
}

}  // namespace rung::lint::flow
