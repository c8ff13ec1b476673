#include "formatter/keyword_case.hpp"

#include "parser/keywords.hpp"

namespace rung::format {

CaseClass case_class(const SymbolInfo& leaf, LeafPlace place, std::string_view text) {
  if (leaf.keyword) return CaseClass::Keyword;
  if (leaf.node == NodeKind::IlOperator) return keywords::is_il_operator(text) ? CaseClass::Keyword : CaseClass::None;
  if (leaf.node != NodeKind::Identifier) return CaseClass::None;
  const bool type_position = (place.parent == NodeKind::TypeName && place.only_child) ||
                             (place.parent == NodeKind::TypedLiteral && place.first_child);
  return type_position && keywords::is_type_name(text) ? CaseClass::ElementaryType : CaseClass::None;
}

void append_in_case(std::string& out, std::string_view text, CaseClass cls, const project::FormatSettings& settings) {
  const bool change =
      cls == CaseClass::Keyword || (cls == CaseClass::ElementaryType && settings.elementary_types_follow_keyword_case);
  if (!change || settings.keyword_case == project::KeywordCase::Preserve) {
    out += text;
    return;
  }
  const bool to_upper = settings.keyword_case == project::KeywordCase::Upper;
  for (char c : text) {
    if (to_upper && c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
    if (!to_upper && c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    out += c;
  }
}

bool equal_ignoring_case(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i) {
    char x = a[i];
    char y = b[i];
    if (x >= 'a' && x <= 'z') x = static_cast<char>(x - 'a' + 'A');
    if (y >= 'a' && y <= 'z') y = static_cast<char>(y - 'a' + 'A');
    if (x != y) return false;
  }
  return true;
}

}  // namespace rung::format
