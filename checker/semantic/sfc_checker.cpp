// Textual SFC: steps, transitions, actions and step macros of one network (see sfc_checker.hpp).
#include "checker/semantic/sfc_checker.hpp"

#include <fmt/format.h>

#include <map>
#include <numeric>
#include <optional>
#include <string>
#include <vector>

#include "checker/symbols/names.hpp"
#include "parser/diagnostic_codes.hpp"

namespace rung::check {
namespace {

struct Step {
  SyntaxNode name;
  bool initial = false;
  bool broken = false;  // the step's header did not parse: no structural checks for it
};

// Why a step name breaks the profile's rule, or empty.
std::string step_name_problem(std::string_view name, const Profile& profile) {
  const auto ascii_letter = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); };
  if (profile.step_names_start_with_letter) {
    if (!ascii_letter(name.front())) return fmt::format("it begins with '{}', not with a letter", name.front());
    for (char c : name) {
      if (!ascii_letter(c) && !(c >= '0' && c <= '9') && c != '_') {
        return "it has a character other than the letters a-z, the digits and '_'";
      }
    }
  }
  if (profile.max_step_name_length != 0 && name.size() > profile.max_step_name_length) {
    return fmt::format("it has {} characters, at most {} are allowed", name.size(), profile.max_step_name_length);
  }
  return {};
}

class SfcChecker {
 public:
  SfcChecker(BodyChecker& body, const ProjectModel& model, const Symbol& pou) : body_(body), model_(model), pou_(pou) {}

  void check(SyntaxNode network) {
    collect(network);
    // A top-level fragment may list transitions whose steps are elsewhere: nothing to resolve.
    if (steps_.empty()) return;
    parent_.resize(steps_.size());
    std::iota(parent_.begin(), parent_.end(), 0);
    for (SyntaxNode transition : transitions_) check_transition(transition);
    check_initial_steps();
    for (const Step& step : steps_) {
      if (!step.broken) check_step_name(step.name);
    }
    for (SyntaxNode step_node : step_nodes_) check_action_associations(step_node);
    for (SyntaxNode code : il_code_) check_step_macros(code);
  }

 private:
  void collect(SyntaxNode network) {
    std::map<std::string, SyntaxNode> transitions_seen;
    for (uint32_t i = 0; i < network.named_child_count(); ++i) {
      SyntaxNode child = network.named_child(i);
      SyntaxNode name = child.child_by_field("name");
      if (child.kind() == "sfc_step") {
        if (!name) continue;
        step_nodes_.push_back(child);
        Step step{name, child.child(0).kind() == "INITIAL_STEP", child.has_error()};
        const std::string key = upper_name(name.text());
        if (auto found = step_index_.find(key); found != step_index_.end()) {
          report_duplicate("step", name, steps_[found->second].name);
          if (step.initial && !step.broken) duplicate_initials_.push_back({found->second, name});
          continue;
        }
        step_index_.emplace(key, steps_.size());
        steps_.push_back(step);
      } else if (child.kind() == "sfc_transition") {
        transitions_.push_back(child);
        if (name) add_unique("transition", name, transitions_seen);
        if (SyntaxNode code = child.child_by_field("body"); code && code.kind() == "il_body") il_code_.push_back(code);
      } else if (child.kind() == "sfc_action_block") {
        // (a second action of one name is E003 of the symbol table: the blocks are POU members)
        if (name) other_names_.emplace(upper_name(name.text()), "action");
        if (SyntaxNode code = child.child_by_field("body"); code && code.kind() == "il_body") il_code_.push_back(code);
      }
    }
    // Actions of the POU itself (CODESYS/TwinCAT: ACTION objects below the PROGRAM).
    for (const Symbol* member : pou_.ordered) {
      if (member->kind != SymbolKind::Action || !member->node || member->node.kind() != "action_declaration") continue;
      if (SyntaxNode code = member->node.child_by_field("body"); code && code.kind() == "il_body") {
        il_code_.push_back(code);
      }
    }
  }

  void add_unique(std::string_view what, SyntaxNode name, std::map<std::string, SyntaxNode>& seen) {
    const std::string key = upper_name(name.text());
    auto [it, inserted] = seen.emplace(key, name);
    if (!inserted) {
      report_duplicate(what, name, it->second);
      return;
    }
    other_names_.emplace(key, what);
  }

