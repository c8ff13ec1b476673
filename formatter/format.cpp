// format_text: parse, refuse broken files, apply the sanctioned token rewrites, lay out (walk,
// spacing, alignment, line breaking until nothing is too long that can be broken), print, and
// check the result against the input before handing it out.
#include "formatter/format.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <optional>

#include "formatter/layout_walk.hpp"
#include "formatter/line_breaking.hpp"
#include "formatter/printer.hpp"
#include "formatter/rewrites.hpp"
#include "formatter/token_check.hpp"
#include "formatter/whitespace_check.hpp"
#include "parser/source/flat_comments.hpp"
#include "parser/syntax_diagnostics.hpp"

namespace rung::format {
namespace {

uint32_t line_of(std::string_view text, uint32_t offset) {
  offset = std::min<uint32_t>(offset, static_cast<uint32_t>(text.size()));
  return 1 + static_cast<uint32_t>(std::count(text.begin(), text.begin() + offset, '\n'));
}

SyntaxTree parse(std::string_view text, bool flat_comments) {
  std::string copy(text);
  if (flat_comments) source::read_comments_flat(copy, 0, copy.size());
  return SyntaxTree::parse(std::move(copy));
}

// The scanner lets a comment that is never closed run to the end of the file: a valid token, but
// a broken file (the syntax checks report it), and one whose last bytes the layout would change.
// The last leaf with text (a pragma counts as one leaf).
SyntaxNode last_leaf(const SyntaxTree& tree) {
  SyntaxNode node = tree.root();
  while (node.child_count() > 0 && node.kind() != "pragma") {
    SyntaxNode last;
    for (uint32_t i = node.child_count(); i-- > 0;) {
      if (node.child(i).end() > node.child(i).begin()) {
        last = node.child(i);
        break;
      }
    }
    if (!last) break;
    node = last;
  }
  return node;
}

bool ends_in_open_comment(const SyntaxTree& tree, bool flat_comments) {
  const SyntaxNode node = last_leaf(tree);
  const std::string_view text = node.text();
  if (node.kind() != "comment" || text.size() < 2) return false;
  if (text.substr(0, 2) == "/*") return text.size() < 4 || text.substr(text.size() - 2) != "*/";
  if (text.substr(0, 2) != "(*") return false;
  if (flat_comments) return text.size() < 4 || text.substr(text.size() - 2) != "*)";
  int depth = 0;
  for (size_t i = 0; i + 1 < text.size(); ++i) {
    if (text[i] == '(' && text[i + 1] == '*') {
      ++depth;
      ++i;
    } else if (text[i] == '*' && text[i + 1] == ')') {
      --depth;
      ++i;
    }
  }
  return depth > 0;
}

bool parses_cleanly(const SyntaxTree& tree, bool flat_comments) {
  return !tree.aborted() && !tree.root().has_error() && !ends_in_open_comment(tree, flat_comments);
}

// "line N: ..." for the first syntax error of a tree that does not parse.
std::string first_syntax_error(const SyntaxTree& tree, std::string_view text) {
  if (tree.aborted()) return "line 1: parsing stopped: the file is too large or too deeply nested";
  if (!tree.root().has_error()) {
    // The only error without an ERROR node: a comment left open at the end of the file.
    return fmt::format("line {}: comment opened here is never closed", line_of(text, last_leaf(tree).begin()));
  }
  SyntaxDiagnosticOptions options;
  options.describe_position = [&](uint32_t offset) {
    uint32_t line_start = offset;
    while (line_start > 0 && text[line_start - 1] != '\n') --line_start;
    return fmt::format("{}:{}", line_of(text, offset), offset - line_start + 1);
  };
  options.max_errors = 1;
  std::vector<Diagnostic> found = collect_syntax_diagnostics(tree, options);
  sort_diagnostics(found);
  for (const Diagnostic& d : found) {
    if (d.severity == Severity::Error) return fmt::format("line {}: {}", line_of(text, d.range.begin), d.message);
  }
  // No diagnostic explains it: name the first ERROR or MISSING node.
  uint32_t at = 0;
  bool seen = false;
  walk_preorder(tree.root(), [&](SyntaxNode node) {
    if (seen) return false;
    if (node.is_error() || node.is_missing()) {
      at = node.begin();
      seen = true;
      return false;
    }
    return node.has_error();
  });
  return fmt::format("line {}: syntax error", line_of(text, at));
}

struct Printed {
  std::string text;
  std::vector<Leaf> leaves;  // the tokens, comments and pragmas it was printed from
};

Printed lay_out_and_print(const SyntaxTree& tree, std::string_view text, const project::FormatSettings& settings) {
  std::vector<uint32_t> breaks;
  WalkOptions options;
  options.collect_breaks = settings.max_line_width > 0;
  options.added_breaks = &breaks;
  WalkResult walk = walk_leaves(tree, text, options);
  Layout layout = lay_out(walk, text, settings);
  // Each round breaks every line that is still too long where it can; a round that finds nothing
  // ends it. Rounds are few (one per nesting of broken calls); the bound only guards the loop.
  for (int round = 0; round < 100 && add_line_breaks(walk, layout, text, settings, breaks); ++round) {
    walk = walk_leaves(tree, text, options);
    layout = lay_out(walk, text, settings);
  }
  std::string printed = print(walk, layout, text, settings);
  return {std::move(printed), std::move(walk.leaves)};
}

}  // namespace

FormatResult format_text(std::string_view text, const project::FormatSettings& settings, const FormatRequest& request) {
  bool flat = request.flat_comments;
  SyntaxTree tree = parse(text, flat);
  if (!parses_cleanly(tree, flat) && !flat) {
    // As Document does for plain files: MATIEC and CODESYS 2.3 code does not nest comments, and
    // "(* old (* code *)" only parses when read flat.
    std::string copy(text);
    if (source::read_comments_flat(copy, 0, copy.size()) > 0) {
      SyntaxTree flat_tree = SyntaxTree::parse(std::move(copy));
      if (parses_cleanly(flat_tree, true)) {
        tree = std::move(flat_tree);
        flat = true;
      }
    }
  }
  FormatRequest read_as = request;
  read_as.flat_comments = flat;
  return format_parsed(tree, text, settings, read_as);
}

FormatResult format_parsed(const SyntaxTree& tree, std::string_view text, const project::FormatSettings& settings,
                           const FormatRequest& request) {
  FormatResult result;
  result.text = std::string(text);
  auto refuse = [&](Status status, std::string message) {
    result.status = status;
    result.message = std::move(message);
    return result;
  };
  const bool flat = request.flat_comments;
  if (!parses_cleanly(tree, flat)) return refuse(Status::SyntaxErrors, first_syntax_error(tree, text));

  // END_ ';' and ELSE IF rewrites first, on the text; the layout then works on the rewritten
  // text's own tree, so that the result formats to itself.
  std::vector<Rewrite> rewrites = plan_rewrites(tree, text, settings);
  std::string rewritten;
  std::optional<SyntaxTree> rewritten_tree;
  if (!rewrites.empty()) {
    rewritten = apply_rewrites(tree, text, rewrites);
    rewritten_tree.emplace(parse(rewritten, flat));
    if (!parses_cleanly(*rewritten_tree, flat)) {
      rewrites.clear();  // cannot happen for a sound plan; format without the rewrites then
      rewritten_tree.reset();
    }
  }
  const SyntaxTree& layout_tree = rewritten_tree ? *rewritten_tree : tree;
  const std::string_view layout_text = rewritten_tree ? std::string_view(rewritten) : text;

  Printed printed = lay_out_and_print(layout_tree, layout_text, settings);
  std::string& formatted = printed.text;

  // A result that only moves whitespace in ways the grammar cannot notice is proven safe
  // without parsing it; rewrites, comments read flat and anything the quick check cannot decide
  // go through the full check on a parse of the result.
  const bool proven =
      rewrites.empty() && !flat && only_safe_whitespace_changes({&tree, text}, printed.leaves, formatted);
  if (!proven) {
    const SyntaxTree formatted_tree = parse(formatted, flat);
    if (auto problem = check_tokens({&tree, text}, {&formatted_tree, formatted}, rewrites)) {
      return refuse(Status::Unsafe, *problem);
    }
  }
  result.changed = formatted != text;
  result.text = std::move(formatted);
  return result;
}

}  // namespace rung::format
