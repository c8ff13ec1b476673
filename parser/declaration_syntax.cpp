#include "parser/declaration_syntax.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>

#include "parser/diagnostic_codes.hpp"
#include "parser/keywords.hpp"

namespace rung {
namespace {

using keywords::upper;

template <size_t N>
bool one_of(const std::array<std::string_view, N>& kinds, std::string_view kind) {
  return std::find(kinds.begin(), kinds.end(), kind) != kinds.end();
}

// Nodes whose children may declare names or hold IL; everything else (statements, expressions,
// type specifications) is never entered.
constexpr auto kContainers = std::to_array<std::string_view>({
    "source_file",
    "program_declaration",
    "function_declaration",
    "function_block_declaration",
    "class_declaration",
    "method_declaration",
    "property_declaration",
    "property_accessor",
    "interface_declaration",
    "action_declaration",
    "transition_declaration",
    "namespace_declaration",
    "generic_constant_block",
    "var_block",
    "var_declaration",
    "type_declaration",
    "struct_type",
    "union_type",
    "enum_type",
    "enum_value",
    "alias_type",
    "il_body",
    "il_instruction",
    "sfc_network",
    "sfc_action_block",
    "sfc_transition",
    "configuration_declaration",
    "resource_declaration",
});

// Nodes whose `name` field declares the name (a label, an argument or a step action refers to one).
constexpr auto kDeclaring = std::to_array<std::string_view>({
    "program_declaration",
    "function_declaration",
    "function_block_declaration",
    "class_declaration",
    "method_declaration",
    "property_declaration",
    "interface_declaration",
    "action_declaration",
    "var_declaration",
    "struct_type",
    "union_type",
    "enum_type",
    "alias_type",
    "enum_value",
});

class DeclarationChecker {
 public:
  DeclarationChecker(const SyntaxTree& tree, const std::function<void(SyntaxFinding)>& report)
      : tree_(tree), report_(report) {}

  void run() {
    SyntaxNode root = tree_.root();
    if (!root) return;
    visit_children(root, "source_file");
  }

 private:
  // Visits the children of `node` (of kind `parent`), and the children of containers below.
  void visit_children(SyntaxNode parent_node, std::string_view parent) {
    const bool declaring = one_of(kDeclaring, parent);
    parent_node.for_each_child([&](SyntaxNode node) {
      if (node.is_error() || node.is_missing() || node.is_extra()) return;
      const std::string_view kind = node.kind();
      const std::string_view field_name = NodeTable::field_name(node.field_id());
      if (declaring && field_name == "name" && kind == "identifier") check_declared_name(node, parent);
      if (parent == "il_instruction" && field_name == "operator") check_il_operator(node);
      if (parent == "source_file" && kind == "expression_fragment") check_fragment(node);
      if (kind == "struct_type") check_struct_colon(node);
      // (a declaration line at top level may be an echo of error recovery)
      if (kind == "var_declaration" && parent != "source_file") check_declaration_has_name(node);
      if (one_of(kContainers, kind)) visit_children(node, kind);
    });
  }

  void check_declared_name(SyntaxNode name, std::string_view declaration) {
    std::string_view text = name.text();
    std::string what = declaration == "var_declaration"                      ? "a variable"
                       : declaration == "enum_value"                         ? "an enumeration value"
                       : declaration.find("_type") != std::string_view::npos ? "a data type"
                                                                             : "a POU";
    // The IEC library declares AND, OR, XOR, NOT and MOD as standard functions.
    bool standard_function = declaration == "function_declaration" && keywords::is_operator_word(text);
    if (keywords::is_reserved(text) && !standard_function) {
      report(codes::kSyntaxError, name.range(),
             fmt::format("'{}' is a reserved keyword and cannot name {}", text, what),
             "choose another name (keywords are reserved in any letter case)");
      return;
    }
    if (text.find("__") != std::string_view::npos) {
      report(codes::kSyntaxError, name.range(), fmt::format("'{}' is not a valid name: two underscores in a row", text),
             "use single underscores; names with '__' are reserved for the system (__NEW, __SYSTEM)");
    }
  }