  void report_duplicate(std::string_view what, SyntaxNode name, SyntaxNode first) {
    body_.report(codes::kDuplicateDeclaration, fmt::format("{} '{}' is declared twice in this SFC", what, name.text()),
                 name.range(),
                 what == "step"
                     ? fmt::format("give each step its own name: a jump to '{}' would be ambiguous", name.text())
                     : fmt::format("give each {} its own name", what),
                 {{first.range(), "first declared here"}});
  }

  // The step `name` refers to, or reports E410 and returns nullopt.
  std::optional<size_t> resolve_step(SyntaxNode name, std::string_view context) {
    const std::string key = upper_name(name.text());
    if (auto found = step_index_.find(key); found != step_index_.end()) return found->second;
    ++unresolved_;
    if (auto other = other_names_.find(key); other != other_names_.end()) {
      body_.report(codes::kUnknownLabel,
                   fmt::format("'{}' is {} {}, not a step ({} needs a step)", name.text(),
                               other->second == "action" ? "an" : "a", other->second, context),
                   name.range(), "name a step (STEP name: ... END_STEP) of this SFC");
    } else {
      std::vector<std::string_view> candidates;
      for (const Step& step : steps_) candidates.push_back(step.name.text());
      const std::string_view suggestion = closest_name(name.text(), candidates);
      body_.report(codes::kUnknownLabel, fmt::format("no step '{}' in this SFC for {}", name.text(), context),
                   name.range(),
                   suggestion.empty() ? std::string("name a step (STEP name: ... END_STEP) of this SFC")
                                      : fmt::format("did you mean '{}'?", suggestion));
    }
    return std::nullopt;
  }

  void check_transition(SyntaxNode transition) {
    std::vector<size_t> connected;
    for (SyntaxNode from : transition.children_by_field("from")) {
      if (from.kind() != "identifier") continue;
      if (auto index = resolve_step(from, "TRANSITION FROM")) connected.push_back(*index);
    }
    for (SyntaxNode to : transition.children_by_field("to")) {
      if (to.kind() != "identifier") continue;
      if (auto index = resolve_step(to, "TRANSITION TO")) connected.push_back(*index);
    }
    for (size_t index : connected) unite(connected.front(), index);
  }

  // Union-find over steps: a network is a set of steps that transitions connect.
  size_t root(size_t index) {
    while (parent_[index] != index) index = parent_[index] = parent_[parent_[index]];
    return index;
  }
  void unite(size_t a, size_t b) { parent_[root(a)] = root(b); }

  void check_initial_steps() {
    // Per network, in source order: its first step and its INITIAL_STEPs.
    std::map<size_t, std::vector<SyntaxNode>> initials;
    std::map<size_t, size_t> first_step;
    for (size_t i = 0; i < steps_.size(); ++i) {
      if (steps_[i].broken) continue;
      const size_t network = root(i);
      first_step.emplace(network, i);
      if (steps_[i].initial) initials[network].push_back(steps_[i].name);
    }
    for (const auto& [index, name] : duplicate_initials_) initials[root(index)].push_back(name);
    for (const auto& [network, first] : first_step) {
      const std::vector<SyntaxNode>& found = initials[network];
      if (found.empty()) {
        // A step reference that did not resolve may be the missing link: say nothing then.
        if (unresolved_ != 0) continue;
        const SyntaxNode name = steps_[first].name;
        body_.report(codes::kInitialStepCount,
                     fmt::format("the SFC network of step '{}' has no INITIAL_STEP", name.text()), name.range(),
                     "make one of its steps INITIAL_STEP, or connect it by a TRANSITION to a network that has one");
        continue;
      }
      for (size_t i = 1; i < found.size(); ++i) {
        body_.report(
            codes::kInitialStepCount,
            fmt::format("a second INITIAL_STEP '{}' in the SFC network of '{}'", found[i].text(), found[0].text()),
            found[i].range(), "an SFC network starts at exactly one step: make this one a STEP",
            {{found[0].range(), "the network's INITIAL_STEP"}});
      }
    }
  }

  void check_step_name(SyntaxNode name) {
    const std::string problem = step_name_problem(name.text(), model_.profile());
    if (problem.empty()) return;
    body_.report(codes::kStepNameNotAllowed, fmt::format("step name '{}' is not allowed: {}", name.text(), problem),
                 name.range(), "step names begin with a letter a-z, go on with letters, digits or '_'");
  }

