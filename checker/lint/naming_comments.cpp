// L060 missing-pou-comment, L061 todo-comment and L062 commented-out-code: what the comments of a
// file say, or fail to say.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <optional>

#include "checker/lint/naming_rules.hpp"
#include "checker/lint/structure_pou.hpp"

namespace rung::lint::naming {
namespace {

using check::Symbol;
using check::SymbolKind;

bool is_blank(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v';
}

bool is_word_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
}

// Whether only blanks stand between the start of the line and `offset`.
bool starts_line(std::string_view text, uint32_t offset) {
  for (uint32_t at = offset; at > 0; --at) {
    const char c = text[at - 1];
    if (c == '\n') return true;
    if (c != ' ' && c != '\t') return false;
  }
  return true;
}

bool same_line(std::string_view text, uint32_t a, uint32_t b) {
  if (a > b) std::swap(a, b);
  return text.substr(a, b - a).find('\n') == std::string_view::npos;
}

// Every comment of the file, in text order.
std::vector<SyntaxNode> comments_of(const NodeList& nodes) {
  std::vector<SyntaxNode> comments;
  nodes.walk(0, [&](uint32_t i) {
    if (nodes.kind(i) == "comment") comments.push_back(nodes.node(i));
    return !nodes.is_extra(i) && nodes.has_children(i);
  });
  return comments;
}

// The text inside the comment's delimiters.
std::string_view comment_content(std::string_view comment) {
  if (comment.starts_with("//")) {
    comment.remove_prefix(2);
    while (comment.starts_with("/")) comment.remove_prefix(1);  // /// doc comments
    return comment;
  }
  if (comment.starts_with("(*") || comment.starts_with("/*")) {
    comment.remove_prefix(2);
    if (comment.ends_with("*)") || comment.ends_with("*/")) comment.remove_suffix(2);
  }
  return comment;
}

// --- L060 ---------------------------------------------------------------------------------------

bool wants_comment(const check::ProjectModel& model, const Symbol& pou) {
  if (pou.name.empty() || !pou.node) return false;  // a snippet without header
  switch (pou.kind) {
    case SymbolKind::Program:
    case SymbolKind::Function:
    case SymbolKind::FunctionBlock:
    case SymbolKind::Interface: return true;
    // An implementation or override is documented where its signature is declared.
    case SymbolKind::Method: return !signature_is_given(model, pou);
    default: return false;
  }
}

// A comment right before the POU, with only blanks and pragmas ({attribute ...}) between.
bool has_comment_before(SyntaxNode root, const Symbol& pou) {
  const std::string_view text = root.source();
  uint32_t at = pou.node.begin();
  for (int guard = 0; guard < 64; ++guard) {
    while (at > 0 && is_blank(text[at - 1])) --at;
    if (at == 0) return false;
    SyntaxNode before = root.descendant_for_range(at - 1, at);
    while (before && before.kind() != "comment" && before.kind() != "pragma" && before.parent() &&
           before.parent().end() == at) {
      before = before.parent();
    }
    if (!before || before.end() != at) return false;
    if (before.kind() == "comment") return true;
    if (before.kind() != "pragma") return false;
    at = before.begin();
  }
  return false;
}

// A comment in the POU's header: on the line of its name, or on a line of its own after the
// name and before the first statement, outside the VAR blocks (those describe variables). The
// CODESYS and TwinCAT habit is the first lines after the header; OSCAT writes its description
// after the last END_VAR.
bool has_comment_in_header(const NodeList& nodes, SyntaxNode root, const Symbol& pou) {
  const std::string_view text = root.source();
  const SyntaxNode name = pou.node.child_by_field("name");
  const uint32_t begin = name ? name.end() : pou.node.begin();
  uint32_t end = pou.node.end();
  for (SyntaxNode body : bodies_of(pou)) end = std::min(end, body.begin());
  for (const Symbol* member : pou.ordered) {
    if (check::is_pou_kind(member->kind) && member->node && member->node.begin() > begin) {
      end = std::min(end, member->node.begin());
    }
  }
  bool found = false;
  nodes.walk(nodes.index_of(pou.node), [&](uint32_t i) {
    if (found || nodes.begin(i) >= end || nodes.end(i) <= begin) return false;
    const std::string_view kind = nodes.kind(i);
    if (kind == "var_block") return false;
    if (kind == "comment") {
      found = starts_line(text, nodes.begin(i)) || (name && same_line(text, name.end(), nodes.begin(i)));
      return false;
    }
    return !nodes.is_extra(i);
  });
  return found;
}

}  // namespace

