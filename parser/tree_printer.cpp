#include "parser/tree_printer.hpp"

#include <fmt/format.h>

#include <vector>

namespace rung {
namespace {

std::string quoted(std::string_view text) {
  std::string out = "\"";
  size_t shown = 0;
  for (char c : text) {
    if (++shown > 60) {
      out += "...";
      break;
    }
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\t': out += "\\t"; break;
      default: out += c;
    }
  }
  out += '"';
  return out;
}

}  // namespace

std::string print_outline(SyntaxNode root, const TreePrintOptions& options) {
  std::string out;
  if (!root) return out;
  struct Item {
    SyntaxNode node;
    std::string_view field;
    uint32_t depth;
  };
  std::vector<Item> stack{{root, {}, 0}};
  while (!stack.empty()) {
    Item item = stack.back();
    stack.pop_back();
    SyntaxNode n = item.node;
    out.append(item.depth * 2, ' ');
    if (!item.field.empty()) fmt::format_to(std::back_inserter(out), "{}: ", item.field);
    if (n.is_missing()) {
      fmt::format_to(std::back_inserter(out), "MISSING {}", n.kind());
    } else if (n.is_named()) {
      out += n.kind();
    } else {
      out += quoted(n.kind());
    }
    if (options.describe_position) {
      fmt::format_to(std::back_inserter(out), " [{}-{}]", options.describe_position(n.begin()),
                     options.describe_position(n.end()));
    } else {
      fmt::format_to(std::back_inserter(out), " [{}-{}]", n.begin(), n.end());
    }
    bool leaf = n.named_child_count() == 0;
    if (options.include_text && leaf && n.is_named() && !n.is_missing()) {
      out += ' ';
      out += quoted(n.text());
    }
    out += '\n';
    uint32_t count = n.child_count();
    for (uint32_t i = count; i-- > 0;) {
      SyntaxNode c = n.child(i);
      if (!c.is_named() && !c.is_missing() && !options.include_anonymous) continue;
      stack.push_back({c, n.field_name_of_child(i), item.depth + 1});
    }
  }
  return out;
}

std::string print_sexp(SyntaxNode root) {
  if (!root) return {};
  char* s = ts_node_string(root.raw());
  std::string out(s);
  free(s);
  return out;
}

}  // namespace rung
