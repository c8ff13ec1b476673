#include "formatter/rewrites.hpp"

#include <algorithm>

#include "formatter/keyword_case.hpp"

namespace rung::format {
namespace {

bool is_blank(std::string_view text) {
  return std::all_of(text.begin(), text.end(),
                     [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v'; });
}

bool is_horizontal_blank(std::string_view text) {
  return std::all_of(text.begin(), text.end(), [](char c) { return c == ' ' || c == '\t'; });
}

// Leaves (tokens, comments, pragmas) in text order; zero-width tokens left out.
std::vector<SyntaxNode> leaves_of(const SyntaxTree& tree) {
  std::vector<SyntaxNode> out;
  walk_preorder(tree.root(), [&](SyntaxNode node) {
    const bool pragma = node.is_extra() && node.kind() == "pragma";
    if (node.child_count() == 0 || pragma) {
      if (node.end() > node.begin()) out.push_back(node);
      return false;
    }
    return true;
  });
  return out;
}

bool is_trivia(SyntaxNode leaf) {
  return leaf.is_extra() && (leaf.kind() == "comment" || leaf.kind() == "pragma");
}

struct TextEdit {
  uint32_t begin;
  uint32_t end;
  std::string replacement;
};

// The range of a removed line part, widened to the whole line (with the line break before it)
// when nothing else stands on that line.
TextEdit removal(std::string_view text, uint32_t begin, uint32_t end) {
  size_t line_start = text.find_last_of("\r\n", begin == 0 ? 0 : begin - 1);
  if (begin == 0) line_start = std::string_view::npos;
  size_t line_end = text.find_first_of("\r\n", end);
  if (line_end == std::string_view::npos) line_end = text.size();
  if (line_start != std::string_view::npos &&
      is_horizontal_blank(text.substr(line_start + 1, begin - line_start - 1)) &&
      is_horizontal_blank(text.substr(end, line_end - end))) {
    size_t from = line_start;
    if (text[from] == '\n' && from > 0 && text[from - 1] == '\r') --from;
    return {static_cast<uint32_t>(from), static_cast<uint32_t>(line_end), ""};
  }
  return {begin, end, ""};
}

// ELSIF in the letter case the ELSE was written in.
std::string elsif_like(std::string_view else_text) {
  const bool lower = std::none_of(else_text.begin(), else_text.end(), [](char c) { return c >= 'A' && c <= 'Z'; });
  const bool upper = std::none_of(else_text.begin(), else_text.end(), [](char c) { return c >= 'a' && c <= 'z'; });
  if (lower) return "elsif";
  if (upper) return "ELSIF";
  return "Elsif";
}

}  // namespace

bool is_statement_end_keyword(SyntaxNode leaf) {
  if (leaf.is_null() || leaf.is_named() || leaf.child_count() != 0) return false;
  const std::string_view kind = leaf.kind();
  return kind == "END_IF" || kind == "END_CASE" || kind == "END_FOR" || kind == "END_WHILE" || kind == "END_REPEAT";
}

ElseIfMerge else_if_merge_at(const SyntaxTree& tree, std::string_view text, uint32_t else_offset) {
  ElseIfMerge none;
  SyntaxNode else_keyword = tree.root().descendant_for_range(else_offset, else_offset + 1);
  if (!else_keyword || else_keyword.begin() != else_offset || else_keyword.kind() != "ELSE") return none;
  SyntaxNode clause = else_keyword.parent();
  if (!clause || clause.kind() != "else_clause") return none;
  SyntaxNode outer = clause.parent();
  if (!outer || outer.kind() != "if_statement") return none;
  SyntaxNode body = clause.child_by_field("body");
  if (!body || body.kind() != "statement_list") return none;
  SyntaxNode inner;
  uint32_t statements = 0;
  for (const SyntaxNode& child : body.named_children()) {
    if (child.is_extra()) return none;  // a comment inside the branch would move across keywords
    ++statements;
    inner = child;
  }
  if (statements != 1 || inner.kind() != "if_statement") return none;
  SyntaxNode if_keyword = inner.child(0);
  if (!if_keyword || if_keyword.kind() != "IF") return none;
  if (!is_blank(text.substr(else_keyword.end(), if_keyword.begin() - else_keyword.end()))) return none;

  SyntaxNode end_if;
  SyntaxNode semicolon;
  for (uint32_t i = inner.child_count(); i-- > 0;) {
    SyntaxNode child = inner.child(i);
    if (child.kind() == "END_IF") {
      end_if = child;
      if (i + 1 < inner.child_count() && inner.child(i + 1).kind() == ";") semicolon = inner.child(i + 1);
      break;
    }
  }
  if (!end_if || inner.end() != (semicolon ? semicolon.end() : end_if.end())) return none;
  // Between the inner END_IF (and its ';') and the outer END_IF: whitespace only.
  SyntaxNode outer_end;
  for (uint32_t i = outer.child_count(); i-- > 0;) {
    if (outer.child(i).kind() == "END_IF") {
      outer_end = outer.child(i);
      break;
    }
  }
  if (!outer_end || outer_end.begin() < inner.end()) return none;
  if (!is_blank(text.substr(inner.end(), outer_end.begin() - inner.end()))) return none;
  const uint32_t semicolon_begin = semicolon ? semicolon.begin() : end_if.end();
  if (!is_blank(text.substr(end_if.end(), semicolon_begin - end_if.end()))) return none;
  return {else_keyword, if_keyword, end_if, semicolon};
}

std::vector<Rewrite> plan_rewrites(const SyntaxTree& tree, std::string_view text,
                                   const project::FormatSettings& settings) {
  std::vector<Rewrite> out;
  const bool semicolons = settings.end_semicolon != project::EndSemicolon::Keep;
  if (!semicolons && !settings.else_if_to_elsif) return out;
  const std::vector<SyntaxNode> leaves = leaves_of(tree);
  std::vector<uint32_t> removed;  // begin offsets of the tokens a merge removes
  if (settings.else_if_to_elsif) {
    for (const SyntaxNode& leaf : leaves) {
      if (leaf.is_named() || leaf.kind() != "ELSE") continue;
      const ElseIfMerge merge = else_if_merge_at(tree, text, leaf.begin());
      if (!merge.valid()) continue;
      out.push_back({Rewrite::Kind::MergeElseIf, leaf.begin()});
      removed.push_back(merge.end_if.begin());
      if (merge.end_semicolon) removed.push_back(merge.end_semicolon.begin());
    }
  }
  auto is_removed = [&](SyntaxNode leaf) {
    return std::find(removed.begin(), removed.end(), leaf.begin()) != removed.end();
  };
  if (semicolons) {
    for (size_t i = 0; i < leaves.size(); ++i) {
      if (!is_statement_end_keyword(leaves[i]) || is_removed(leaves[i])) continue;
      size_t next = i + 1;
      while (next < leaves.size() && is_trivia(leaves[next])) ++next;
      const bool followed = next < leaves.size() && leaves[next].kind() == ";";
      if (settings.end_semicolon == project::EndSemicolon::Always && !followed) {
        out.push_back({Rewrite::Kind::AddSemicolon, leaves[i].begin()});
      } else if (settings.end_semicolon == project::EndSemicolon::Never) {
        // Every ';' that directly follows on the line goes ("END_IF;;" too: a second empty
        // statement would otherwise be the next run's directly following ';').
        for (size_t k = i + 1;
             k < leaves.size() && leaves[k].kind() == ";" && !is_removed(leaves[k]) &&
             is_horizontal_blank(text.substr(leaves[k - 1].end(), leaves[k].begin() - leaves[k - 1].end()));
             ++k) {
          out.push_back({Rewrite::Kind::RemoveSemicolon, leaves[k].begin()});
        }
      }
    }
  }
  std::sort(out.begin(), out.end(), [](const Rewrite& a, const Rewrite& b) { return a.at < b.at; });
  return out;
}

std::string apply_rewrites(const SyntaxTree& tree, std::string_view text, const std::vector<Rewrite>& rewrites) {
  std::vector<TextEdit> edits;
  for (const Rewrite& r : rewrites) {
    switch (r.kind) {
      case Rewrite::Kind::AddSemicolon: {
        SyntaxNode keyword = tree.root().descendant_for_range(r.at, r.at + 1);
        edits.push_back({keyword.end(), keyword.end(), ";"});
        break;
      }
      case Rewrite::Kind::RemoveSemicolon: edits.push_back({r.at, r.at + 1, ""}); break;
      case Rewrite::Kind::MergeElseIf: {
        const ElseIfMerge merge = else_if_merge_at(tree, text, r.at);
        if (!merge.valid()) break;
        edits.push_back({merge.else_keyword.begin(), merge.if_keyword.end(), elsif_like(merge.else_keyword.text())});
        const uint32_t end = merge.end_semicolon ? merge.end_semicolon.end() : merge.end_if.end();
        edits.push_back(removal(text, merge.end_if.begin(), end));
        break;
      }
    }
  }
  std::sort(edits.begin(), edits.end(), [](const TextEdit& a, const TextEdit& b) { return a.begin < b.begin; });
  std::string out;
  out.reserve(text.size() + edits.size());
  uint32_t at = 0;
  for (const TextEdit& e : edits) {
    if (e.begin < at) continue;  // overlapping edits cannot come from one plan; never apply twice
    out.append(text.substr(at, e.begin - at));
    out += e.replacement;
    at = e.end;
  }
  out.append(text.substr(at));
  return out;
}

}  // namespace rung::format