void check_pou_comment(LintContext& context) {
  const SyntaxNode root = context.root();
  if (!root) return;
  for (const Symbol* pou : context.pous()) {
    if (!wants_comment(context.model(), *pou)) continue;
    if (has_comment_before(root, *pou) || has_comment_in_header(context.nodes(), root, *pou)) continue;
    context.report("L060", fmt::format("{} has no comment that says what it does", pou_label(*pou)), pou->name_range,
                   "write what it does (and what its inputs and outputs mean) in a comment right before it or on "
                   "the lines after its header");
  }
}

// --- L061 ---------------------------------------------------------------------------------------

namespace {

constexpr std::array<std::string_view, 4> kTodoWords = {"TODO", "FIXME", "XXX", "HACK"};

// The first TODO word of the comment as a whole word, as (offset in `comment`, length).
std::optional<std::pair<size_t, size_t>> todo_word(std::string_view comment) {
  for (size_t at = 0; at < comment.size(); ++at) {
    const char first = check::ascii_upper(comment[at]);
    if (std::none_of(kTodoWords.begin(), kTodoWords.end(), [&](std::string_view word) { return word[0] == first; })) {
      continue;  // the cheap test first: comments are long, TODO words rare
    }
    if (at > 0 && is_word_char(comment[at - 1])) continue;
    for (std::string_view word : kTodoWords) {
      if (at + word.size() > comment.size() || !check::names_equal(comment.substr(at, word.size()), word)) continue;
      if (at + word.size() < comment.size() && is_word_char(comment[at + word.size()])) continue;
      return std::make_pair(at, word.size());
    }
  }
  return std::nullopt;
}

// The note after the word, on its line, for the message.
std::string note_text(std::string_view rest) {
  rest = rest.substr(0, rest.find_first_of("\r\n"));
  if (rest.ends_with("*)") || rest.ends_with("*/")) rest.remove_suffix(2);
  return message_excerpt(rest, 60);
}

}  // namespace

void check_todo_comment(LintContext& context) {
  const SyntaxNode root = context.root();
  if (!root) return;
  for (SyntaxNode comment : comments_of(context.nodes())) {
    const std::string_view text = comment.text();
    const auto word = todo_word(text);
    if (!word) continue;
    const uint32_t begin = comment.begin() + static_cast<uint32_t>(word->first);
    context.report("L061",
                   fmt::format("{} comment: '{}'", check::upper_name(text.substr(word->first, word->second)),
                               note_text(text.substr(word->first))),
                   {begin, begin + static_cast<uint32_t>(word->second)},
                   "finish the work or track it where it cannot be forgotten (an issue); rung.toml [lint.rules] "
                   "L061 = \"off\" if TODO comments are your tracker");
  }
}

// --- L062 ---------------------------------------------------------------------------------------

