// L011 output-written-in-several-places: a physical output (a variable declared AT %Q..., or a
// %Q address written directly) assigned in more than one place of the project. The PLCopen coding
// guidelines ask that a physical output be written only once: when two pieces of logic write it,
// the last one in the cycle silently wins and the other's effect is invisible on the machine.
//
// A place is a POU (a method or action counts on its own) and, inside it, one statement list:
// writes in different branches of one IF or CASE are one place (only one of them runs), writes in
// sequence are two (`xOut := FALSE; IF bOn THEN xOut := TRUE; END_IF` is two places). Each place
// after the first (project order: files in order, then by position) is reported, naming the first.
//
// The same output is the same address (%QX0.1 declared twice, or declared and written directly,
// is one output) and the same part of it: writing xOut.3 and xOut.4, or aOut[1] and aOut[2], is
// writing different outputs. Addresses the configuration completes later (%Q*) are not followed:
// each instance gets an output of its own. Passing an output to a VAR_IN_OUT is not a write here.
#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <mutex>
#include <set>

#include "checker/lint/semantic_rules.hpp"
#include "checker/lint/semantic_support.hpp"
#include "checker/lint/usage_project.hpp"
#include "checker/query/resolve.hpp"
#include "checker/semantic/address_checker.hpp"

namespace rung::lint::semantic {
namespace {

using check::SourceId;
using check::Symbol;

// One IF or CASE a write sits in: the statement (by its start) and the branch.
struct Branch {
  uint32_t statement = 0;
  uint32_t index = 0;
};

struct OutputWrite {
  std::string key;    // the output: canonical address and the part written ("%QW2.3")
  std::string shown;  // how the message names it: "'xValve' (%QX0.1)", "%QX0.2"
  SourceId source = check::kNoSource;
  const Symbol* pou = nullptr;
  TextRange range;  // the written target, tree coordinates
  std::vector<Branch> branches;
  bool new_place = true;  // not in another branch of an IF/CASE than an earlier write of the POU
};

// Only one of them runs: they are in different branches of the same IF or CASE.
bool exclusive(const OutputWrite& a, const OutputWrite& b) {
  for (const Branch& x : a.branches) {
    for (const Branch& y : b.branches) {
      if (x.statement == y.statement && x.index != y.index) return true;
    }
  }
  return false;
}

// "[I, 2]" from "[ i,2 ]": a part of a target in one spelling.
std::string normalized(std::string_view text) {
  std::string out;
  for (char c : text) {
    if (c == ' ' || c == '\t' || c == '\r' || c == '\n') continue;
    out.push_back(static_cast<char>(std::toupper(static_cast<unsigned char>(c))));
  }
  return out;
}

// The writes of physical outputs of one POU, with the IF/CASE branches they sit in.
class WriteCollector {
 public:
  WriteCollector(const check::ProjectModel& model, const Symbol& pou,
                 const std::map<const Symbol*, std::string>& outputs,
                 const std::set<std::string, std::less<>>& output_names, std::vector<OutputWrite>& out)
      : model_(model), pou_(pou), outputs_(outputs), output_names_(output_names), out_(out), typer_(model, pou) {}

  void run() {
    for (SyntaxNode body : bodies_of(pou_)) this->body(body, 0);
  }

 private:
  static constexpr int kMaxDepth = 200;

  void body(SyntaxNode node, int depth) {
    if (!node || depth > kMaxDepth) return;
    const std::string_view kind = node.kind();
    if (kind == "statement_list") return list(node, depth);
    if (kind == "il_body") {
      for (SyntaxNode instruction : node.children_of_kind("il_instruction")) {
        const SyntaxNode op = instruction.child_by_field("operator");
        const std::string_view name = op ? op.text() : std::string_view();
        if (check::names_equal(name, "ST") || check::names_equal(name, "STN") || check::names_equal(name, "S") ||
            check::names_equal(name, "R")) {
          target(instruction.child_by_field("operand"));
        }
      }
      return;
    }
    if (kind == "sfc_network") {
      for (SyntaxNode block : node.children_of_kind("sfc_action_block")) {
        if (!is_member_action_block(pou_, block)) body(block.child_by_field("body"), depth + 1);
      }
    }
  }

