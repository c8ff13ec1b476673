// L052 loop-variable-after-loop: a FOR counter read after its END_FOR, in the statements that
// follow the loop in the same statement list, before anything writes it again. The standard leaves
// its value after the loop open, and compilers differ: CODESYS leaves end + step (11 after
// FOR i := 1 TO 10), others the end value (10). A program that reads it behaves differently when
// it moves to another PLC.
//
// A forward scan: a statement that certainly writes the counter first (an assignment, another
// FOR over it, every branch of an IF/CASE with ELSE) or leaves (RETURN, EXIT, JMP) ends it without
// a finding; a loop body or a branch that may not run does not.
#include <fmt/format.h>

#include "checker/lint/semantic_rules.hpp"
#include "checker/lint/semantic_support.hpp"

namespace rung::lint::semantic {
namespace {

using ast::StatementKind;
using check::Symbol;

constexpr int kMaxDepth = 200;

enum class Flow { Open, Read, Written };  // Written also stands for "control leaves here"

struct Outcome {
  Flow flow = Flow::Open;
  SyntaxNode read;  // the counter's name, for Read
};

class CounterScan {
 public:
  CounterScan(const check::ProjectModel& model, const Symbol& pou, const Symbol& counter)
      : model_(model), pou_(pou), counter_(counter) {}

  // The statements of `list` from index `from` on.
  Outcome scan(const std::vector<SyntaxNode>& statements, size_t from, int depth) {
    for (size_t i = from; i < statements.size(); ++i) {
      const Outcome outcome = statement(statements[i], depth);
      if (outcome.flow != Flow::Open) return outcome;
    }
    return {};
  }

 private:
  Outcome list(SyntaxNode statement_list, int depth) {
    if (!statement_list || depth > kMaxDepth) return {};
    return scan(ast::statements(statement_list), 0, depth + 1);
  }

  Outcome statement(SyntaxNode node, int depth) {
    if (depth > kMaxDepth || node.is_error()) return {};
    switch (ast::statement_kind(node)) {
      case StatementKind::Assignment: {
        if (Outcome read = reads(node.child_by_field("right")); read.flow == Flow::Read) return read;
        const SyntaxNode left = without_parentheses(node.child_by_field("left"));
        if (left && left.kind() == "identifier" && names_counter(left)) return {Flow::Written, {}};
        return reads(left);
      }
      case StatementKind::Call: {
        const SyntaxNode call = node.named_child(0);
        if (Outcome read = reads(call); read.flow == Flow::Read) return read;
        return writes_output(call) ? Outcome{Flow::Written, {}} : Outcome{};
      }
      case StatementKind::If: return branches(node, "condition", depth);
      case StatementKind::Case: return branches(node, "value", depth);
      case StatementKind::For: {
        for (const char* field : {"start", "end", "step"}) {
          if (Outcome read = reads(node.child_by_field(field)); read.flow == Flow::Read) return read;
        }
        const SyntaxNode variable = node.child_by_field("variable");
        if (variable && variable.kind() == "identifier" && names_counter(variable)) return {Flow::Written, {}};
        return only_reads(list(node.child_by_field("body"), depth));  // the body may not run
      }
      case StatementKind::While: {
        if (Outcome read = reads(node.child_by_field("condition")); read.flow == Flow::Read) return read;
        return only_reads(list(node.child_by_field("body"), depth));
      }
      case StatementKind::Repeat: {
        // The body runs at least once, before the condition.
        if (Outcome body = list(node.child_by_field("body"), depth); body.flow != Flow::Open) return body;
        return reads(node.child_by_field("condition"));
      }
      case StatementKind::Return:
        if (SyntaxNode condition = node.child_by_field("condition")) return reads(condition);  // RETURN only if ...
        return {Flow::Written, {}};
      case StatementKind::Exit:
      case StatementKind::Continue:
      case StatementKind::Jump: return {Flow::Written, {}};
      case StatementKind::Label:
      case StatementKind::Empty: return {};
      case StatementKind::Try: return only_reads(list(node.child_by_field("body"), depth));
      default: return reads(node);
    }
  }