  void check_action_associations(SyntaxNode step) {
    for (uint32_t i = 0; i < step.named_child_count(); ++i) {
      SyntaxNode association = step.named_child(i);
      if (association.kind() != "sfc_action") continue;
      SyntaxNode name = association.child_by_field("name");
      if (!name || name.is_missing()) continue;
      const std::string key = upper_name(name.text());
      if (auto other = other_names_.find(key); other != other_names_.end()) {
        if (other->second == "action") continue;
        body_.report(codes::kWrongKindOfName, fmt::format("'{}' is a transition, not an action", name.text()),
                     name.range(), "associate an action (ACTION name: ... END_ACTION) or a BOOL variable");
        continue;
      }
      if (step_index_.contains(key)) {
        body_.report(codes::kWrongKindOfName, fmt::format("'{}' is a step, not an action", name.text()), name.range(),
                     "associate an action (ACTION name: ... END_ACTION) or a BOOL variable");
        continue;
      }
      const Symbol* found = model_.lookup(&pou_, name.text());
      if (!found) {
        if (model_.has_unresolved_base(&pou_)) continue;
        body_.report(codes::kUndeclaredName,
                     fmt::format("'{}' is neither an action of this SFC nor a variable", name.text()), name.range(),
                     fmt::format("declare ACTION {}: ... END_ACTION, or a BOOL variable {}", name.text(), name.text()));
        continue;
      }
      if (found->kind == SymbolKind::Action) continue;
      if (found->kind == SymbolKind::Variable) {
        const Type* type = underlying(model_.type_of(found));
        if (!type || type->is_unknown() || type->kind == TypeKind::Bool) continue;
        body_.report(codes::kWrongKindOfName,
                     fmt::format("'{}' is a variable of type {}; a step can set only an action or a BOOL variable",
                                 name.text(), model_.type_of(found)->name),
                     name.range());
        continue;
      }
      body_.report(codes::kWrongKindOfName,
                   fmt::format("'{}' is a {}, not an action", name.text(), symbol_kind_name(found->kind)), name.range(),
                   "associate an action (ACTION name: ... END_ACTION) or a BOOL variable");
    }
  }

  void check_step_macros(SyntaxNode il_body) {
    for (uint32_t i = 0; i < il_body.named_child_count(); ++i) {
      SyntaxNode macro = il_body.named_child(i);
      if (macro.kind() != "sfc_step_macro") continue;
      SyntaxNode macro_name = macro.child_by_field("name");
      if (!macro_name) continue;
      const std::string name = upper_name(macro_name.text());
      const bool takes_step = name != "DEACTIVATE_ALL_STEPS";
      SyntaxNode step = macro.child_by_field("step");
      if (takes_step && !step) {
        body_.report(codes::kIlOperandCount, fmt::format("@{} needs the step it acts on", name), macro.range(),
                     fmt::format("write @{}(StepName)", name));
      } else if (!takes_step && step) {
        body_.report(codes::kIlOperandCount, "@DEACTIVATE_ALL_STEPS takes no step", step.range(),
                     "write @DEACTIVATE_ALL_STEPS(), or @DEACTIVATE_STEP(name) for one step");
      } else if (step) {
        resolve_step(step, fmt::format("@{}", name));
      }
    }
  }

  BodyChecker& body_;
  const ProjectModel& model_;
  const Symbol& pou_;
  std::vector<Step> steps_;
  std::vector<SyntaxNode> step_nodes_;  // every sfc_step, duplicates too
  std::map<std::string, size_t> step_index_;
  std::map<std::string, std::string_view> other_names_;  // transitions and actions of the chart
  std::vector<std::pair<size_t, SyntaxNode>> duplicate_initials_;
  std::vector<SyntaxNode> transitions_;
  std::vector<SyntaxNode> il_code_;
  std::vector<size_t> parent_;
  size_t unresolved_ = 0;
};

}  // namespace

void check_sfc_network(BodyChecker& body, const ProjectModel& model, const Symbol& pou, SyntaxNode network) {
  SfcChecker(body, model, pou).check(network);
}

void report_step_macro_in_st(BodyChecker& body, SyntaxNode macro) {
  SyntaxNode at = macro.child(0);
  SyntaxNode name = macro.child_by_field("name");
  body.report(codes::kInvalidCharacter,
              fmt::format("'@' has no meaning in Structured Text: @{} is an OpenPCS macro for IL code only",
                          name ? upper_name(name.text()) : std::string("ACTIVATE_STEP")),
              at ? at.range() : macro.range(), "write this code in IL to change the active steps with the macro");
}

}  // namespace rung::check