  void list(SyntaxNode statements, int depth) {
    if (!statements || depth > kMaxDepth) return;
    for (SyntaxNode statement : ast::statements(statements)) this->statement(statement, depth + 1);
  }

  void statement(SyntaxNode node, int depth) {
    switch (ast::statement_kind(node)) {
      case ast::StatementKind::Assignment: {
        // a := b := value writes both.
        for (SyntaxNode at = node; at && (at.kind() == "assignment_statement" || at.kind() == "assignment_expression");
             at = at.child_by_field("right")) {
          target(at.child_by_field("left"));
        }
        return;
      }
      case ast::StatementKind::Call:
        if (SyntaxNode call = node.named_child(0); call && call.kind() == "call_expression") {
          const SyntaxNode arguments = call.child_by_field("arguments");
          for (const check::CallArgument& argument : check::call_arguments(arguments)) {
            if (argument.output) target(argument.value);
          }
        }
        return;
      case ast::StatementKind::If:
      case ast::StatementKind::Case: {
        uint32_t index = 0;
        auto branch = [&](SyntaxNode list_node) {
          branches_.push_back({node.begin(), index++});
          list(list_node, depth);
          branches_.pop_back();
        };
        if (SyntaxNode then = node.child_by_field("body")) branch(then);
        for (SyntaxNode clause : node.named_children()) {
          const std::string_view kind = clause.kind();
          if (kind == "elsif_clause" || kind == "else_clause" || kind == "case_element") {
            branch(clause.child_by_field("body"));
          }
        }
        return;
      }
      case ast::StatementKind::For:
      case ast::StatementKind::While:
      case ast::StatementKind::Repeat: return list(node.child_by_field("body"), depth);
      case ast::StatementKind::Try:
        list(node.child_by_field("body"), depth);
        for (SyntaxNode clause : node.named_children()) {
          if (clause.kind() == "catch_clause" || clause.kind() == "finally_clause") {
            list(clause.child_by_field("body"), depth);
          }
        }
        return;
      default: return;
    }
  }

  void target(SyntaxNode node) {
    node = without_parentheses(node);
    if (!node || node.has_error()) return;
    if (node.kind() == "direct_variable") {
      const check::DirectAddressResult parsed = check::parse_direct_address(node.text(), model_.profile().addressing);
      if (!parsed.ok() || parsed.address->area != check::AddressArea::Output || parsed.address->wildcard) return;
      const std::string address = check::format_direct_address(*parsed.address);
      add(address, address, node);
      return;
    }
    // Down to the variable written: xOut, GVL.xOut, aOut[1], wOut.3, stOut.bValve.
    std::string part;
    SyntaxNode root = node;
    for (int depth = 0; depth < kMaxDepth; ++depth) {
      const std::string_view kind = root.kind();
      if (kind == "identifier" || kind == "global_reference") break;
      if (kind == "member_expression") {
        const SyntaxNode object = root.child_by_field("object");
        const SyntaxNode member = root.child_by_field("member");
        if (!object || !member) return;
        if (object.kind() == "identifier") {
          const Symbol* qualifier = model_.lookup(&pou_, object.text());
          if (qualifier && qualifier->kind == check::SymbolKind::GlobalList) break;  // GVL.xOut
        }
        part.insert(0, "." + normalized(member.text()));
        root = object;
      } else if (kind == "index_expression") {
        const SyntaxNode object = root.child_by_field("object");
        if (!object) return;
        part.insert(0, normalized(std::string_view(root.text()).substr(object.end() - root.begin())));
        root = object;
      } else {
        return;  // pointer^ := ...: not a located variable
      }
    }
    const SyntaxNode name = root.kind() == "member_expression"  ? root.child_by_field("member")
                            : root.kind() == "global_reference" ? root.child_by_field("name")
                                                                : root;
    if (!name || !output_names_.contains(normalized(name.text()))) return;  // typing only what may be an output
    auto info = typer_.type_of(root);
    if (!info || !info->symbol) return;
    auto found = outputs_.find(check::query::canonical_symbol(model_, info->symbol));
    if (found == outputs_.end()) return;
    add(found->second + part, fmt::format("'{}' ({})", node.text(), found->second), node);
  }

  void add(std::string key, std::string shown, SyntaxNode where) {
    out_.push_back(OutputWrite{std::move(key), std::move(shown), pou_.source, &pou_, where.range(), branches_});
  }

