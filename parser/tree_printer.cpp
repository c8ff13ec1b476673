#include "parser/tree_printer.hpp"

#include <fmt/format.h>

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
  // A cursor walk: iterative (deep trees are fine) and it knows each child's field name.
  TSTreeCursor cursor = ts_tree_cursor_new(root.raw());
  uint32_t depth = 0;
  while (true) {
    SyntaxNode n(ts_tree_cursor_current_node(&cursor), root.source());
    if (n.is_named() || n.is_missing() || options.include_anonymous) {
      out.append(size_t{depth} * 2, ' ');
      const char* field = depth > 0 ? ts_tree_cursor_current_field_name(&cursor) : nullptr;
      if (field) fmt::format_to(std::back_inserter(out), "{}: ", field);
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
        fmt::format_to(std::back_inserter(out), " [{}-{}]", options.describe_position(n.begin()),
                       describe_end(n.end()));
      } else {
        fmt::format_to(std::back_inserter(out), " [{}-{}]", n.begin(), n.end());
      }
      if (options.include_text && n.named_child_count() == 0 && n.is_named() && !n.is_missing()) {
        out += ' ';
        out += quoted(n.text());
      }
      out += '\n';
    }
    if (ts_tree_cursor_goto_first_child(&cursor)) {
      ++depth;
      continue;
    }
    bool done = false;
    while (!ts_tree_cursor_goto_next_sibling(&cursor)) {
      if (depth == 0 || !ts_tree_cursor_goto_parent(&cursor)) {
        done = true;
        break;
      }
      --depth;
    }
    if (done || depth == 0) break;
  }
  ts_tree_cursor_delete(&cursor);
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
