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

  void check_body(SyntaxNode body) {
    walk_preorder(body, [&](SyntaxNode node) {
      if (node.is_extra() || exempt_.count({node.begin(), node.end()})) return false;
      const std::string_view kind = node.kind();
      if (kind == "case_element") {
        for (SyntaxNode label : node.children_by_field("label")) exempt_.insert({label.begin(), label.end()});
      } else if (kind == "member_expression") {
        // x.3: the number picks a bit of x.
        if (SyntaxNode member = node.child_by_field("member"); member && is_number_literal(member.kind())) {
          exempt_.insert({member.begin(), member.end()});
        }
      } else if (kind == "index_expression") {
        // a[3]: the number picks an element (filling an array element by element is common).
        for (SyntaxNode index : node.children_by_field("index")) {
          if (is_number_literal(index.kind())) exempt_.insert({index.begin(), index.end()});
        }
      } else if (kind == "unary_expression") {
        const SyntaxNode operand = node.child_by_field("operand");
        if (operand && is_number_literal(operand.kind()) && ast::operator_of(node) == "-") {
          check_literal(operand, node.range(), true);
          return false;
        }
      } else if (is_number_literal(kind)) {
        check_literal(node, node.range(), false);
        return false;
      }
      return node.child_count() > 0;
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
    for (SyntaxNode body : bodies_of(*pou)) check.check_body(body);
  }
}

}  // namespace rung::lint::structure