  const check::ProjectModel& model_;
  const Symbol& pou_;
  const std::map<const Symbol*, std::string>& outputs_;
  const std::set<std::string, std::less<>>& output_names_;
  std::vector<OutputWrite>& out_;
  ExpressionTyper typer_;
  std::vector<Branch> branches_;
};

// Every write of a physical output in the project, built once per lint run.
class ProjectOutputWrites {
 public:
  const std::vector<OutputWrite>& writes(const check::ProjectModel& model, ProjectUsage& usage,
                                         const ProjectIndex& index) {
    std::call_once(once_, [&] { build(model, usage, index); });
    return writes_;
  }
  // The first place that writes `key`.
  const OutputWrite* first(const std::string& key) const {
    auto found = first_.find(key);
    return found == first_.end() ? nullptr : &writes_[found->second];
  }

 private:
  void build(const check::ProjectModel& model, ProjectUsage& usage, const ProjectIndex& index) {
    // The outputs: located variables at a complete %Q address, by their canonical address.
    std::map<const Symbol*, std::string> outputs;
    std::set<std::string, std::less<>> names;
    const check::AddressTable& table = model.address_table();
    for (size_t i = 0; i < table.variables.size() && i < table.located.size(); ++i) {
      const check::DirectAddress& address = table.located[i].address;
      if (address.area != check::AddressArea::Output || address.wildcard) continue;
      outputs.emplace(table.variables[i], check::format_direct_address(address));
      names.insert(normalized(table.variables[i]->name));
    }
    // The files that may write one: they name an output, or hold a %Q address.
    std::set<SourceId> files;
    for (const auto& [variable, address] : outputs) {
      for (SourceId id : usage.files_mentioning(model, variable->name)) files.insert(id);
    }
    for (SourceId id = 0; id < model.source_count(); ++id) {
      if (index.mentions_output_address(id)) files.insert(id);
    }
    for (SourceId id : files) {
      for (const Symbol* pou : check::pous_of(model.source(id).symbols)) {
        WriteCollector(model, *pou, outputs, names, writes_).run();
      }
    }
    // Places: a write in sequence after another write of the same output in the same POU starts
    // a new one; a write in another branch of the same IF/CASE does not.
    std::map<std::pair<const Symbol*, std::string>, std::vector<size_t>> by_pou;
    for (size_t i = 0; i < writes_.size(); ++i) {
      OutputWrite& write = writes_[i];
      std::vector<size_t>& earlier = by_pou[{write.pou, write.key}];
      write.new_place = earlier.empty() || std::any_of(earlier.begin(), earlier.end(),
                                                       [&](size_t e) { return !exclusive(writes_[e], write); });
      earlier.push_back(i);
      if (write.new_place) first_.emplace(write.key, i);
    }
  }

  std::once_flag once_;
  std::vector<OutputWrite> writes_;  // project order: files by id, POUs and writes in text order
  std::map<std::string, size_t> first_;
};

std::string pou_name(const Symbol& pou) {
  if (pou.name.empty()) return "the file's statements";
  if (pou.owner && !pou.owner->name.empty()) return fmt::format("{}.{}", pou.owner->name, pou.name);
  return std::string(pou.name);
}

}  // namespace

void check_output_writes(LintContext& context) {
  const check::ProjectModel& model = context.model();
  ProjectOutputWrites& index = context.cache().get<ProjectOutputWrites>();
  for (const OutputWrite& write : index.writes(model, project_usage(context), context.cache().index(model))) {
    if (write.source != context.source_id() || !write.new_place) continue;
    const OutputWrite* first = index.first(write.key);
    if (!first || first == &write) continue;
    const std::string at = place_of(model, first->source, first->range.begin);
    std::vector<DiagnosticLabel> labels;
    if (first->source == write.source) labels.push_back({first->range, "first written here"});
    context.report(
        "L011",
        first->pou == write.pou
            ? fmt::format("physical output {} is written again (first at {})", write.shown, at)
            : fmt::format("physical output {} is also written in {} (at {})", write.shown, pou_name(*first->pou), at),
        write.range,
        "write each physical output in one place only (PLCopen coding guidelines): compute its value "
        "in variables, then assign the output once",
        std::move(labels));
  }
}

}  // namespace rung::lint::semantic
