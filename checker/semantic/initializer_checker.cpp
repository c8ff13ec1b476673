#include "checker/semantic/initializer_checker.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <optional>

#include "checker/semantic/body_checker.hpp"
#include "parser/diagnostic_codes.hpp"

namespace rung::check {
namespace {

bool has_initializer_shape(std::string_view kind) {
  return kind == "array_initializer" || kind == "struct_initializer" || kind == "repeated_initializer";
}

// The children of an initializer that are values (comments are named children too).
std::vector<SyntaxNode> elements_of(SyntaxNode initializer) {
  std::vector<SyntaxNode> elements;
  for (uint32_t i = 0; i < initializer.named_child_count(); ++i) {
    SyntaxNode child = initializer.named_child(i);
    if (!child.is_extra() && child.kind() != "comment" && child.kind() != "pragma") elements.push_back(child);
  }
  return elements;
}

// How many elements an array has, if its bounds are all known.
std::optional<__int128> element_count(const Type& array) {
  __int128 total = 1;
  for (const ArrayDimension& dimension : array.dimensions) {
    if (dimension.open || !dimension.known || dimension.upper < dimension.lower) return std::nullopt;
    total *= dimension.upper - dimension.lower + 1;
  }
  return total;
}

class InitializerChecker {
 public:
  InitializerChecker(const ProjectModel& model, const Symbol& scope, std::vector<Diagnostic>& out)
      : model_(model), scope_(scope), out_(out), body_(model, scope, out) {}

  // `value` initialises something of type `target`.
  void check(SyntaxNode value, const Type* target) {
    const Type* base = underlying(target);
    if (!value || base->is_unknown()) return;
    const std::string_view kind = value.kind();
    if (kind == "struct_initializer") {
      check_structure(value, target, base);
    } else if (kind == "array_initializer") {
      check_array(value, target, base);
    } else if (!has_initializer_shape(kind)) {
      check_scalar(value, target);
    }
  }

 private:
  void report(std::string_view code, std::string message, TextRange range, std::string help = {},
              std::vector<DiagnosticLabel> labels = {}) {
    out_.push_back(make_diagnostic(code, std::move(message), range, std::move(help), std::move(labels)));
  }

  // (m1 := 1, m2 := TRUE): a STRUCT or UNION, or a function block's inputs (CODESYS).
  void check_structure(SyntaxNode value, const Type* target, const Type* base) {
    const bool has_members =
        base->kind == TypeKind::Struct || base->kind == TypeKind::Union || base->kind == TypeKind::Pou;
    if (!has_members) {
      report(codes::kTypeMismatch,
             fmt::format("a structure initial value (member := value, ...) cannot initialise a variable of type {}",
                         target->name),
             value.range(), "write one value of the variable's type");
      return;
    }
    if (!base->declaration) return;  // an inline STRUCT: its members are not symbols
    std::vector<std::pair<std::string_view, SyntaxNode>> seen;
    for (SyntaxNode field : value.children_of_kind("field_initializer")) {
      SyntaxNode name = field.child_by_field("name");
      if (!name) continue;
      const Symbol* member = model_.find_member(base->declaration, name.text());
      if (!member || member->kind != SymbolKind::Variable) {
        report(codes::kUnknownMember, fmt::format("'{}' has no member '{}'", target->name, name.text()), name.range());
        continue;
      }
      const auto first = std::find_if(seen.begin(), seen.end(),
                                      [&](const auto& entry) { return names_equal(entry.first, name.text()); });
      if (first != seen.end()) {
        report(codes::kDuplicateParameter, fmt::format("'{}' is given twice in this initial value", name.text()),
               name.range(), "give each member one value", {{first->second.range(), "first given here"}});
        continue;
      }
      seen.emplace_back(name.text(), name);
      check(field.child_by_field("value"), model_.type_of(member));
    }
  }

  // [1, 2, 3(0)]: as many values as the array has elements at most.
  void check_array(SyntaxNode value, const Type* target, const Type* base) {
    if (base->kind != TypeKind::Array) {
      report(codes::kTypeMismatch,
             fmt::format("an array initial value [...] cannot initialise a variable of type {}", target->name),
             value.range(), "write one value of the variable's type");
      return;
    }
    __int128 count = 0;
    bool countable = true;
    walk_array_elements(value, base, 1, count, countable);
    const std::optional<__int128> capacity = element_count(*base);
    if (countable && capacity && count > *capacity) {
      report(codes::kLiteralOutOfRange,
             fmt::format("{} initial values for the {} elements of {}", int128_to_string(count),
                         int128_to_string(*capacity), target->name),
             value.range(), "remove the extra values or enlarge the array");
    }
  }