namespace {

bool is_type_declaration_kind(std::string_view kind) {
  return kind == "array_type" || kind == "pointer_type" || kind == "reference_type" || kind == "string_type" ||
         kind == "subrange_type";
}

enum class Verdict { Code, Neutral, Prose };

// Whether a declaration looks like one a programmer wrote: an elementary or constructed type, or
// an initial value. "Usage: fbMotor(bStart := TRUE);" parses as a declaration of Usage with
// initial arguments, and "Note: see;" as one of type `see`: such text is prose.
Verdict declaration_verdict(const check::TypeArena& types, SyntaxNode declaration) {
  const ast::VarDeclaration::Parts parts = ast::VarDeclaration(declaration).parts();
  if (parts.init_arguments) return Verdict::Prose;
  if (parts.initial_value) return Verdict::Code;
  if (!parts.type) return Verdict::Neutral;
  if (is_type_declaration_kind(parts.type.kind())) return Verdict::Code;
  if (parts.type.kind() == "type_name" && types.elementary(parts.type.text(), false)) return Verdict::Code;
  return Verdict::Neutral;
}

Verdict statement_verdict(SyntaxNode statement) {
  switch (ast::statement_kind(statement)) {
    case ast::StatementKind::Label: return Verdict::Prose;  // "Example:" before code
    case ast::StatementKind::Assignment:
    case ast::StatementKind::If:
    case ast::StatementKind::Case:
    case ast::StatementKind::For:
    case ast::StatementKind::While:
    case ast::StatementKind::Repeat: return Verdict::Code;
    case ast::StatementKind::Call: {
      // "done;" is a call of `done` to the parser, and a word to a reader.
      const SyntaxNode call = statement.named_child(0);
      return call && call.child_by_field("arguments") ? Verdict::Code : Verdict::Neutral;
    }
    default: return Verdict::Neutral;
  }
}

// Whether the text is ST code: it parses without a single error into statements or declarations
// (not IL, which any two words are, nor bare expressions), at least one of which only code has.
bool is_code(const check::TypeArena& types, std::string_view content) {
  if (content.find(';') == std::string_view::npos) return false;
  const SyntaxTree tree = SyntaxTree::parse(std::string(content));
  if (tree.aborted()) return false;
  const SyntaxNode root = tree.root();
  if (!root || root.has_error()) return false;
  bool code = false;
  for (SyntaxNode item : root.named_children()) {
    const std::string_view kind = item.kind();
    Verdict verdict = Verdict::Prose;
    if (kind == "comment" || kind == "pragma") {
      verdict = Verdict::Neutral;
    } else if (kind == "statement_list") {
      verdict = Verdict::Neutral;
      for (SyntaxNode statement : ast::statements(item)) {
        const Verdict one = statement_verdict(statement);
        if (one == Verdict::Prose) return false;
        if (one == Verdict::Code) verdict = Verdict::Code;
      }
    } else if (kind == "var_declaration") {
      verdict = declaration_verdict(types, item);
    } else if (kind == "var_block" || kind.ends_with("_declaration")) {
      verdict = Verdict::Code;
    }
    if (verdict == Verdict::Prose) return false;
    code = code || verdict == Verdict::Code;
  }
  return code;
}

// Runs of `//` comments, each on a line of its own on consecutive lines, are one piece of text
// (code commented out line by line); any other comment is a piece of its own.
std::vector<std::vector<SyntaxNode>> comment_runs(std::string_view text, const std::vector<SyntaxNode>& comments) {
  std::vector<std::vector<SyntaxNode>> runs;
  for (SyntaxNode comment : comments) {
    const bool line_comment = comment.text().starts_with("//") && starts_line(text, comment.begin());
    if (line_comment && !runs.empty()) {
      const SyntaxNode last = runs.back().back();
      const std::string_view gap = text.substr(last.end(), comment.begin() - last.end());
      const bool next_line = last.text().starts_with("//") && starts_line(text, last.begin()) &&
                             std::count(gap.begin(), gap.end(), '\n') == 1 &&
                             gap.find_first_not_of(" \t\r\n") == std::string_view::npos;
      if (next_line) {
        runs.back().push_back(comment);
        continue;
      }
    }
    runs.push_back({comment});
  }
  return runs;
}

// The first line of code, for the message.
std::string first_code_line(std::string_view content) {
  const size_t start = content.find_first_not_of(" \t\r\n");
  return start == std::string_view::npos ? std::string() : message_excerpt(content.substr(start), 50);
}

}  // namespace

void check_commented_code(LintContext& context) {
  const SyntaxNode root = context.root();
  if (!root) return;
  const std::string_view text = context.text();
  for (const std::vector<SyntaxNode>& run : comment_runs(text, comments_of(context.nodes()))) {
    std::string content;
    for (SyntaxNode comment : run) {
      if (!content.empty()) content += '\n';
      content += comment_content(comment.text());
    }
    if (!is_code(context.model().types(), content)) continue;
    context.report("L062", fmt::format("commented-out code: '{}'", first_code_line(content)),
                   {run.front().begin(), run.back().end()},
                   "delete it (version control keeps the old code) or bring it back: commented-out code goes stale "
                   "and leaves readers guessing whether it should run");
  }
}

}  // namespace rung::lint::naming
