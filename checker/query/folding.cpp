#include "checker/query/folding.hpp"

#include <algorithm>
#include <optional>

#include "checker/symbols/names.hpp"

namespace rung::check::query {
namespace {

// Blocks closed by a keyword (END_xxx, UNTIL) or a parenthesis.
bool is_block(std::string_view kind) {
  static constexpr std::string_view kBlocks[] = {
      "program_declaration",  "function_declaration",      "function_block_declaration", "class_declaration",
      "interface_declaration", "method_declaration",       "property_declaration",       "property_accessor",
      "action_declaration",   "transition_declaration",    "namespace_declaration",      "var_block",
      "type_declaration",     "struct_type",               "union_type",                 "enum_type",
      "case_statement",       "for_statement",             "while_statement",            "repeat_statement",
      "try_statement",        "sfc_step",                  "sfc_transition",             "sfc_action_block",
      "configuration_declaration", "resource_declaration", "argument_list",              "struct_initializer",
      "array_initializer",    "case_element",              "catch_clause",               "finally_clause",
  };
  return std::find(std::begin(kBlocks), std::end(kBlocks), kind) != std::end(kBlocks);
}

bool is_closing_token(std::string_view kind) {
  return kind.starts_with("END_") || kind == ")" || kind == "]" || kind == "UNTIL";
}

class FoldCollector {
 public:
  explicit FoldCollector(const Document& document) : document_(document) {}

  std::vector<Fold> collect() {
    const SyntaxTree* tree = document_.tree();
    if (!tree || tree->aborted()) return {};
    std::vector<SyntaxNode> comments;
    std::vector<SyntaxNode> regions;  // open {region} pragmas
    walk_preorder(tree->root(), [&](SyntaxNode node) {
      if (!node.is_named()) return false;
      const std::string_view kind = node.kind();
      if (kind == "comment") {
        comments.push_back(node);
        return false;
      }
      if (kind == "pragma") {
        region_pragma(node, regions);
        return false;
      }
      if (kind == "if_statement") {
        if_branches(node);
      } else if (kind == "else_clause" || kind == "elsif_clause") {
        // An IF folds branch by branch (if_branches); CASE .. ELSE folds like a case element.
        if (node.parent() && node.parent().kind() != "if_statement") block(node);
      } else if (is_block(kind)) {
        block(node);
      }
      return true;
    });
    comment_runs(comments);
    std::sort(folds_.begin(), folds_.end(), [](const Fold& a, const Fold& b) {
      return a.first_line != b.first_line ? a.first_line < b.first_line : a.last_line > b.last_line;
    });
    // One fold per first line (editors show one fold marker per line): the widest.
    folds_.erase(std::unique(folds_.begin(), folds_.end(),
                             [](const Fold& a, const Fold& b) { return a.first_line == b.first_line; }),
                 folds_.end());
    return std::move(folds_);
  }

 private:
  uint32_t line_of_file(uint32_t file_offset) const { return document_.file_lines().position_of(file_offset).line; }
  uint32_t first_line(SyntaxNode node) const { return line_of_file(document_.file_offset_of(node.begin())); }
  uint32_t last_line(SyntaxNode node) const {
    return line_of_file(document_.file_end_offset_of(std::max(node.begin() + 1, node.end())) - 1);
  }

  // Whether the token is text of the file (not inserted by a container reader).
  bool is_real(SyntaxNode token) const {
    const auto* container = document_.container();
    if (!container) return true;
    const containers::Segment* segment = container->segment_at(token.begin());
    return segment && segment->file_begin.has_value();
  }

  // Whether only blanks stand before the token on its line.
  bool starts_its_line(SyntaxNode token) const {
    const uint32_t at = document_.file_offset_of(token.begin());
    const std::string_view text = document_.file_text();
    const uint32_t start = document_.file_lines().line_start(line_of_file(at));
    for (uint32_t i = start; i < at && i < text.size(); ++i) {
      if (text[i] != ' ' && text[i] != '\t') return false;
    }
    return true;
  }

  // The last line a block folds away: the line before its closing keyword when that keyword
  // starts its own line, else the block's last line.
  uint32_t fold_end(SyntaxNode node) const {
    SyntaxNode closing;
    for (SyntaxNode child = node.child(node.child_count() - 1); child; child = child.prev_sibling()) {
      if (child.is_named()) break;
      if (is_closing_token(child.kind())) closing = child;
      if (child.kind() != ";" && !is_closing_token(child.kind())) break;
    }
    if (node.kind() == "repeat_statement") closing = until_of(node);
    if (closing && !closing.is_missing() && is_real(closing) && starts_its_line(closing)) {
      const uint32_t line = first_line(closing);
      return line > 0 ? line - 1 : 0;
    }
    return last_line(node);
  }

  // REPEAT .. UNTIL c END_REPEAT folds up to the UNTIL line.
  static SyntaxNode until_of(SyntaxNode repeat) {
    for (SyntaxNode child = repeat.child(0); child; child = child.next_sibling()) {
      if (!child.is_named() && child.kind() == "UNTIL") return child;
    }
    return {};
  }

  void add(uint32_t first, uint32_t last, FoldKind kind) {
    if (last > first) folds_.push_back({first, last, kind});
  }

  void block(SyntaxNode node) { add(first_line(node), fold_end(node), FoldKind::Code); }

  // IF .. ELSIF .. ELSE .. END_IF: each branch folds up to the line before the next one, so the
  // ELSIF/ELSE/END_IF lines stay visible.
  void if_branches(SyntaxNode node) {
    std::vector<SyntaxNode> starts{node};
    for (SyntaxNode child : node.named_children()) {
      if (child.kind() == "elsif_clause" || child.kind() == "else_clause") starts.push_back(child);
    }
    for (size_t i = 0; i + 1 < starts.size(); ++i) {
      const uint32_t next = first_line(starts[i + 1]);
      if (next > 0) add(first_line(starts[i]), next - 1, FoldKind::Code);
    }
    add(first_line(starts.back()), fold_end(node), FoldKind::Code);
  }

  void region_pragma(SyntaxNode pragma, std::vector<SyntaxNode>& open) {
    SyntaxNode region = pragma.first_child_of_kind("region_pragma");
    if (!region) return;
    const std::string_view text = region.text();
    const bool closes = text.size() >= 3 && names_equal(text.substr(0, 3), "END");
    if (!closes) {
      open.push_back(pragma);
    } else if (!open.empty()) {
      add(first_line(open.back()), last_line(pragma), FoldKind::Region);
      open.pop_back();
    }
  }

  // A block comment over several lines folds; so does a run of comments that each stand alone
  // on consecutive lines (// lines).
  void comment_runs(const std::vector<SyntaxNode>& comments) {
    size_t i = 0;
    while (i < comments.size()) {
      const uint32_t first = first_line(comments[i]);
      uint32_t last = last_line(comments[i]);
      size_t j = i + 1;
      if (first == last && starts_its_line(comments[i])) {
        while (j < comments.size() && first_line(comments[j]) == last + 1 && last_line(comments[j]) == last + 1 &&
               starts_its_line(comments[j])) {
          ++last;
          ++j;
        }
      }
      add(first, last, FoldKind::Comment);
      i = j;
    }
  }

  const Document& document_;
  std::vector<Fold> folds_;
};

}  // namespace

std::vector<Fold> folding_ranges(const Document& document) { return FoldCollector(document).collect(); }

}  // namespace rung::check::query
