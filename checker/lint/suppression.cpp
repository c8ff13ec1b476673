#include "checker/lint/suppression.hpp"

#include <algorithm>
#include <array>
#include <optional>
#include <utility>

#include "checker/lint/lint_rule.hpp"
#include "checker/symbols/file_symbols.hpp"

namespace rung::lint {
namespace {

constexpr std::string_view kMarker = "rung-lint";

enum class Reach { Line, Following, Pou, File };

struct Directive {
  Reach reach = Reach::Line;
  std::vector<std::string> codes;
};

bool is_blank(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v';
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && is_blank(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_blank(s.back())) s.remove_suffix(1);
  return s;
}

// "L030, unused-variable -- why": the rule codes named before "--". nullopt when names were
// written but none is a rule: a typo must not switch off every rule.
std::optional<std::vector<std::string>> read_codes(std::string_view list) {
  if (size_t reason = list.find("--"); reason != std::string_view::npos) list = list.substr(0, reason);
  std::vector<std::string> codes;
  bool named_any = false;
  size_t at = 0;
  while (at < list.size()) {
    while (at < list.size() && (is_blank(list[at]) || list[at] == ',')) ++at;
    size_t end = at;
    while (end < list.size() && !is_blank(list[end]) && list[end] != ',') ++end;
    if (end == at) break;
    named_any = true;
    if (const Rule* rule = find_rule(list.substr(at, end - at))) codes.emplace_back(rule->code);
    at = end;
  }
  if (named_any && codes.empty()) return std::nullopt;
  return codes;
}

// "ignore-pou L070 -- generated code" -> Pou, {L070}. `plain_ignore` is what a bare "ignore"
// reaches (a line for comments, what follows for attributes).
std::optional<Directive> read_directive(std::string_view text, Reach plain_ignore) {
  text = trim(text);
  size_t word_end = 0;
  while (word_end < text.size() && !is_blank(text[word_end]) && text[word_end] != ',') ++word_end;
  const std::string_view word = text.substr(0, word_end);
  Directive directive;
  if (word == "ignore")
    directive.reach = plain_ignore;
  else if (word == "ignore-pou")
    directive.reach = Reach::Pou;
  else if (word == "ignore-file")
    directive.reach = Reach::File;
  else
    return std::nullopt;
  std::optional<std::vector<std::string>> codes = read_codes(text.substr(word_end));
  if (!codes) return std::nullopt;
  directive.codes = std::move(*codes);
  return directive;
}

// The directive of a comment: the text after "rung-lint:" up to the comment's end.
std::optional<Directive> comment_directive(std::string_view comment, size_t marker) {
  std::string_view rest = comment.substr(marker + kMarker.size());
  rest = trim(rest);
  if (rest.empty() || rest.front() != ':') return std::nullopt;
  rest.remove_prefix(1);
  if (rest.size() >= 2 && (rest.substr(rest.size() - 2) == "*)" || rest.substr(rest.size() - 2) == "*/")) {
    rest.remove_suffix(2);
  }
  return read_directive(rest, Reach::Line);
}

// The directive of `attribute 'rung-lint' := 'ignore L030'` (the pragma's text between braces).
std::optional<Directive> attribute_directive(std::string_view pragma) {
  const std::optional<check::Attribute> attribute = check::parse_attribute_pragma(pragma);
  if (!attribute || attribute->name != kMarker) return std::nullopt;
  return read_directive(attribute->value, Reach::Following);
}

// Nodes a POU suppression can cover: the file's top-level declarations and the POUs and members
// inside them.
bool is_pou_kind(std::string_view kind) {
  static constexpr std::array<std::string_view, 9> kinds{
      "program_declaration",   "function_declaration", "function_block_declaration",
      "class_declaration",     "method_declaration",   "property_declaration",
      "interface_declaration", "action_declaration",   "transition_declaration"};
  return std::find(kinds.begin(), kinds.end(), kind) != kinds.end();
}

bool holds_declarations(std::string_view kind) {
  return kind == "source_file" || kind == "namespace_declaration" || kind == "function_block_declaration" ||
         kind == "class_declaration" || kind == "interface_declaration" || kind == "program_declaration";
}

std::vector<TextRange> declaration_ranges(SyntaxNode root) {
  std::vector<TextRange> ranges;
  // Children of the file are declarations whatever their kind (TYPE, VAR_GLOBAL, ...).
  for (SyntaxNode top : root.named_children()) {
    if (top.is_extra()) continue;
    ranges.push_back(top.range());
    if (!holds_declarations(top.kind())) continue;
    bool first = true;
    walk_preorder(top, [&](SyntaxNode node) {
      if (std::exchange(first, false)) return true;
      if (!node.is_named() || node.is_extra()) return false;
      if (is_pou_kind(node.kind())) ranges.push_back(node.range());
      return holds_declarations(node.kind());
    });
  }
  return ranges;
}

class Reader {
 public:
  explicit Reader(SyntaxNode root) : root_(root), text_(root.source()) {}

