// L020-L023: the size and shape of POUs, against rung.toml [lint.thresholds] limits.
#include <fmt/format.h>

#include "checker/lint/structure_pou.hpp"
#include "checker/lint/structure_rules.hpp"

namespace rung::lint::structure {
namespace {

using check::Symbol;

// The control statements whose bodies nest, with the keyword that starts them.
std::string_view control_keyword(std::string_view kind) {
  if (kind == "if_statement") return "IF";
  if (kind == "case_statement") return "CASE";
  if (kind == "for_statement") return "FOR";
  if (kind == "while_statement") return "WHILE";
  if (kind == "repeat_statement") return "REPEAT";
  return {};
}

// Nodes that hold statements without nesting them deeper: branches of an IF or CASE, the parts of
// a TRY.
bool holds_statements(std::string_view kind) {
  return kind == "statement_list" || kind == "elsif_clause" || kind == "else_clause" || kind == "case_element" ||
         kind == "try_statement" || kind == "catch_clause" || kind == "finally_clause";
}

// The POUs whose size these rules measure: named ones (a snippet without header is no POU).
bool is_measured(const Symbol& pou) {
  return !pou.name.empty() && pou.name_range.end > pou.name_range.begin;
}

class NestingCheck {
 public:
  NestingCheck(LintContext& context, int64_t limit) : context_(context), nodes_(context.nodes()), limit_(limit) {}

  // Visits the statements below node `node` at nesting `depth`; a control statement deeper than
  // the limit is reported and not entered, so a deep chain gives one finding.
  void visit(uint32_t node, int64_t depth) {
    if (node == NodeList::kNone || depth > kMaxDepth) return;  // broken code nested absurdly deep
    nodes_.for_each_child(node, [&](uint32_t child) {
      if (!nodes_.is_named(child)) return;
      const std::string_view kind = nodes_.kind(child);
      const std::string_view keyword = control_keyword(kind);
      if (keyword.empty()) {
        if (holds_statements(kind)) visit(child, depth);
        return;
      }
      if (depth + 1 > limit_) {
        report(child, keyword, depth + 1);
        return;
      }
      visit(child, depth + 1);
    });
  }

 private:
  static constexpr int64_t kMaxDepth = 256;

  void report(uint32_t statement, std::string_view keyword, int64_t depth) {
    const uint32_t begin = nodes_.begin(statement);
    context_.report("L020", fmt::format("{} nested {} levels deep (limit {})", keyword, depth, limit_),
                    {begin, begin + static_cast<uint32_t>(keyword.size())},
                    fmt::format("move the inner part into a method or function, or leave early (RETURN, EXIT, "
                                "CONTINUE) to flatten it; rung.toml [lint.thresholds] max_nesting = {} sets the limit",
                                limit_));
  }