  // Counts the values (a repeated `n(values)` counts n times) and checks each against the element
  // type. A multi-dimensional array may be written row by row ([[1, 2], [3, 4]]): such nested
  // lists are counted but not checked against the element type.
  void walk_array_elements(SyntaxNode list, const Type* array, __int128 factor, __int128& count, bool& countable) {
    for (SyntaxNode element : elements_of(list)) {
      if (element.kind() == "repeated_initializer") {
        SyntaxNode times = element.child_by_field("count");
        auto repeat = times ? parse_integer_literal(times.text()) : std::nullopt;
        if (!repeat) {
          countable = false;
          continue;
        }
        std::vector<SyntaxNode> inner = elements_of(element);
        if (!inner.empty() && inner.front() == times) inner.erase(inner.begin());
        if (inner.empty()) count += factor * static_cast<__int128>(*repeat);  // n() : n default values
        for (SyntaxNode part : inner) {
          if (part.kind() == "repeated_initializer" || part.kind() == "array_initializer") {
            countable = false;
            continue;
          }
          count += factor * static_cast<__int128>(*repeat);
          check(part, array->element);
        }
      } else if (element.kind() == "array_initializer" && array->dimensions.size() > 1 &&
                 underlying(array->element)->kind != TypeKind::Array) {
        walk_rows(element, array->element, factor, count);
      } else {
        count += factor;
        check(element, array->element);
      }
    }
  }

  void walk_rows(SyntaxNode row, const Type* element, __int128 factor, __int128& count) {
    for (SyntaxNode part : elements_of(row)) {
      if (part.kind() == "array_initializer") {
        walk_rows(part, element, factor, count);
      } else {
        count += factor;
        check(part, element);
      }
    }
  }

  void check_scalar(SyntaxNode value, const Type* target) {
    if (model_.profile().literal_initial_values_only) check_literal_only(value);
    ExprInfo info = body_.type_of(value);
    if (info.names_type) {
      report(codes::kWrongKindOfName, fmt::format("'{}' is a type, not a value", value.text()), value.range(),
             "write one of its values");
      return;
    }
    body_.check_conversion(info, target, value);
  }

  // OpenPCS computes no initial values: a variable, a named constant or a parameter in one is
  // S5043 "use literals or enum values".
  void check_literal_only(SyntaxNode value) {
    std::vector<SyntaxNode> stack{value};
    while (!stack.empty()) {
      SyntaxNode node = stack.back();
      stack.pop_back();
      if (node.kind() == "identifier") {
        const Symbol* symbol = model_.lookup(&scope_, node.text());
        if (symbol && symbol->kind == SymbolKind::Variable) {
          report(codes::kNotConstant,
                 fmt::format("'{}' is a {}: initial values in this profile are literals or enum values", node.text(),
                             symbol->has(kConstant) ? "named constant" : "variable"),
                 node.range(), "write the value itself");
          return;
        }
        continue;
      }
      if (node.kind() == "member_expression") {
        if (SyntaxNode object = node.child_by_field("object")) stack.push_back(object);
        continue;
      }
      for (uint32_t i = 0; i < node.named_child_count(); ++i) stack.push_back(node.named_child(i));
    }
  }

  const ProjectModel& model_;
  const Symbol& scope_;
  std::vector<Diagnostic>& out_;
  BodyChecker body_;
};

}  // namespace

void check_initial_value(const ProjectModel& model, const Symbol& owner, const Symbol& variable,
                         std::vector<Diagnostic>& out) {
  if (!(variable.flags & kHasInitializer) || variable.name.empty()) return;  // most have none: no walk
  SyntaxNode value = variable.node.child_by_field("value");
  if (!value) return;
  // `a, b : INT := 300` shares one value: only the first name reports, once.
  const std::vector<SyntaxNode> names = variable.node.children_by_field("name");
  if (names.empty() || names.front().range().begin != variable.name_range.begin) return;
  if (variable.section == ast::VarSection::External) {
    if (model.profile().external_initial_values) return;
    out.push_back(make_diagnostic(
        codes::kInitialValueNotAllowed,
        fmt::format("VAR_EXTERNAL '{}' takes no initial value: the VAR_GLOBAL it refers to has it", variable.name),
        value.range(), "move the value to the VAR_GLOBAL declaration"));
    return;
  }
  if (variable.location_node && !model.profile().located_initial_values) {
    out.push_back(make_diagnostic(
        codes::kInitialValueNotAllowed,
        fmt::format("'{}' is at a direct address: in this profile it takes no initial value", variable.name),
        value.range(), "the value comes from the process image; remove ':= ...'"));
    return;
  }
  InitializerChecker(model, owner, out).check(value, model.type_of(&variable));
}

void check_type_initializer(const ProjectModel& model, const Symbol& type_symbol, std::vector<Diagnostic>& out) {
  SyntaxNode value = type_symbol.node.child_by_field("value");
  if (!value) return;
  InitializerChecker(model, type_symbol, out).check(value, model.type_of(&type_symbol));
  if (value.kind() != "struct_initializer") return;
  // A member initialised in its declaration and again after END_STRUCT (OpenPCS S4033).
  for (SyntaxNode field : value.children_of_kind("field_initializer")) {
    SyntaxNode name = field.child_by_field("name");
    const Symbol* member = name ? type_symbol.own_member(name.text()) : nullptr;
    if (!member || member->kind != SymbolKind::Variable || !member->has(kHasInitializer)) continue;
    SyntaxNode first = member->node.child_by_field("value");
    out.push_back(make_diagnostic(codes::kDuplicateParameter,
                                  fmt::format("'{}' is initialised twice: in its declaration and here", name.text()),
                                  name.range(), "keep one of the two initial values",
                                  {{first ? first.range() : member->name_range, "initialised here first"}}));
  }
}

}  // namespace rung::check
