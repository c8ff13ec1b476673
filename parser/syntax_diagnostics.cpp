#include "parser/syntax_diagnostics.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <optional>
#include <string_view>

#include "parser/declaration_syntax.hpp"
#include "parser/diagnostic_codes.hpp"
#include "parser/keywords.hpp"
#include "parser/source/line_index.hpp"

namespace rung {
namespace {

using keywords::upper;

bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v';
}

// Short, printable excerpt of a token for a message.
std::string excerpt(std::string_view text) {
  size_t cut = text.find_first_of("\r\n");
  if (cut != std::string_view::npos) text = text.substr(0, cut);
  if (text.size() > 32) return std::string(text.substr(0, 29)) + "...";
  return std::string(text);
}

// The first leaf of `node` that has text.
SyntaxNode first_leaf(SyntaxNode node) {
  while (node && node.child_count() > 0) node = node.child(0);
  return node;
}

// The last non-empty leaf that starts before `offset` (the token a missing one should follow).
// Comments and pragmas are skipped: a ';' never belongs after a comment.
SyntaxNode last_leaf_before(SyntaxNode root, uint32_t offset) {
  while (offset > 0) {
    SyntaxNode node = root.descendant_for_range(offset - 1, offset);
    // Climb until the node starts before offset and has a non-empty leaf there.
    while (node && node.begin() >= offset) node = node.parent();
    while (node && node.child_count() > 0 && !node.is_extra()) {
      SyntaxNode pick;
      for (uint32_t i = node.child_count(); i-- > 0;) {
        SyntaxNode c = node.child(i);
        if (c.begin() < offset && c.end() > c.begin()) {
          pick = c;
          break;
        }
      }
      if (!pick) break;
      node = pick;
    }
    if (!node || node.begin() >= offset) return {};
    if (node.is_extra()) {
      offset = node.begin();  // look before the comment or pragma
      continue;
    }
    if (node.child_count() == 0 && node.end() > node.begin()) return node;
    return {};
  }
  return {};
}

// Names the construct an END_ keyword closes, e.g. END_IF -> IF, END_VAR -> VAR,
// END_FUNCTION_BLOCK -> FUNCTION_BLOCK.
std::string opener_of(std::string_view end_keyword) {
  if (end_keyword.rfind("END_", 0) == 0) return std::string(end_keyword.substr(4));
  return {};
}

// Finds the keyword token that opened the construct a MISSING END_xxx belongs to.
SyntaxNode find_opener(SyntaxNode missing, std::string_view opener) {
  for (SyntaxNode node = missing.parent(); node; node = node.parent()) {
    uint32_t n = node.child_count();
    for (uint32_t i = 0; i < n; ++i) {
      SyntaxNode c = node.child(i);
      if (c.is_extra()) continue;
      std::string kind = upper(c.kind());
      // VAR_INPUT, VAR_GLOBAL ... all close with END_VAR.
      if (kind == opener || (opener == "VAR" && kind.rfind("VAR", 0) == 0 && !c.is_named())) return c;
      if (!c.is_extra()) break;  // only the node's first real child can be its opener
    }
  }
  return {};
}

class Collector {
 public:
  Collector(const SyntaxTree& tree, const SyntaxDiagnosticOptions& options) : tree_(tree), options_(options) {}

  std::vector<Diagnostic> run() {
    if (!tree_.root()) return {};
    std::vector<SyntaxFinding> findings;
    check_declaration_syntax(tree_, [&findings](SyntaxFinding f) { findings.push_back(std::move(f)); });
    for (const auto& f : findings) {
      if (!f.explains_closer.empty()) explanations_.push_back({f.range.end, std::string(f.explains_closer)});
    }
    walk(tree_.root());
    for (auto& f : findings) report_finding(std::move(f));
    check_unterminated_comment();
    sort_diagnostics(out_);
    if (out_.size() > options_.max_errors) {
      uint32_t at = out_[options_.max_errors].range.begin;
      size_t hidden = out_.size() - options_.max_errors + dropped_;
      out_.resize(options_.max_errors);
      Diagnostic note;
      note.code = std::string(codes::kTooManyErrors);
      note.severity = Severity::Info;
      note.message = fmt::format("{} more syntax errors not shown", hidden);
      note.range = {at, at};
      note.help = "fix the first errors: later ones are often caused by them";
      out_.push_back(std::move(note));
    }
    return std::move(out_);
  }

