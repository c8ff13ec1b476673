#include "formatter/syntax_kinds.hpp"

#include <string_view>
#include <utility>
#include <vector>

#include "parser/syntax_tree.hpp"

namespace rung::format {
namespace {

constexpr std::pair<std::string_view, NodeKind> kNamedKinds[] = {
    {"source_file", NodeKind::SourceFile},
    {"statement_list", NodeKind::StatementList},
    {"if_statement", NodeKind::IfStatement},
    {"elsif_clause", NodeKind::ElsifClause},
    {"else_clause", NodeKind::ElseClause},
    {"case_statement", NodeKind::CaseStatement},
    {"case_element", NodeKind::CaseElement},
    {"for_statement", NodeKind::ForStatement},
    {"while_statement", NodeKind::WhileStatement},
    {"repeat_statement", NodeKind::RepeatStatement},
    {"try_statement", NodeKind::TryStatement},
    {"catch_clause", NodeKind::CatchClause},
    {"finally_clause", NodeKind::FinallyClause},
    {"var_block", NodeKind::VarBlock},
    {"generic_constant_block", NodeKind::GenericConstantBlock},
    {"var_declaration", NodeKind::VarDeclaration},
    {"empty_declaration", NodeKind::EmptyDeclaration},
    {"access_declaration", NodeKind::AccessDeclaration},
    {"struct_type", NodeKind::StructType},
    {"union_type", NodeKind::UnionType},
    {"enum_type", NodeKind::EnumType},
    {"enum_value", NodeKind::EnumValue},
    {"alias_type", NodeKind::AliasType},
    {"type_declaration", NodeKind::TypeDeclaration},
    {"program_declaration", NodeKind::Program},
    {"function_declaration", NodeKind::Function},
    {"function_block_declaration", NodeKind::FunctionBlock},
    {"class_declaration", NodeKind::Class},
    {"method_declaration", NodeKind::Method},
    {"property_declaration", NodeKind::Property},
    {"property_accessor", NodeKind::PropertyAccessor},
    {"interface_declaration", NodeKind::Interface},
    {"action_declaration", NodeKind::Action},
    {"transition_declaration", NodeKind::TransitionDeclaration},
    {"namespace_declaration", NodeKind::Namespace},
    {"using_directive", NodeKind::UsingDirective},
    {"configuration_declaration", NodeKind::Configuration},
    {"resource_declaration", NodeKind::Resource},
    {"task_configuration", NodeKind::TaskConfiguration},
    {"program_configuration", NodeKind::ProgramConfiguration},
    {"il_body", NodeKind::IlBody},
    {"il_instruction", NodeKind::IlInstruction},
    {"il_expression", NodeKind::IlExpression},
    {"il_label", NodeKind::IlLabel},
    {"il_operator", NodeKind::IlOperator},
    {"sfc_network", NodeKind::SfcNetwork},
    {"sfc_step", NodeKind::SfcStep},
    {"sfc_action", NodeKind::SfcAction},
    {"sfc_transition", NodeKind::SfcTransition},
    {"sfc_action_block", NodeKind::SfcActionBlock},
    {"sfc_step_macro", NodeKind::SfcStepMacro},
    {"label", NodeKind::Label},
    {"expression_fragment", NodeKind::ExpressionFragment},
    {"binary_expression", NodeKind::BinaryExpression},
    {"unary_expression", NodeKind::UnaryExpression},
    {"argument_list", NodeKind::ArgumentList},
    {"argument_lists", NodeKind::ArgumentLists},
    {"call_expression", NodeKind::CallExpression},
    {"parenthesized_expression", NodeKind::ParenthesizedExpression},
    {"index_expression", NodeKind::IndexExpression},
    {"global_reference", NodeKind::GlobalReference},
    {"typed_literal", NodeKind::TypedLiteral},
    {"generic_type", NodeKind::GenericType},
    {"variadic_type", NodeKind::VariadicType},
    {"string_type", NodeKind::StringType},
    {"array_type", NodeKind::ArrayType},
    {"subrange_type", NodeKind::SubrangeType},
    {"array_initializer", NodeKind::ArrayInitializer},
    {"struct_initializer", NodeKind::StructInitializer},
    {"repeated_initializer", NodeKind::RepeatedInitializer},
    {"type_name", NodeKind::TypeName},
    {"identifier", NodeKind::Identifier},
    {"comment", NodeKind::Comment},
    {"pragma", NodeKind::Pragma},
    {"var_qualifier", NodeKind::VarQualifier},
    {"modifier", NodeKind::Modifier},
};

constexpr std::pair<std::string_view, TokenClass> kPunctuation[] = {
    {",", TokenClass::Comma},      {";", TokenClass::Semicolon},   {"(", TokenClass::OpenParen},
    {")", TokenClass::CloseParen}, {"[", TokenClass::OpenBracket}, {"]", TokenClass::CloseBracket},
    {".", TokenClass::Dot},        {"..", TokenClass::Range},      {"^", TokenClass::Caret},
    {"#", TokenClass::Hash},       {":", TokenClass::Colon},       {":=", TokenClass::Assign},
    {"=>", TokenClass::Assign},    {"?=", TokenClass::Assign},     {"S=", TokenClass::Assign},
    {"R=", TokenClass::Assign},    {"REF=", TokenClass::Assign},   {"@", TokenClass::At},
    {"+", TokenClass::Operator},   {"-", TokenClass::Operator},    {"*", TokenClass::Operator},
    {"/", TokenClass::Operator},   {"**", TokenClass::Operator},   {"=", TokenClass::Operator},
    {"<>", TokenClass::Operator},  {"<", TokenClass::Operator},    {">", TokenClass::Operator},
    {"<=", TokenClass::Operator},  {">=", TokenClass::Operator},   {"&", TokenClass::Operator},
};

// The grammar shows every keyword by its upper-case spelling (kw(), kwAs()); punctuation and
// aliases like 'unreachable' are not words of capitals.
bool is_keyword_name(std::string_view name) {
  bool letter = false;
  for (char c : name) {
    if (c >= 'A' && c <= 'Z') {
      letter = true;
    } else if (c != '_' && c != '=') {
      return false;
    }
  }
  return letter;
}

std::vector<SymbolInfo> build_table() {
  const TSLanguage* language = tree_sitter_iec61131();
  const uint32_t count = ts_language_symbol_count(language);
  std::vector<SymbolInfo> table(count);
  for (uint32_t id = 0; id < count; ++id) {
    const TSSymbol symbol = static_cast<TSSymbol>(id);
    const char* raw = ts_language_symbol_name(language, symbol);
    if (!raw) continue;
    const std::string_view name(raw);
    SymbolInfo& info = table[id];
    info.named = ts_language_symbol_type(language, symbol) == TSSymbolTypeRegular;
    if (info.named) {
      for (const auto& [kind_name, kind] : kNamedKinds)
        if (kind_name == name) info.node = kind;
      info.keyword = info.node == NodeKind::VarQualifier || info.node == NodeKind::Modifier;
      continue;
    }
    for (const auto& [text, token] : kPunctuation)
      if (text == name) info.token = token;
    if (is_keyword_name(name)) {
      info.keyword = true;
      info.closer = name.substr(0, 4) == "END_" || name == "UNTIL" || name == "__ENDTRY";
      info.middle = name == "ELSE" || name == "ELSIF" || name == "__CATCH" || name == "__FINALLY";
      if (info.token == TokenClass::Other) info.token = TokenClass::Keyword;
    }
  }
  return table;
}

}  // namespace

const SymbolInfo& symbol_info(TSSymbol symbol) {
  static const std::vector<SymbolInfo> table = build_table();
  static const SymbolInfo none;
  return symbol < table.size() ? table[symbol] : none;
}

}  // namespace rung::format
