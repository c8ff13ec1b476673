#include "parser/conditional_branches.hpp"

#include <cctype>
#include <string_view>
#include <vector>

namespace rung {
namespace {

enum class Directive { If, ElsIf, Else, EndIf, Other };

// The directive of a conditional pragma's text, e.g. "IF defined (DEBUG)" -> If.
Directive directive_of(std::string_view text) {
  size_t i = 0;
  while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
  std::string word;
  while (i < text.size() && (std::isalnum(static_cast<unsigned char>(text[i])) || text[i] == '_')) {
    word += static_cast<char>(std::toupper(static_cast<unsigned char>(text[i])));
    ++i;
  }
  if (word == "IF") return Directive::If;
  if (word == "ELSIF") return Directive::ElsIf;
  if (word == "ELSE") return Directive::Else;
  if (word == "END_IF") return Directive::EndIf;
  return Directive::Other;
}

struct Marker {
  Directive directive;
  uint32_t begin;  // start of the whole {...} pragma
};

}  // namespace

size_t keep_first_conditional_branches(const SyntaxTree& tree, std::string& text) {
  if (!tree.root()) return 0;
  // Conditional pragmas in text order.
  std::vector<Marker> markers;
  for_each_pragma(tree.root(), [&](SyntaxNode n) {
    SyntaxNode c = n.first_child_of_kind("conditional_pragma");
    if (c) markers.push_back({directive_of(c.text()), n.begin()});
  });
  size_t blanked = 0;
  // For each group: once a second branch starts, blank up to the group's {END_IF}.
  struct Group {
    bool skipping = false;
    uint32_t from = 0;
  };
  std::vector<Group> groups;
  auto blank = [&](uint32_t from, uint32_t to) {
    for (uint32_t k = from; k < to && k < text.size(); ++k) {
      if (text[k] != '\n' && text[k] != '\r') {
        text[k] = ' ';
        ++blanked;
      }
    }
  };
  for (const Marker& m : markers) {
    switch (m.directive) {
      case Directive::If: groups.push_back({}); break;
      case Directive::ElsIf:
      case Directive::Else:
        if (!groups.empty() && !groups.back().skipping) groups.back() = {true, m.begin};
        break;
      case Directive::EndIf:
        if (!groups.empty()) {
          if (groups.back().skipping) blank(groups.back().from, m.begin);
          groups.pop_back();
        }
        break;
      case Directive::Other: break;
    }
  }
  return blanked;
}

}  // namespace rung