 private:
  std::string where(uint32_t offset) const {
    return options_.describe_position ? options_.describe_position(offset) : fmt::format("offset {}", offset);
  }

  void add(std::string_view code, TextRange range, std::string message, std::string help = {},
           std::vector<DiagnosticLabel> labels = {}) {
    // Errors arrive in text order; once the cap is reached only count them, so a file of
    // garbage costs linear time.
    if (out_.size() > options_.max_errors) {
      ++dropped_;
      return;
    }
    // One report per start position: tree-sitter can flag the same spot twice.
    for (size_t i = out_.size(); i-- > 0 && i + 4 >= out_.size();) {
      if (out_[i].range.begin == range.begin && out_[i].code == code) return;
    }
    Diagnostic d;
    d.code = std::string(code);
    d.severity = Severity::Error;
    d.message = std::move(message);
    d.range = range;
    d.help = std::move(help);
    d.labels = std::move(labels);
    out_.push_back(std::move(d));
  }

  // A finding of the declaration pass, or of the walk: a stray closing keyword that a misspelled
  // opener before it explains (VAR_GLOBAS ... END_VAR) is no second mistake.
  void report_finding(SyntaxFinding f) {
    if (!f.stray_keyword.empty()) {
      for (auto& e : explanations_) {
        if (!e.closer.empty() && e.closer == f.stray_keyword && e.after <= f.range.begin) {
          e.closer.clear();
          return;
        }
      }
    }
    add(f.code, f.range, std::move(f.message), std::move(f.help));
  }

  // Iterative walk: error nodes are reported and not entered (their insides are echoes).
  void walk(SyntaxNode root) {
    std::vector<SyntaxNode> stack{root};
    while (!stack.empty()) {
      SyntaxNode node = stack.back();
      stack.pop_back();
      if (node.is_missing()) {
        report_missing(node);
        continue;
      }
      if (node.is_error()) {
        // Several error regions inside one statement or declaration are one mistake: report the
        // first only.
        if (node.begin() < skip_errors_until_) continue;
        report_error(node);
        for (SyntaxNode p = node.parent(); p; p = p.parent()) {
          std::string_view k = p.kind();
          if ((k.size() > 10 && k.substr(k.size() - 10) == "_statement") || k == "var_declaration") {
            skip_errors_until_ = p.end();
            break;
          }
          if (k == "statement_list" || k == "source_file") break;
        }
        continue;
      }
      if (!node.has_error()) continue;
      for (uint32_t i = node.child_count(); i-- > 0;) stack.push_back(node.child(i));
    }
  }