  // IF (condition, THEN, ELSIF..., ELSE) and CASE (selector, branches, ELSE): a read in any
  // branch is a finding; the counter is written only if every branch writes it and ELSE exists.
  Outcome branches(SyntaxNode node, const char* head, int depth) {
    if (Outcome read = reads(node.child_by_field(head)); read.flow == Flow::Read) return read;
    bool all_write = true;
    bool has_else = false;
    auto merge = [&](const Outcome& outcome) {
      if (outcome.flow != Flow::Written) all_write = false;
      return outcome.flow == Flow::Read;
    };
    if (SyntaxNode body = node.child_by_field("body")) {  // IF's THEN
      if (Outcome outcome = list(body, depth); merge(outcome)) return outcome;
    }
    for (SyntaxNode clause : node.named_children()) {
      const std::string_view kind = clause.kind();
      if (kind == "elsif_clause") {
        if (Outcome read = reads(clause.child_by_field("condition")); read.flow == Flow::Read) return read;
      } else if (kind == "else_clause") {
        has_else = true;
      } else if (kind != "case_element") {
        continue;
      }
      if (Outcome outcome = list(clause.child_by_field("body"), depth); merge(outcome)) return outcome;
    }
    return all_write && has_else ? Outcome{Flow::Written, {}} : Outcome{};
  }

  static Outcome only_reads(const Outcome& outcome) { return outcome.flow == Flow::Read ? outcome : Outcome{}; }

  Outcome reads(SyntaxNode expression) {
    const SyntaxNode read = first_read(expression, 0);
    return read ? Outcome{Flow::Read, read} : Outcome{};
  }

  // The first name of the counter in `node` that reads it, in text order. Member names after '.',
  // parameter names and the targets of outputs (`=> i`, a write) are not reads.
  SyntaxNode first_read(SyntaxNode node, int depth) {
    if (!node || depth > kMaxDepth || node.is_extra() || !node.is_named()) return {};
    const std::string_view kind = node.kind();
    if (kind == "identifier") return names_counter(node) ? node : SyntaxNode();
    if (kind == "member_expression") return first_read(node.child_by_field("object"), depth + 1);
    if (kind == "argument") return first_read(node.child_by_field("value"), depth + 1);
    if (kind == "output_argument" || kind == "typed_literal") return {};
    for (SyntaxNode child : node.named_children()) {
      if (SyntaxNode read = first_read(child, depth + 1)) return read;
    }
    return {};
  }

  // fb(Q => i): the call writes the counter.
  bool writes_output(SyntaxNode call) {
    const SyntaxNode arguments = call ? call.child_by_field("arguments") : SyntaxNode();
    if (!arguments) return false;
    for (SyntaxNode argument : arguments.children_of_kind("output_argument")) {
      const SyntaxNode target = argument.child_by_field("target");
      if (target && target.kind() == "identifier" && names_counter(target)) return true;
    }
    return false;
  }

  bool names_counter(SyntaxNode identifier) const {
    return check::names_equal(identifier.text(), counter_.name) && model_.lookup(&pou_, identifier.text()) == &counter_;
  }

  const check::ProjectModel& model_;
  const Symbol& pou_;
  const Symbol& counter_;
};

void check_list(LintContext& context, ExpressionTyper& typer, SyntaxNode list) {
  const std::vector<SyntaxNode> statements = ast::statements(list);
  for (size_t i = 0; i + 1 < statements.size(); ++i) {
    const SyntaxNode loop = statements[i];
    if (ast::statement_kind(loop) != StatementKind::For || loop.has_error()) continue;
    const SyntaxNode variable = loop.child_by_field("variable");
    if (!variable || variable.kind() != "identifier") continue;
    auto info = typer.type_of(variable);
    if (!info || !info->symbol || info->symbol->kind != check::SymbolKind::Variable) continue;
    const Symbol& counter = *info->symbol;
    const Outcome outcome = CounterScan(context.model(), typer.pou(), counter).scan(statements, i + 1, 0);
    if (outcome.flow != Flow::Read) continue;
    const FilePosition end = context.source().document->position_of_tree_offset(loop.end());
    context.report("L052",
                   fmt::format("'{}' is read after its FOR loop (END_FOR on line {}): its value there depends on "
                               "the compiler",
                               outcome.read.text(), end.line),
                   outcome.read.range(),
                   "CODESYS leaves end + step in the counter, other compilers the end value: keep the value you "
                   "need in a variable of its own (e.g. set it before EXIT), or write the counter before reading it");
  }
}

}  // namespace

void check_loop_variable_after(LintContext& context) {
  for (const Symbol* pou : context.pous()) {
    ExpressionTyper typer(context.model(), *pou);
    const NodeList& nodes = context.nodes();
    walk_bodies(nodes, *pou, [&](uint32_t i) {
      // Only a list with a FOR loop in it has a counter to read after the loop.
      if (nodes.kind(i) == "statement_list" && nodes.first_child_of_kind(i, "for_statement") != NodeList::kNone) {
        check_list(context, typer, nodes.node(i));
      }
      return true;
    });
  }
}

}  // namespace rung::lint::semantic
