#include "checker/query/doc_comment.hpp"

#include <algorithm>

namespace rung::check::query {
namespace {

constexpr int kMaxCommentLines = 64;  // a doc comment longer than this is a file header, not a doc comment

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

bool is_extra(SyntaxNode node) { return node && (node.kind() == "comment" || node.kind() == "pragma"); }

// Whether only blanks stand between the start of the line and `offset`.
bool starts_line(std::string_view text, uint32_t offset) {
  for (uint32_t at = offset; at > 0; --at) {
    if (text[at - 1] == '\n') return true;
    if (!is_blank(text[at - 1])) return false;
  }
  return true;
}

// The comment or pragma that ends exactly at `at`.
SyntaxNode extra_ending_at(SyntaxNode root, uint32_t at) {
  if (at == 0) return {};
  SyntaxNode node = root.descendant_for_range(at - 1, at);
  while (node && !is_extra(node) && node.parent() && node.parent().end() == at) node = node.parent();
  return is_extra(node) && node.end() == at ? node : SyntaxNode();
}

// The comment that begins exactly at `at`.
SyntaxNode comment_starting_at(SyntaxNode root, uint32_t at) {
  if (at >= root.source().size()) return {};
  SyntaxNode node = root.descendant_for_range(at, at + 1);
  while (node && node.kind() != "comment" && node.parent() && node.parent().begin() == at) node = node.parent();
  return node && node.kind() == "comment" && node.begin() == at ? node : SyntaxNode();
}

// The comment lines right above the line of `begin`: attribute pragmas between are skipped, a
// blank line or code ends them, and a comment after code on its line belongs to that code.
std::vector<SyntaxNode> comments_above(SyntaxNode root, uint32_t begin) {
  const std::string_view text = root.source();
  std::vector<SyntaxNode> found;
  if (!starts_line(text, begin)) return found;
  uint32_t at = begin;
  for (int guard = 0; guard < kMaxCommentLines; ++guard) {
    uint32_t p = at;
    int newlines = 0;
    while (p > 0 && (is_blank(text[p - 1]) || text[p - 1] == '\n')) newlines += text[--p] == '\n';
    if (p == 0 || newlines > 1) break;
    const SyntaxNode extra = extra_ending_at(root, p);
    if (!extra || !starts_line(text, extra.begin())) break;
    if (extra.kind() == "comment") found.push_back(extra);
    at = extra.begin();
  }
  std::reverse(found.begin(), found.end());
  return found;
}

// The comment after `end` on the same line, a ',' or ';' between allowed (`Red, // ...`).
SyntaxNode comment_after(SyntaxNode root, uint32_t end) {
  const std::string_view text = root.source();
  uint32_t p = end;
  while (p < text.size() && is_blank(text[p])) ++p;
  if (p < text.size() && (text[p] == ',' || text[p] == ';')) ++p;
  while (p < text.size() && is_blank(text[p])) ++p;
  return comment_starting_at(root, p);
}

// A POU's description on its header line after the name, or on the lines right after the header.
std::vector<SyntaxNode> header_comments(SyntaxNode root, uint32_t name_end) {
  const std::string_view text = root.source();
  std::vector<SyntaxNode> found;
  size_t line_end = text.find('\n', name_end);
  if (line_end == std::string_view::npos) line_end = text.size();
  for (uint32_t p = name_end; p < line_end; ++p) {
    if (text[p] != '/' && text[p] != '(') continue;
    if (SyntaxNode comment = comment_starting_at(root, p)) {
      found.push_back(comment);
      return found;
    }
  }
  uint32_t p = static_cast<uint32_t>(line_end);
  for (int guard = 0; guard < kMaxCommentLines && p < text.size(); ++guard) {
    int newlines = 0;
    while (p < text.size() && (is_blank(text[p]) || text[p] == '\n')) newlines += text[p++] == '\n';
    if (newlines > 1) break;
    const SyntaxNode comment = comment_starting_at(root, p);
    if (!comment) break;
    found.push_back(comment);
    p = comment.end();
  }
  return found;
}

// Where a declaration's line starts: a TYPE written on one line with its single type starts at TYPE.
uint32_t declaration_begin(const Symbol& symbol) {
  uint32_t begin = symbol.node.begin();
  if (symbol.kind == SymbolKind::DataType) {
    const SyntaxNode holder = symbol.node.parent();
    if (holder && holder.kind() == "type_declaration") {
      const std::string_view between = holder.source().substr(holder.begin(), begin - holder.begin());
      if (between.find('\n') == std::string_view::npos) begin = holder.begin();
    }
  }
  return begin;
}

std::string_view trim(std::string_view line) {
  while (!line.empty() && is_blank(line.front())) line.remove_prefix(1);
  while (!line.empty() && is_blank(line.back())) line.remove_suffix(1);
  return line;
}

}  // namespace

std::string comment_content(std::string_view comment) {
  if (comment.starts_with("//")) {
    while (comment.starts_with("/")) comment.remove_prefix(1);
  } else if (comment.starts_with("(*") || comment.starts_with("/*")) {
    const bool pascal = comment.starts_with("(*");
    comment.remove_prefix(2);
    if (comment.ends_with(pascal ? "*)" : "*/")) comment.remove_suffix(2);
    while (comment.starts_with("*")) comment.remove_prefix(1);  // (** doc *)
    while (comment.ends_with("*")) comment.remove_suffix(1);
  }
  std::vector<std::string_view> lines;
  for (size_t start = 0; start <= comment.size();) {
    size_t end = comment.find('\n', start);
    if (end == std::string_view::npos) end = comment.size();
    std::string_view line = comment.substr(start, end - start);
    while (!line.empty() && is_blank(line.back())) line.remove_suffix(1);
    lines.push_back(line);
    start = end + 1;
  }
  while (!lines.empty() && trim(lines.front()).empty()) lines.erase(lines.begin());
  while (!lines.empty() && trim(lines.back()).empty()) lines.pop_back();
  // The first line follows the delimiter: only the later lines' indentation is common.
  size_t indent = std::string_view::npos;
  for (size_t i = 1; i < lines.size(); ++i) {
    if (trim(lines[i]).empty()) continue;
    size_t blanks = 0;
    while (blanks < lines[i].size() && is_blank(lines[i][blanks])) ++blanks;
    indent = std::min(indent, blanks);
  }
  std::string out;
  for (size_t i = 0; i < lines.size(); ++i) {
    std::string_view line = lines[i];
    if (i == 0) {
      line = trim(line);
    } else if (indent != std::string_view::npos) {
      line.remove_prefix(std::min(indent, line.size()));
    }
    if (i > 0) out += '\n';
    out += line;
  }
  return out;
}

std::string doc_comment(const ProjectModel& model, const Symbol& symbol) {
  if (symbol.source >= model.source_count() || !symbol.node) return {};
  const Document& document = *model.source(symbol.source).document;
  const SyntaxTree* tree = document.tree();
  if (!tree || tree->aborted()) return {};
  const SyntaxNode root = tree->root();
  std::vector<SyntaxNode> comments = comments_above(root, declaration_begin(symbol));
  if (comments.empty() && is_pou_kind(symbol.kind) && !symbol.name.empty()) {
    comments = header_comments(root, symbol.name_range.end);
  } else if (comments.empty() && (symbol.kind == SymbolKind::Variable || symbol.kind == SymbolKind::EnumValue)) {
    if (SyntaxNode comment = comment_after(root, symbol.node.end())) comments.push_back(comment);
  }
  const std::string_view file = document.file_text();
  std::string doc;
  for (SyntaxNode comment : comments) {
    const uint32_t begin = document.file_offset_of(comment.begin());
    const uint32_t end = document.file_end_offset_of(comment.end());
    if (end <= begin || end > file.size()) continue;
    const std::string content = comment_content(file.substr(begin, end - begin));
    std::string_view rest = content;
    while (!rest.empty()) {
      const size_t newline = rest.find('\n');
      const std::string_view line = rest.substr(0, newline);
      rest = newline == std::string_view::npos ? std::string_view() : rest.substr(newline + 1);
      if (symbol.has(kLibrary) && trim(line).starts_with("source:")) continue;
      if (!doc.empty()) doc += '\n';
      doc += line;
    }
  }
  return doc;
}

}  // namespace rung::check::query