  void report_missing(SyntaxNode node) {
    std::string kind = std::string(node.kind());
    // The grammar reads a closing word where an IL instruction may start (a doubled END_VAR) up
    // to a token that never comes: the word itself is the mistake.
    // The same for a ';' between the arguments of a call, SHL(in_word;n).
    if (kind == "unreachable") {
      SyntaxNode word = last_leaf_before(tree_.root(), node.begin());
      if (!word) return;
      if (word.text() != ";") {
        report_finding(stray_keyword(word));
        return;
      }
      SyntaxNode call = node.parent();
      while (call && call.kind() != "call_expression") call = call.parent();
      SyntaxNode function = call ? call.child_by_field("function") : SyntaxNode{};
      add(codes::kSyntaxError, word.range(),
          function ? fmt::format("';' between the arguments of '{}'", excerpt(function.text()))
                   : std::string("';' between the arguments of a call"),
          "separate arguments with ','; ';' ends a statement");
      return;
    }
    std::string opener = opener_of(upper(kind));
    uint32_t at = node.begin();
    if (!opener.empty()) {
      SyntaxNode open = find_opener(node, opener);
      if (open) {
        if (upper(open.text()) == "IF" && is_else_if(open)) {
          SyntaxNode else_kw = previous_token(open);
          add(codes::kElseIf, {else_kw.begin(), open.end()}, "unexpected 'ELSE IF' — did you mean ELSIF?",
              "write ELSIF; 'ELSE IF' opens a nested IF that needs its own END_IF");
          return;
        }
        add(codes::kUnclosedBlock, {at, at},
            fmt::format("{} at {} has no {}", upper(open.text()), where(open.begin()), upper(kind)),
            fmt::format("add {} to close the {} block", upper(kind), upper(open.text())),
            {DiagnosticLabel{open.range(), fmt::format("this {} is never closed", upper(open.text()))}});
        return;
      }
      add(codes::kUnclosedBlock, {at, at}, fmt::format("missing {}", upper(kind)), fmt::format("add {}", upper(kind)));
      return;
    }
    // Point at the end of the token the missing one should follow, not at the next line.
    SyntaxNode prev = last_leaf_before(tree_.root(), at);
    uint32_t pos = prev ? prev.end() : at;
    if (kind == ";") {
      std::string_view what = "statement";
      for (SyntaxNode p = node.parent(); p; p = p.parent()) {
        std::string_view k = p.kind();
        if (k.find("declaration") != std::string_view::npos || k.find("type") != std::string_view::npos) {
          what = "declaration";
          break;
        }
        if (k.find("statement") != std::string_view::npos) break;
      }
      add(codes::kMissingToken, {pos, pos}, fmt::format("missing ';' after {}", what),
          fmt::format("end the {} with ';'", what));
      return;
    }
    if (node.is_named() && prev && !prev.is_named() && !prev.text().empty() &&
        !std::isalnum(static_cast<unsigned char>(prev.text().back())) && prev.text() != ")" && prev.text() != "]") {
      add(codes::kMissingToken, {pos, pos}, fmt::format("missing operand after '{}'", prev.text()),
          "write the value or expression that belongs here");
      return;
    }
    if (node.is_named()) {
      std::string readable = kind;
      std::replace(readable.begin(), readable.end(), '_', ' ');
      add(codes::kMissingToken, {pos, pos}, fmt::format("missing {}", readable));
    } else {
      add(codes::kMissingToken, {pos, pos}, fmt::format("missing '{}'", kind), fmt::format("insert '{}'", kind));
    }
  }

  // The scanner lets an unclosed comment run to the end of the file, which is valid as a token;
  // only the comment that ends the file can be unclosed, so only that one is checked.
  void check_unterminated_comment() {
    // The last leaf with text: zero-width MISSING tokens may follow it at any depth.
    SyntaxNode node = tree_.root();
    for (;;) {
      SyntaxNode pick;
      for (uint32_t i = node.child_count(); i-- > 0;) {
        SyntaxNode c = node.child(i);
        if (c.end() > c.begin()) {
          pick = c;
          break;
        }
      }
      if (!pick) break;
      node = pick;
    }
    if (!node || node.child_count() > 0 || node == tree_.root()) return;
    std::string_view text = node.text();
    if (text.rfind("/*", 0) == 0) {
      if (text.size() < 4 || text.substr(text.size() - 2) != "*/") report_unclosed_comment(node.begin(), "*/");
      return;
    }
    if (text.rfind("(*", 0) != 0) return;
    int depth = 0;
    for (size_t i = 0; i + 1 < text.size(); ++i) {
      if (text[i] == '(' && text[i + 1] == '*') {
        ++depth;
        ++i;
      } else if (text[i] == '*' && text[i + 1] == ')') {
        --depth;
        ++i;
        if (depth == 0 && i + 1 < text.size()) return;  // closed before the end: not this case
      }
    }
    if (depth > 0) report_unclosed_comment(node.begin(), "*)");
  }

  void report_unclosed_comment(uint32_t begin, std::string_view close) {
    add(codes::kUnterminatedComment, {begin, begin + 2},
        fmt::format("comment opened at {} is never closed", where(begin)),
        fmt::format("close the comment with '{}'", close));
  }

  SyntaxNode previous_token(SyntaxNode node) const { return last_leaf_before(tree_.root(), node.begin()); }

  bool is_else_if(SyntaxNode if_keyword) const {
    SyntaxNode prev = previous_token(if_keyword);
    return prev && upper(prev.text()) == "ELSE";
  }