  std::vector<Suppression> read() {
    std::vector<Suppression> out;
    for (size_t at = text_.find(kMarker); at != std::string_view::npos; at = text_.find(kMarker, at + 1)) {
      const auto begin = static_cast<uint32_t>(at);
      const SyntaxNode node = root_.named_descendant_for_range(begin, static_cast<uint32_t>(at + kMarker.size()));
      if (node.is_null()) continue;
      std::optional<Directive> directive;
      SyntaxNode holder = node;
      if (node.kind() == "comment") {
        directive = comment_directive(node.text(), at - node.begin());
      } else if (node.kind() == "attribute_pragma") {
        directive = attribute_directive(node.text());
        holder = node.parent();  // the pragma with its braces
        if (holder.is_null()) continue;
      } else {
        continue;  // a string or an identifier that happens to spell the marker
      }
      at = std::max<size_t>(at, holder.end() - 1);  // one directive per comment
      if (directive) out.push_back({scope_of(*directive, holder), std::move(directive->codes)});
    }
    return out;
  }

 private:
  TextRange line_at(uint32_t offset) const {
    const size_t start = offset == 0 ? 0 : text_.rfind('\n', offset - 1);
    const size_t end = text_.find('\n', offset);
    return {static_cast<uint32_t>(start == std::string_view::npos || offset == 0 ? 0 : start + 1),
            static_cast<uint32_t>(end == std::string_view::npos ? text_.size() : end + 1)};
  }

  // The first offset after `offset` that is code: not blank, not a comment or pragma.
  std::optional<uint32_t> next_code(uint32_t offset) const {
    uint32_t at = offset;
    while (at < text_.size()) {
      if (is_blank(text_[at])) {
        ++at;
        continue;
      }
      const SyntaxNode node = root_.named_descendant_for_range(at, at + 1);
      if (!node.is_null() && node.begin() == at && node.end() > at &&
          (node.kind() == "comment" || node.kind() == "pragma")) {
        at = node.end();
        continue;
      }
      return at;
    }
    return std::nullopt;
  }

  bool alone_on_line(SyntaxNode comment) const {
    const TextRange line = line_at(comment.begin());
    return trim(text_.substr(line.begin, comment.begin() - line.begin)).empty();
  }

  // The declaration that starts at `code`, else the innermost one around `offset`.
  std::optional<TextRange> declaration_at(std::optional<uint32_t> code, uint32_t offset) {
    if (!declarations_) declarations_ = declaration_ranges(root_);
    std::optional<TextRange> around;
    for (const TextRange& range : *declarations_) {
      if (code && range.begin == *code) return range;
      if (range.begin <= offset && offset < range.end && (!around || range.begin >= around->begin)) around = range;
    }
    return around;
  }

  TextRange scope_of(const Directive& directive, SyntaxNode node) {
    const std::optional<uint32_t> code = next_code(node.end());
    switch (directive.reach) {
      case Reach::File: return {0, static_cast<uint32_t>(text_.size())};
      case Reach::Pou: return declaration_at(code, node.begin()).value_or(TextRange{0, 0});
      case Reach::Following: {
        // An attribute belongs to what follows it: a POU, else the declaration on the next line.
        if (!code) return {0, 0};
        if (std::optional<TextRange> pou = declaration_at(code, node.begin()); pou && pou->begin == *code) return *pou;
        return line_at(*code);
      }
      case Reach::Line:
        if (!alone_on_line(node)) return line_at(node.begin());
        return code ? line_at(*code) : TextRange{0, 0};
    }
    return {0, 0};
  }

  SyntaxNode root_;
  std::string_view text_;
  std::optional<std::vector<TextRange>> declarations_;
};

}  // namespace

std::vector<Suppression> read_suppressions(SyntaxNode root) {
  if (root.is_null() || root.source().find(kMarker) == std::string_view::npos) return {};
  return Reader(root).read();
}

bool is_suppressed(std::span<const Suppression> suppressions, const Diagnostic& finding) {
  const uint32_t at = finding.range.begin;
  return std::any_of(suppressions.begin(), suppressions.end(), [&](const Suppression& s) {
    if (at < s.scope.begin || at >= s.scope.end) return false;
    return s.codes.empty() || std::find(s.codes.begin(), s.codes.end(), finding.code) != s.codes.end();
  });
}

}  // namespace rung::lint