  // Only a located variable may go without a name (AT %IX0.0 : BOOL;). "Retain : INT;" as the
  // first line of a VAR block reads as the qualifier RETAIN before a declaration without a name.
  void check_declaration_has_name(SyntaxNode declaration) {
    if (declaration.child_by_field("name") || declaration.child_by_field("location")) return;
    SyntaxNode first = declaration.child(0);
    if (!first) return;
    SyntaxNode before = declaration.prev_sibling();
    while (before && before.is_extra()) before = before.prev_sibling();
    if (before && before.kind() == "var_qualifier") {
      report(codes::kSyntaxError, before.range(),
             fmt::format("'{}' is a reserved keyword and cannot name a variable", before.text()),
             "choose another name (keywords are reserved in any letter case)");
      return;
    }
    report(codes::kSyntaxError, first.range(), fmt::format("declaration without a name before '{}'", first.text()),
           "write the name of the variable first: name : type;");
  }

  // TYPE S STRUCT ... END_STRUCT: the grammar lets the ':' out so that the members are still read.
  void check_struct_colon(SyntaxNode type) {
    SyntaxNode name = type.child_by_field("name");
    if (!name) return;  // STRUCT written inside a declaration has no name and no ':'
    for (uint32_t i = 0, n = type.child_count(); i < n; ++i) {
      SyntaxNode c = type.child(i);
      if (c.text() == ":") return;
      if (!c.is_named() && upper(c.text()) == "STRUCT") break;
    }
    report(codes::kMissingToken, {name.end(), name.end()},
           fmt::format("missing ':' after the type name '{}'", name.text()),
           fmt::format("write TYPE {} : STRUCT", name.text()));
  }

  // An unknown word at the start of a line parses as an IL operator (a function call in IL).
  void check_il_operator(SyntaxNode op) {
    std::string word = upper(op.text());
    if (keywords::is_il_operator(word)) return;
    // TIME (CODESYS TIME()) and the other type names are functions too.
    if (keywords::is_reserved(word) && !keywords::is_type_name(word)) {
      report_(stray_keyword(op));
      return;
    }
    report_misspelling(op);
  }

  // A misspelled opener alone on a line at top level (VAR_GLOBAS) is an expression fragment.
  void check_fragment(SyntaxNode fragment) {
    SyntaxNode value = fragment.child_by_field("value");
    if (value && value.kind() == "identifier") report_misspelling(value);
  }

  void report_misspelling(SyntaxNode word) {
    std::string_view meant = keywords::misspelled(word.text(), true);
    if (meant.empty()) return;
    report(codes::kMisspelledKeyword, word.range(),
           fmt::format("'{}' is not a keyword — did you mean {}?", word.text(), meant), fmt::format("write {}", meant),
           keywords::closer_of(meant));
  }

  void report(std::string_view code, TextRange range, std::string message, std::string help,
              std::string_view explains_closer = {}) {
    report_(SyntaxFinding{code, range, std::move(message), std::move(help), explains_closer, {}});
  }

  const SyntaxTree& tree_;
  const std::function<void(SyntaxFinding)>& report_;
};

}  // namespace

SyntaxFinding stray_keyword(SyntaxNode keyword) {
  std::string word = upper(keyword.text());
  bool closer = word.rfind("END_", 0) == 0;
  SyntaxFinding f{codes::kSyntaxError,
                  keyword.range(),
                  closer ? fmt::format("unexpected '{}': no {} block is open here", keyword.text(), word.substr(4))
                         : fmt::format("unexpected keyword '{}'", keyword.text()),
                  closer ? fmt::format("remove it, or open the block that {} closes", word) : std::string{},
                  {},
                  word};
  return f;
}

void check_declaration_syntax(const SyntaxTree& tree, const std::function<void(SyntaxFinding)>& report) {
  DeclarationChecker(tree, report).run();
}

}  // namespace rung