  void report_error(SyntaxNode node) {
    std::string_view text = node.text();
    size_t skip = 0;
    while (skip < text.size() && is_space(text[skip])) ++skip;
    uint32_t begin = node.begin() + static_cast<uint32_t>(skip);
    std::string_view body = text.substr(skip);
    SyntaxNode leaf = first_leaf(node);
    std::string_view first =
        leaf && leaf.end() > leaf.begin() ? leaf.text() : body.substr(0, std::min<size_t>(body.size(), 1));
    if (leaf && leaf.begin() > begin) first = body.substr(0, std::min<size_t>(body.size(), 1));
    // An elision "..." splits into '.' tokens where a global name (.x) may start.
    if (body.rfind("...", 0) == 0) first = body.substr(0, 3);

    if (body.rfind("(*", 0) == 0 || body.rfind("/*", 0) == 0) {
      std::string_view close = body.rfind("(*", 0) == 0 ? "*)" : "*/";
      if (body.find(close) == std::string_view::npos) {
        report_unclosed_comment(begin, close);
        return;
      }
    }
    if (!body.empty() && (body[0] == '\'' || body[0] == '"')) {
      size_t eol = body.find_first_of("\r\n");
      std::string_view line = body.substr(0, eol);
      if (line.find(body[0], 1) == std::string_view::npos) {
        add(codes::kUnterminatedString, {begin, begin + static_cast<uint32_t>(line.size())},
            "string literal is not closed on its line", fmt::format("add the closing {}", body[0]));
        return;
      }
    }
    // ELSE IF where ELSIF was meant often surfaces as an error node starting at ELSE.
    std::string up = upper(body.substr(0, std::min<size_t>(body.size(), 16)));
    if (up.rfind("ELSE", 0) == 0) {
      size_t i = 4;
      while (i < up.size() && is_space(up[i])) ++i;
      if (i > 4 && up.compare(i, 2, "IF") == 0 &&
          (i + 2 >= up.size() || !std::isalnum(static_cast<unsigned char>(up[i + 2])))) {
        add(codes::kElseIf, {begin, begin + static_cast<uint32_t>(i + 2)}, "unexpected 'ELSE IF' — did you mean ELSIF?",
            "write ELSIF; 'ELSE IF' opens a nested IF that needs its own END_IF");
        return;
      }
    }
    // An error region that starts with a statement's ';' is about what follows the ';'.
    if (first == ";") {
      std::vector<SyntaxNode> leaves = leaves_of(node, 8);
      if (leaves.size() >= 2 && leaves[0].text() == ";") {
        SyntaxNode next = leaves[1];
        add(codes::kSyntaxError, next.range(),
            fmt::format("unexpected '{}': a statement cannot start here", excerpt(next.text())),
            "a statement starts with a name or keyword (x := ..., IF, CASE, FOR, a call f(...);)");
        return;
      }
    }
    if (!first.empty()) {
      unsigned char c0 = static_cast<unsigned char>(first[0]);
      bool token_char =
          std::isalnum(c0) || c0 == '_' ||
          std::string_view("()[];:,.=<>+-*/^#%&'\"{}").find(static_cast<char>(c0)) != std::string_view::npos;
      if (!token_char) {
        size_t len = 1;
        if (c0 >= 0xC0) len = c0 >= 0xF0 ? 4 : c0 >= 0xE0 ? 3 : 2;
        len = std::min(len, first.size());
        add(codes::kInvalidCharacter, {begin, begin + static_cast<uint32_t>(len)},
            fmt::format("'{}' cannot appear here", first.substr(0, len)),
            "remove it, or put it inside a comment or a string");
        return;
      }
    }
    if (report_stray_closer(node)) return;
    if (report_bare_name_line(node)) return;
    if (report_common_mistake(node)) return;
    if (report_block_structure(node)) return;
    if (report_missing_semicolon(node)) return;
    // A statement that runs on into the next line usually lacks its ';'.
    SyntaxNode prev = last_leaf_before(tree_.root(), begin);
    if (prev && ends_expression(prev) && line_of(prev.end()) < line_of(begin) && starts_statement(node)) {
      add(codes::kMissingToken, {prev.end(), prev.end()}, "missing ';' after statement", "end the statement with ';'");
      return;
    }
    if (report_after_complete_declaration(node)) return;
    std::string context = describe_context(node);
    add(codes::kSyntaxError, {begin, std::max(begin + 1, begin + static_cast<uint32_t>(first.size()))},
        fmt::format("unexpected '{}'{}", excerpt(first), context));
  }