  LintContext& context_;
  const NodeList& nodes_;
  int64_t limit_;
};

// IL instructions that jump, call or return only when the current result is TRUE (or FALSE).
bool is_conditional_il(std::string_view op) {
  for (std::string_view conditional : {"JMPC", "JMPCN", "CALC", "CALCN", "RETC", "RETCN"}) {
    if (check::names_equal(op, conditional)) return true;
  }
  return false;
}

// The decisions of a body (node `body` of `nodes`): each IF, ELSIF, CASE branch (not ELSE), FOR,
// WHILE and REPEAT, each AND_THEN / OR_ELSE (they skip their right operand: a branch of their own;
// AND and OR evaluate both operands), and each conditional IL jump, call or return.
int64_t decisions_in(const NodeList& nodes, uint32_t body) {
  static const TSFieldId kOperator = NodeList::field_id("operator");
  int64_t decisions = 0;
  nodes.walk(body, [&](uint32_t i) {
    if (nodes.is_extra(i)) return false;
    const std::string_view kind = nodes.kind(i);
    if (kind == "if_statement" || kind == "elsif_clause" || kind == "case_element" || kind == "for_statement" ||
        kind == "while_statement" || kind == "repeat_statement") {
      ++decisions;
    } else if (kind == "binary_expression") {
      const std::string_view op = operator_text(nodes, i);
      if (check::names_equal(op, "AND_THEN") || check::names_equal(op, "OR_ELSE")) ++decisions;
    } else if (kind == "il_instruction") {
      if (const uint32_t op = nodes.child_by_field(i, kOperator);
          op != NodeList::kNone && is_conditional_il(nodes.text(op))) {
        ++decisions;
      }
    }
    return nodes.has_children(i);
  });
  return decisions;
}

// Statements of a body (node `body` of `nodes`) at any depth (empty statements and labels are
// none); IL instructions too.
int64_t statements_in(const NodeList& nodes, uint32_t body) {
  int64_t count = 0;
  nodes.walk(body, [&](uint32_t i) {
    if (nodes.is_extra(i)) return false;
    const std::string_view kind = nodes.kind(i);
    // Every statement kind but labels ends in _statement (ast::statement_kind decides which).
    if (kind.ends_with("_statement")) {
      const ast::StatementKind statement = ast::statement_kind(nodes.node(i));
      if (statement != ast::StatementKind::Unknown && statement != ast::StatementKind::Empty) ++count;
    } else if (kind == "il_instruction") {
      ++count;
    }
    return nodes.has_children(i);
  });
  return count;
}

}  // namespace

void check_nesting(LintContext& context) {
  NestingCheck check(context, context.threshold("max_nesting", 4));
  for (const Symbol* pou : context.pous()) {
    for (SyntaxNode body : bodies_of(*pou)) check.visit(context.nodes().index_of(body), 0);
  }
}

void check_complexity(LintContext& context) {
  const int64_t limit = context.threshold("max_cyclomatic_complexity", 15);
  for (const Symbol* pou : context.pous()) {
    if (!is_measured(*pou)) continue;
    int64_t complexity = 1;
    for (SyntaxNode body : bodies_of(*pou)) complexity += decisions_in(context.nodes(), context.nodes().index_of(body));
    if (complexity <= limit) continue;
    context.report("L021",
                   fmt::format("{} has a cyclomatic complexity of {} (limit {})", pou_label(*pou), complexity, limit),
                   pou->name_range,
                   fmt::format("each decision (IF, ELSIF, CASE branch, loop) is one more path to understand and "
                               "test; move parts into methods or functions; rung.toml [lint.thresholds] "
                               "max_cyclomatic_complexity = {} sets the limit",
                               limit));
  }
}

void check_pou_length(LintContext& context) {
  const int64_t limit = context.threshold("max_statements", 200);
  for (const Symbol* pou : context.pous()) {
    if (!is_measured(*pou)) continue;
    int64_t count = 0;
    for (SyntaxNode body : bodies_of(*pou)) count += statements_in(context.nodes(), context.nodes().index_of(body));
    if (count <= limit) continue;
    context.report("L022", fmt::format("{} has {} statements (limit {})", pou_label(*pou), count, limit),
                   pou->name_range,
                   fmt::format("split it into methods, actions or smaller POUs that each do one thing; rung.toml "
                               "[lint.thresholds] max_statements = {} sets the limit",
                               limit));
  }
}

void check_parameter_count(LintContext& context) {
  const int64_t limit = context.threshold("max_parameters", 8);
  for (const Symbol* pou : context.pous()) {
    if (!is_measured(*pou) || signature_is_given(context.model(), *pou)) continue;
    int64_t inputs = 0, outputs = 0, in_outs = 0;
    for (const Symbol* member : pou->ordered) {
      if (member->kind != check::SymbolKind::Variable) continue;
      if (member->section == ast::VarSection::Input) ++inputs;
      if (member->section == ast::VarSection::Output) ++outputs;
      if (member->section == ast::VarSection::InOut) ++in_outs;
    }
    const int64_t count = inputs + outputs + in_outs;
    if (count <= limit) continue;
    context.report("L023",
                   fmt::format("{} has {} parameters (limit {}): {} inputs, {} outputs, {} in-outs", pou_label(*pou),
                               count, limit, inputs, outputs, in_outs),
                   pou->name_range,
                   fmt::format("pass values that belong together in a STRUCT, or split the POU; rung.toml "
                               "[lint.thresholds] max_parameters = {} sets the limit",
                               limit));
  }
}

}  // namespace rung::lint::structure
