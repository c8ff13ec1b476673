// L050 magic-number: numeric literals in statements. Declarations are where numbers get names
// (initial values, CONSTANT blocks, array bounds), so only bodies are read; CASE labels (the
// values a state variable takes), bit numbers (x.3) and literal array indices (a[3]) are exempt, and so are the numbers
// rung.toml [lint.naming] allowed_numbers lists. TIME, DATE and TOD literals carry a unit and are
// not numbers here.
#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <optional>
#include <set>

#include "checker/lint/structure_pou.hpp"
#include "checker/lint/structure_rules.hpp"

namespace rung::lint::structure {
namespace {

constexpr std::string_view kDefaultAllowed = "-1,0,1,2";

// The value of an integer or real literal as written: 1_000, 16#FF, 2#1010, 1.5E3.
std::optional<double> literal_value(std::string_view text, bool real) {
  std::string digits;
  for (char c : text) {
    if (c != '_') digits += c;
  }
  if (digits.empty()) return std::nullopt;
  if (real) {
    char* end = nullptr;
    const double value = std::strtod(digits.c_str(), &end);
    return end && *end == '\0' ? std::optional<double>(value) : std::nullopt;
  }
  int base = 10;
  std::string number = digits;
  if (const size_t hash = digits.find('#'); hash != std::string::npos) {
    base = std::atoi(digits.substr(0, hash).c_str());
    number = digits.substr(hash + 1);
  }
  if (base < 2 || base > 36 || number.empty()) return std::nullopt;
  char* end = nullptr;
  const double value = static_cast<double>(std::strtoull(number.c_str(), &end, base));
  return end && *end == '\0' ? std::optional<double>(value) : std::nullopt;
}

// The numbers of a comma-separated list ("-1,0,1,2"); entries that are no number are ignored.
std::vector<double> number_list(std::string_view list) {
  std::vector<double> numbers;
  while (!list.empty()) {
    const size_t comma = list.find(',');
    std::string entry(list.substr(0, comma));
    char* end = nullptr;
    const double value = std::strtod(entry.c_str(), &end);
    if (end != entry.c_str()) numbers.push_back(value);
    if (comma == std::string_view::npos) break;
    list.remove_prefix(comma + 1);
  }
  return numbers;
}

bool is_number_literal(std::string_view kind) {
  return kind == "integer_literal" || kind == "real_literal";
}

class MagicNumbers {
 public:
  MagicNumbers(LintContext& context, std::string_view allowed_text)
      : context_(context), allowed_text_(allowed_text), allowed_(number_list(allowed_text)) {}

  // The literals of the body that is node `body` of `nodes`.
  void check_body(const NodeList& nodes, uint32_t body) {
    static const TSFieldId kLabel = NodeList::field_id("label");
    static const TSFieldId kMember = NodeList::field_id("member");
    static const TSFieldId kIndex = NodeList::field_id("index");
    static const TSFieldId kOperand = NodeList::field_id("operand");
    nodes.walk(body, [&](uint32_t i) {
      if (nodes.is_extra(i) || (!exempt_.empty() && exempt_.count({nodes.begin(i), nodes.end(i)}))) return false;
      const std::string_view kind = nodes.kind(i);
      if (kind == "case_element") {
        nodes.for_each_child(i, [&](uint32_t label) {
          if (nodes.field(label) == kLabel) exempt_.insert({nodes.begin(label), nodes.end(label)});
        });
      } else if (kind == "member_expression") {
        // x.3: the number picks a bit of x.
        if (const uint32_t member = nodes.child_by_field(i, kMember);
            member != NodeList::kNone && is_number_literal(nodes.kind(member))) {
          exempt_.insert({nodes.begin(member), nodes.end(member)});
        }
      } else if (kind == "index_expression") {
        // a[3]: the number picks an element (filling an array element by element is common).
        nodes.for_each_child(i, [&](uint32_t index) {
          if (nodes.field(index) == kIndex && is_number_literal(nodes.kind(index))) {
            exempt_.insert({nodes.begin(index), nodes.end(index)});
          }
        });
      } else if (kind == "unary_expression") {
        const uint32_t operand = nodes.child_by_field(i, kOperand);
        if (operand != NodeList::kNone && is_number_literal(nodes.kind(operand)) && operator_text(nodes, i) == "-") {
          check_literal(nodes.node(operand), nodes.range(i), true);
          return false;
        }
      } else if (is_number_literal(kind)) {
        check_literal(nodes.node(i), nodes.range(i), false);
        return false;
      }
      return nodes.has_children(i);
    });
  }

 private:
  void check_literal(SyntaxNode literal, TextRange shown, bool negative) {
    std::optional<double> value = literal_value(literal.text(), literal.kind() == "real_literal");
    if (!value) return;
    if (negative) *value = -*value;
    for (double allowed : allowed_) {
      if (std::fabs(allowed - *value) <= 1e-12 * std::max(1.0, std::fabs(allowed))) return;
    }
    const std::string_view text = context_.text().substr(shown.begin, shown.end - shown.begin);
    const bool real = literal.kind() == "real_literal";
    context_.report("L050", fmt::format("magic number {}: give it a name", text), shown,
                    fmt::format("declare a constant (e.g. VAR CONSTANT {} : {} := {}; END_VAR) so the number says "
                                "what it means and changes in one place; rung.toml [lint.naming] allowed_numbers = "
                                "\"{}\" lists the numbers that need no name",
                                real ? "rLimit" : "iLimit", real ? "REAL" : "INT", text, allowed_text_));
  }

  LintContext& context_;
  std::string_view allowed_text_;
  std::vector<double> allowed_;
  std::set<std::pair<uint32_t, uint32_t>> exempt_;  // CASE labels, bit numbers, array indices
};

}  // namespace

void check_magic_number(LintContext& context) {
  MagicNumbers check(context, context.naming("allowed_numbers", kDefaultAllowed));
  for (const check::Symbol* pou : context.pous()) {
    for (SyntaxNode body : bodies_of(*pou)) check.check_body(context.nodes(), context.nodes().index_of(body));
  }
}

}  // namespace rung::lint::structure