  // A name alone on its line before the body's statements ("PRG_PID" NEWLINE "M_Act();"): a call
  // of a program written without "();" whose ';' is missing (it is no IL, which never mixes
  // with statements).
  bool report_bare_name_line(SyntaxNode error) {
    std::vector<SyntaxNode> leaves = leaves_of(error, 16);
    if (leaves.empty() || leaves.size() % 2 == 0) return false;
    for (size_t i = 0; i < leaves.size(); ++i) {
      bool ok = i % 2 == 0 ? leaves[i].kind() == "identifier" : leaves[i].text() == ".";
      if (!ok) return false;
    }
    SyntaxNode next = error.next_sibling();
    while (next && next.is_extra()) next = next.next_sibling();
    if (!next || (next.kind() != "statement_list" && next.kind().find("_statement") == std::string_view::npos)) {
      return false;
    }
    SyntaxNode last = leaves.back();
    if (line_of(leaves.front().begin()) != line_of(last.end()) || line_of(next.begin()) <= line_of(last.end())) {
      return false;
    }
    add(codes::kMissingToken, {last.end(), last.end()}, "missing ';' after statement",
        fmt::format("end the statement with ';' (a call without arguments is written {}();)", error.text()));
    return true;
  }

  // An error region that is one closing keyword alone (a doubled END_VAR before the body).
  bool report_stray_closer(SyntaxNode error) {
    std::vector<SyntaxNode> leaves = leaves_of(error, 2);
    if (leaves.size() != 1) return false;
    std::string word = upper(leaves[0].text());
    if (word.rfind("END_", 0) != 0 || !keywords::is_reserved(word)) return false;
    report_finding(stray_keyword(leaves[0]));
    return true;
  }

  // Mistakes people bring from other languages or make by typing: misspelled keywords
  // (ELSEIF, ENDIF, END_IFF), C operators (==, !=, &&, ||), '=' where ':=' assigns.
  bool report_common_mistake(SyntaxNode error) {
    std::vector<SyntaxNode> leaves = leaves_of(error, 4096);
    // The token before the error region belongs to the statement it breaks.
    if (SyntaxNode before = last_leaf_before(tree_.root(), error.begin())) leaves.insert(leaves.begin(), before);
    for (size_t i = 0; i < leaves.size(); ++i) {
      SyntaxNode leaf = leaves[i];
      std::string_view t = leaf.text();
      // The lexer splits '==' into two '=' tokens.
      if (t == "=" && i > 0 && leaves[i - 1].text() == "=" && leaves[i - 1].end() == leaf.begin()) {
        add(codes::kWrongOperator, {leaves[i - 1].begin(), leaf.end()}, "'==' is not an IEC 61131-3 operator",
            "compare with '='");
        return true;
      }
      if (t == "==" || t == "!=" || t == "&&" || t == "||" || t == "!") {
        static constexpr std::pair<std::string_view, std::string_view> kOps[] = {{"==", "compare with '='"},
                                                                                 {"!=", "compare with '<>'"},
                                                                                 {"&&", "write AND (or AND_THEN)"},
                                                                                 {"||", "write OR (or OR_ELSE)"},
                                                                                 {"!", "write NOT"}};
        for (const auto& [op, fix] : kOps) {
          if (t == op) {
            add(codes::kWrongOperator, leaf.range(), fmt::format("'{}' is not an IEC 61131-3 operator", t),
                std::string(fix));
            return true;
          }
        }
      }
      if (leaf.kind() == "identifier" || (!leaf.is_named() && !keyword_of(leaf).empty())) {
        std::string word = upper(t);
        std::string_view meant = keywords::misspelled(word, false);
        if (!meant.empty()) {
          add(codes::kMisspelledKeyword, leaf.range(),
              fmt::format("'{}' is not a keyword — did you mean {}?", t, meant), fmt::format("write {}", meant));
          return true;
        }
      }
      // `a = 1;` at the start of a line: '=' compares in ST, ':=' assigns.
      if (t == "=" && i > 0) {
        SyntaxNode target = leaves[i - 1];
        bool at_line_start =
            i < 2 || line_of(leaves[i - 2].end()) < line_of(target.begin()) || leaves[i - 2].text() == ";";
        bool in_for = i >= 2 && upper(leaves[i - 2].text()) == "FOR";
        bool name_like = target.is_named() && !target.text().empty() &&
                         (std::isalpha(static_cast<unsigned char>(target.text()[0])) || target.text()[0] == '_');
        if (name_like && (at_line_start || in_for)) {
          add(codes::kWrongOperator, leaf.range(),
              in_for ? std::string("FOR needs ':=' to set its counter")
                     : std::string("'=' compares; it does not assign"),
              in_for ? std::string("write FOR i := 1 TO 10 DO") : std::string("assign with ':='"));
          return true;
        }
      }
    }
    return false;
  }

