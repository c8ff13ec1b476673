#include "parser/tree_printer.hpp"

#include <fmt/format.h>

#include <cctype>
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

// Calls visit(node, depth) for `root` and every node below it in preorder; iterative.
template <typename Visit>
void walk_with_depth(SyntaxNode root, Visit&& visit) {
  std::vector<uint32_t> open_ends;  // subtree ends of the ancestors of the current node
  walk_preorder(root, [&](SyntaxNode node) {
    while (!open_ends.empty() && open_ends.back() <= node.index()) open_ends.pop_back();
    visit(node, static_cast<uint32_t>(open_ends.size()));
    open_ends.push_back(node.subtree_end());
    return true;
  });
}

}  // namespace

std::string print_outline(SyntaxNode root, const TreePrintOptions& options) {
  std::string out;
  walk_with_depth(root, [&](SyntaxNode n, uint32_t depth) {
    if (!(n.is_named() || n.is_missing() || options.include_anonymous)) return;
    out.append(size_t{depth} * 2, ' ');
    const std::string_view field = depth > 0 ? NodeTable::field_name(n.field_id()) : std::string_view();
    if (!field.empty()) fmt::format_to(std::back_inserter(out), "{}: ", field);
    if (n.is_missing()) {
      fmt::format_to(std::back_inserter(out), "MISSING {}", n.kind());
    } else if (n.is_named()) {
      out += n.kind();
    } else {
      out += quoted(n.kind());
    }
    if (options.describe_position) {
      const auto& describe_end =
          options.describe_end_position ? options.describe_end_position : options.describe_position;
      fmt::format_to(std::back_inserter(out), " [{}-{}]", options.describe_position(n.begin()), describe_end(n.end()));
    } else {
      fmt::format_to(std::back_inserter(out), " [{}-{}]", n.begin(), n.end());
    }
    if (options.include_text && n.named_child_count() == 0 && n.is_named() && !n.is_missing()) {
      out += ' ';
      out += quoted(n.text());
    }
    out += '\n';
  });
  return out;
}

namespace {

// The first character of `text` as tree-sitter's S-expressions show an unexpected character.
std::string unexpected_char(std::string_view text) {
  if (text.empty()) return "INVALID";
  const auto byte = static_cast<unsigned char>(text[0]);
  switch (byte) {
    case '\n': return "'\\n'";
    case '\t': return "'\\t'";
    case '\r': return "'\\r'";
    case '\0': return "'\\0'";
    default: break;
  }
  if (byte < 128 && std::isprint(byte)) return fmt::format("'{}'", static_cast<char>(byte));
  // A UTF-8 sequence: its code point, in decimal.
  uint32_t code = byte;
  size_t length = 1;
  if ((byte & 0xE0) == 0xC0) {
    code = byte & 0x1F;
    length = 2;
  } else if ((byte & 0xF0) == 0xE0) {
    code = byte & 0x0F;
    length = 3;
  } else if ((byte & 0xF8) == 0xF0) {
    code = byte & 0x07;
    length = 4;
  }
  for (size_t i = 1; i < length && i < text.size(); ++i)
    code = (code << 6) | (static_cast<unsigned char>(text[i]) & 0x3F);
  return std::to_string(code);
}

}  // namespace

// The format of tree-sitter's ts_node_string: named and missing nodes, with their fields.
std::string print_sexp(SyntaxNode root) {
  std::string out;
  std::vector<uint32_t> open_ends;  // subtree ends of the printed ancestors still open
  walk_with_depth(root, [&](SyntaxNode n, uint32_t depth) {
    while (!open_ends.empty() && open_ends.back() <= n.index()) {
      out += ')';
      open_ends.pop_back();
    }
    if (!(n.is_named() || n.is_missing())) return;
    if (n != root) out += ' ';
    const std::string_view field = depth > 0 ? NodeTable::field_name(n.field_id()) : std::string_view();
    if (!field.empty() && n != root) fmt::format_to(std::back_inserter(out), "{}: ", field);
    if (n.is_error() && n.child_count() == 0 && n.end() > n.begin()) {
      out += "(UNEXPECTED " + unexpected_char(n.text());
    } else if (n.is_missing()) {
      out += "(MISSING ";
      if (n.is_named()) {
        out += n.kind();
      } else {
        fmt::format_to(std::back_inserter(out), "\"{}\"", n.kind());
      }
    } else {
      fmt::format_to(std::back_inserter(out), "({}", n.kind());
    }
    open_ends.push_back(n.subtree_end());
  });
  out.append(open_ends.size(), ')');
  return out;
}

}  // namespace rung