  // An error region that only wraps complete declarations (a whole FUNCTION that could not be
  // closed) means the parser broke on what follows it: point there, not at the POU keyword.
  bool report_after_complete_declaration(SyntaxNode error) {
    uint32_t n = error.named_child_count();
    if (n == 0) return false;
    for (uint32_t i = 0; i < n; ++i) {
      SyntaxNode c = error.named_child(i);
      if (c.is_extra()) continue;
      if (c.kind().find("_declaration") == std::string_view::npos || c.has_error() || c.is_error()) return false;
    }
    SyntaxNode last = error.named_child(n - 1);
    // The first token after the error region.
    SyntaxNode next = error.next_sibling();
    while (next && next.child_count() > 0) next = next.child(0);
    if (!next || next.end() == next.begin()) return false;
    std::string readable(last.kind());
    std::replace(readable.begin(), readable.end(), '_', ' ');
    add(codes::kSyntaxError, next.range(), fmt::format("unexpected '{}' in {}", excerpt(next.text()), readable),
        "a statement starts with a name or keyword (x := ..., IF, CASE, FOR, a call f(...);)");
    return true;
  }

  // Non-empty leaves below `node` in text order (comments and pragmas skipped), at most `limit`.
  static std::vector<SyntaxNode> leaves_of(SyntaxNode node, size_t limit = 20000) {
    std::vector<SyntaxNode> leaves;
    std::vector<SyntaxNode> stack{node};
    while (!stack.empty() && leaves.size() < limit) {
      SyntaxNode n = stack.back();
      stack.pop_back();
      if (n.is_extra() && n.child_count() == 0 && n != node) continue;
      if (n.child_count() == 0) {
        if (n.end() > n.begin()) leaves.push_back(n);
        continue;
      }
      for (uint32_t i = n.child_count(); i-- > 0;) stack.push_back(n.child(i));
    }
    return leaves;
  }

  // The keyword a leaf stands for (upper case), or "" for names, literals and punctuation.
  static std::string keyword_of(SyntaxNode leaf) {
    if (leaf.is_named() && leaf.kind() != "identifier") return {};
    std::string up = upper(leaf.text());
    if (up.empty() || !std::isalpha(static_cast<unsigned char>(up[0]))) return {};
    return up;
  }

  static bool is_operator_word(std::string_view kw) {
    return kw == "AND" || kw == "OR" || kw == "XOR" || kw == "NOT" || kw == "MOD" || kw == "AND_THEN" ||
           kw == "OR_ELSE";
  }

  static bool ends_expression(SyntaxNode leaf) {
    std::string_view t = leaf.text();
    if (t == ")" || t == "]" || t == "^") return true;
    if (!keyword_of(leaf).empty() && !leaf.is_named()) return false;
    return leaf.is_named() || std::isalnum(static_cast<unsigned char>(t.empty() ? ' ' : t.back()));
  }

  struct BlockRule {
    std::string_view opener;
    std::string_view closer;
    std::string_view separator;  // the word that must follow the header (THEN, DO, OF), or ""
  };

  static const BlockRule* block_rule(std::string_view keyword) {
    static constexpr BlockRule kRules[] = {
        {"IF", "END_IF", "THEN"},        {"CASE", "END_CASE", "OF"},    {"FOR", "END_FOR", "DO"},
        {"WHILE", "END_WHILE", "DO"},    {"REPEAT", "END_REPEAT", ""},  {"STRUCT", "END_STRUCT", ""},
        {"VAR", "END_VAR", ""},          {"TYPE", "END_TYPE", ""},      {"UNION", "END_UNION", ""},
        {"VAR_INPUT", "END_VAR", ""},    {"VAR_OUTPUT", "END_VAR", ""}, {"VAR_IN_OUT", "END_VAR", ""},
        {"VAR_GLOBAL", "END_VAR", ""},   {"VAR_TEMP", "END_VAR", ""},   {"VAR_STAT", "END_VAR", ""},
        {"VAR_EXTERNAL", "END_VAR", ""}, {"VAR_INST", "END_VAR", ""},
    };
    for (const auto& r : kRules)
      if (r.opener == keyword) return &r;
    return nullptr;
  }

  // Reads the keywords inside an error region like a person would: an IF that never meets its
  // END_IF, a WHILE whose condition runs into the next line without DO, an ELSE IF.
  bool report_block_structure(SyntaxNode error) {
    std::vector<SyntaxNode> leaves = leaves_of(error);
    struct Open {
      const BlockRule* rule;
      SyntaxNode keyword;
      bool header_done;
      bool after_else;
    };
    std::vector<Open> open;
    SyntaxNode else_if;     // the ELSE of the first ELSE IF pair seen
    SyntaxNode else_if_if;  // ... and its IF
    SyntaxNode pou_end;     // an END_PROGRAM/END_FUNCTION_BLOCK/... reached while blocks were open
    for (size_t i = 0; i < leaves.size(); ++i) {
      SyntaxNode leaf = leaves[i];
      std::string kw = keyword_of(leaf);
      // A header (IF cond THEN) must reach its separator before a new line starts a statement.
      if (!open.empty() && !open.back().header_done) {
        Open& top = open.back();
        if (!top.rule->separator.empty() && kw == top.rule->separator) {
          top.header_done = true;
          continue;
        }
        if (top.rule->separator.empty()) {
          top.header_done = true;
        } else if (i > 0 && line_of(leaf.begin()) > line_of(leaves[i - 1].end()) && ends_expression(leaves[i - 1]) &&
                   !is_operator_word(kw) && leaf.text() != ")" && leaf.text() != "]") {
          SyntaxNode last = leaves[i - 1];
          add(codes::kMissingToken, {last.end(), last.end()},
              fmt::format("missing {} after the {} condition", top.rule->separator, top.rule->opener),
              fmt::format("write {} at the end of the line", top.rule->separator),
              {DiagnosticLabel{top.keyword.range(),
                               fmt::format("this {} needs {}", top.rule->opener, top.rule->separator)}});
          return true;
        }
      }
      if (kw.empty()) continue;
      if (const BlockRule* rule = block_rule(kw)) {
        bool after_else = i > 0 && keyword_of(leaves[i - 1]) == "ELSE" && kw == "IF";
        if (after_else && !else_if) {
          else_if = leaves[i - 1];
          else_if_if = leaf;
        }
        open.push_back({rule, leaf, false, after_else});
        continue;
      }
      if (kw.rfind("END_", 0) == 0) {
        // Close the innermost block this END_ belongs to; blocks above it were left open.
        for (size_t k = open.size(); k-- > 0;) {
          if (open[k].rule->closer == kw) {
            open.erase(open.begin() + static_cast<std::ptrdiff_t>(k));
            break;
          }
        }
        bool pou = kw == "END_PROGRAM" || kw == "END_FUNCTION" || kw == "END_FUNCTION_BLOCK" || kw == "END_METHOD" ||
                   kw == "END_ACTION" || kw == "END_PROPERTY" || kw == "END_TYPE";
        if (pou && !open.empty() && !pou_end) pou_end = leaf;
      }
    }
    if (open.empty()) return false;
    uint32_t at = pou_end ? pou_end.begin() : error.end();
    bool else_if_reported = false;
    for (const auto& o : open) {
      // An unclosed VAR block next to an unclosed statement is an echo of the statement.
      if (o.rule->closer == "END_VAR" && open.size() > 1) continue;
      if (else_if && !else_if_reported && o.rule->opener == "IF") {
        add(codes::kElseIf, {else_if.begin(), else_if_if.end()}, "unexpected 'ELSE IF' — did you mean ELSIF?",
            "write ELSIF; 'ELSE IF' opens a nested IF that needs its own END_IF");
        else_if_reported = true;
        continue;
      }
      std::string opener(o.rule->opener);
      add(codes::kUnclosedBlock, {at, at},
          fmt::format("{} at {} has no {}", opener, where(o.keyword.begin()), o.rule->closer),
          fmt::format("add {} to close the {} block", o.rule->closer, opener),
          {DiagnosticLabel{o.keyword.range(), fmt::format("this {} is never closed", opener)}});
    }
    return true;
  }

  // `a := 1` NEWLINE `b := 2;` parses as one broken statement; find the line break where a ';'
  // belongs: an expression ends a line and the next line starts `name :=` or `name(`.
  bool report_missing_semicolon(SyntaxNode error) {
    SyntaxNode scope = error;
    for (SyntaxNode p = error.parent(); p; p = p.parent()) {
      std::string_view k = p.kind();
      if (k.find("statement") != std::string_view::npos && k != "statement_list") {
        scope = p;
      }
      if (k == "statement_list" || k == "body" || k == "source_file" || k.find("declaration") != std::string_view::npos)
        break;
    }
    std::vector<SyntaxNode> leaves = leaves_of(scope);
    for (size_t i = 1; i + 1 < leaves.size(); ++i) {
      SyntaxNode prev = leaves[i - 1], cur = leaves[i], next = leaves[i + 1];
      if (line_of(cur.begin()) <= line_of(prev.end())) continue;
      if (!ends_expression(prev)) continue;
      if (!(cur.is_named() || keyword_of(cur).size())) continue;
      std::string_view n = next.text();
      if (n == ":=" || n == "(" || n == "S=" || n == "R=" || n == "=>" || n == ".") {
        if (!keyword_of(cur).empty() && !cur.is_named()) continue;
        add(codes::kMissingToken, {prev.end(), prev.end()}, "missing ';' after statement",
            "end the statement with ';'");
        return true;
      }
    }
    return false;
  }

  // Built on first use: most files have no syntax error and never need it.
  uint32_t line_of(uint32_t offset) {
    if (!lines_) lines_.emplace(tree_.text());
    return lines_->position_of(offset).line;
  }

  // Whether an error node's parent is a statement list: then a ';' between lines was likely meant.
  static bool starts_statement(SyntaxNode node) {
    SyntaxNode parent = node.parent();
    if (!parent) return false;
    std::string_view k = parent.kind();
    return k.find("statement") != std::string_view::npos || k == "body" || k.find("clause") != std::string_view::npos ||
           k.find("_declaration") != std::string_view::npos || k == "source_file";
  }

  static std::string describe_context(SyntaxNode node) {
    for (SyntaxNode p = node.parent(); p; p = p.parent()) {
      std::string_view k = p.kind();
      if (k == "source_file") break;
      if (k.find("statement") != std::string_view::npos || k.find("declaration") != std::string_view::npos ||
          k == "var_block" || k.find("type") != std::string_view::npos) {
        std::string readable(k);
        std::replace(readable.begin(), readable.end(), '_', ' ');
        return fmt::format(" in {}", readable);
      }
    }
    return {};
  }

  struct Explanation {
    uint32_t after;
    std::string closer;  // emptied once a stray closer used it
  };

  const SyntaxTree& tree_;
  const SyntaxDiagnosticOptions& options_;
  std::vector<Explanation> explanations_;
  std::vector<Diagnostic> out_;
  std::optional<source::LineIndex> lines_;
  uint32_t skip_errors_until_ = 0;
  size_t dropped_ = 0;
};

}  // namespace

std::vector<Diagnostic> collect_syntax_diagnostics(const SyntaxTree& tree, const SyntaxDiagnosticOptions& options) {
  return Collector(tree, options).run();
}

}  // namespace rung
