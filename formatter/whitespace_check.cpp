#include "formatter/whitespace_check.hpp"

#include <algorithm>
#include <vector>

#include "formatter/comment_text.hpp"
#include "formatter/keyword_case.hpp"

namespace rung::format {
namespace {

// The most characters the scanner's look-ahead for a ';' reads (`budget` in rest_has_semicolon,
// grammar/src/scanner.c), with a margin.
constexpr uint32_t kScanLimit = 4096 - 96;

enum class Gap : uint8_t { None, Blanks, Break };

struct Piece {
  std::string_view text;  // in the input
  uint32_t offset = 0;
  bool ignore_case = false;
};

// What the formatter writes between tokens; the lexer and the scanner skip each of them alike.
bool is_gap_byte(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r';
}

// A character the scanner may read as part of a word (bytes of non-ASCII characters included, to
// be safe).
bool is_word_byte(char c) {
  const auto u = static_cast<unsigned char>(c);
  return (u >= 'a' && u <= 'z') || (u >= 'A' && u <= 'Z') || (u >= '0' && u <= '9') || u == '_' || u >= 0x80;
}

bool is_word_start_byte(char c) {
  return is_word_byte(c) && !(c >= '0' && c <= '9');
}

char upper(char c) {
  return c >= 'a' && c <= 'z' ? static_cast<char>(c - 'a' + 'A') : c;
}

Gap classify(std::string_view gap) {
  if (gap.empty()) return Gap::None;
  return gap.find_first_of("\r\n") != std::string_view::npos ? Gap::Break : Gap::Blanks;
}

// The word the scanner may read up to the end of `a` could be S, R or REF (then a '=' right
// after it is the ExST assignment S=, R=, REF=).
bool may_end_assignment_word(std::string_view input, const Piece& a) {
  const size_t end = a.offset + a.text.size();
  const char last = upper(input[end - 1]);
  if (last == 'S' || last == 'R') return true;
  return end >= 3 && last == 'F' && upper(input[end - 2]) == 'E' && upper(input[end - 3]) == 'R';
}

// '<' of a generic type, '#' of a typed literal, '...' of a variadic type: the grammar reads them
// only right after the token before them. ('<' is looked up in the tree: it is mostly less-than.)
bool reads_immediately(const SyntaxTree& tree, const Piece& p) {
  if (p.text == "#" || p.text == "...") return true;
  if (p.text != "<") return false;
  const SyntaxNode leaf = tree.root().descendant_for_range(p.offset, p.offset + 1);
  return leaf.parent().kind() == "generic_type";
}

// Whether some reading of the grammar depends on whether `a` and `b` touch.
bool touching_matters(const SyntaxTree& tree, std::string_view input, const Piece& a, const Piece& b) {
  const char last = a.text.back();
  const char first = b.text.front();
  if (last == '#' || reads_immediately(tree, b)) return true;
  if (is_word_byte(last) && is_word_byte(first)) return true;
  if (first == '*' && (last == '(' || last == '/')) return true;
  if (first == '/' && last == '/') return true;
  if (first == '=' && (last == ':' || (is_word_byte(last) && may_end_assignment_word(input, a)))) return true;
  return false;
}

// Blanks between `a` and `b` may go: no token goes on across these characters.
bool may_join(const Piece& a, const Piece& b) {
  const char last = a.text.back();
  const char first = b.text.front();
  if (std::string_view("<.#=*/").find(first) != std::string_view::npos) return false;
  return std::string_view(")],;").find(last) != std::string_view::npos ||
         std::string_view(")],;([").find(first) != std::string_view::npos;
}

bool same_piece(const Piece& p, std::string_view out) {
  if (out.size() != p.text.size()) return false;
  return p.ignore_case ? equal_ignoring_case(p.text, out) : p.text == out;
}

// The characters of a pragma as the scanner's ';' look-ahead reads them (it does not know
// pragmas): parentheses and ';' outside quotes count. False when a quote stays open (the scanner
// would then skip past the pragma) or a comment opener stands in it.
struct PragmaScan {
  bool plain = true;
  int depth_change = 0;
  bool semicolon = false;
};
PragmaScan scan_pragma(std::string_view text) {
  PragmaScan r;
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    const char next = i + 1 < text.size() ? text[i + 1] : '\0';
    if (c == '\'' || c == '"') {
      size_t j = i + 1;
      while (j < text.size() && text[j] != c && text[j] != '\n' && text[j] != '\r') j += text[j] == '$' ? 2 : 1;
      if (j >= text.size() || text[j] != c) r.plain = false;
      i = j;
    } else if ((c == '(' && next == '*') || (c == '/' && (next == '/' || next == '*'))) {
      r.plain = false;
    } else if (c == '(') {
      ++r.depth_change;
    } else if (c == ')') {
      --r.depth_change;
    } else if (c == ';') {
      r.semicolon = true;
    }
  }
  return r;
}

bool is_pragma(std::string_view piece) {
  return piece.front() == '{';
}

// What the scanner's look-ahead spends on a piece: one step for a comment or a string, one per
// character for anything else.
uint32_t scan_cost(const Piece& p) {
  const char first = p.text.front();
  if (is_comment(p.text) || first == '\'' || first == '"') return 1;
  return static_cast<uint32_t>(p.text.size());
}

struct Gaps {
  std::vector<uint32_t> in;   // bytes of the gap before each piece, in the input
  std::vector<uint32_t> out;  // the same in the output
  std::vector<Gap> kind;      // its class (the same in both)
};

// The scanner's look-ahead for a ';' never runs out of budget, in either text:
// - to the end of a line (IL operands): every stretch between line breaks or ';' stays short;
// - to the ')' that closes a '(' at the start of a line (a call after an IL line): every '(' on a
//   line that starts with a word, up to its ')' or the next ';', stays short.
bool scanner_budget_suffices(const std::vector<Piece>& pieces, const Gaps& gaps) {
  std::vector<PragmaScan> pragma(pieces.size());
  for (size_t k = 0; k < pieces.size(); ++k) {
    if (is_pragma(pieces[k].text)) {
      pragma[k] = scan_pragma(pieces[k].text);
      if (!pragma[k].plain) return false;
    }
  }
  auto is_semicolon = [&](size_t k) { return pieces[k].text == ";" || pragma[k].semicolon; };
  uint32_t line_in = 0;
  uint32_t line_out = 0;
  for (size_t k = 0; k < pieces.size(); ++k) {
    if (gaps.kind[k] == Gap::Break) {
      line_in = line_out = 0;
    } else {
      line_in += gaps.in[k];
      line_out += gaps.out[k];
    }
    line_in += scan_cost(pieces[k]);
    line_out += scan_cost(pieces[k]);
    if (line_in >= kScanLimit || line_out >= kScanLimit) return false;
    if (is_semicolon(k)) line_in = line_out = 0;
  }
  // Each scan below stops within kScanLimit steps; the total bound keeps bad input linear.
  size_t steps_left = 16 * pieces.size() + 65536;
  bool line_starts_with_word = false;
  for (size_t k = 0; k < pieces.size(); ++k) {
    if (k == 0 || gaps.kind[k] == Gap::Break) line_starts_with_word = is_word_start_byte(pieces[k].text.front());
    if (!line_starts_with_word || pieces[k].text != "(") continue;
    int depth = 1;
    uint32_t cost_in = 0;
    uint32_t cost_out = 0;
    for (size_t j = k + 1; j < pieces.size() && depth > 0; ++j) {
      if (steps_left-- == 0) return false;
      cost_in += gaps.in[j] + scan_cost(pieces[j]);
      cost_out += gaps.out[j] + scan_cost(pieces[j]);
      if (cost_in >= kScanLimit || cost_out >= kScanLimit) return false;
      if (is_semicolon(j)) break;
      if (pieces[j].text == "(") ++depth;
      if (pieces[j].text == ")") --depth;
      depth += pragma[j].depth_change;
    }
  }
  return true;
}

}  // namespace

bool only_safe_whitespace_changes(CheckInput input, const std::vector<Leaf>& leaves, std::string_view output) {
  const std::string_view text = input.text;
  std::vector<Piece> pieces;
  pieces.reserve(leaves.size());
  for (const Leaf& leaf : leaves) {
    if (leaf.end <= leaf.begin || leaf.end > text.size()) return false;
    pieces.push_back({text.substr(leaf.begin, leaf.end - leaf.begin), leaf.begin,
                      !leaf.trivia() && leaf.case_class != CaseClass::None});
  }

  // A byte order mark stays in front of both texts.
  static constexpr std::string_view kBom = "\xEF\xBB\xBF";
  const bool bom = text.substr(0, 3) == kBom;
  if (bom != (output.substr(0, 3) == kBom)) return false;
  size_t in_at = bom ? 3 : 0;
  size_t out_at = in_at;

  Gaps gaps;
  gaps.in.reserve(pieces.size());
  gaps.out.reserve(pieces.size());
  gaps.kind.reserve(pieces.size());
  for (size_t k = 0; k < pieces.size(); ++k) {
    const Piece& p = pieces[k];
    if (p.offset < in_at) return false;
    const std::string_view gap_in = text.substr(in_at, p.offset - in_at);
    if (!std::all_of(gap_in.begin(), gap_in.end(), is_gap_byte)) return false;
    size_t out_end = out_at;
    while (out_end < output.size() && is_gap_byte(output[out_end])) ++out_end;
    const std::string_view gap_out = output.substr(out_at, out_end - out_at);

    const Gap kind_in = classify(gap_in);
    const Gap kind_out = classify(gap_out);
    if (kind_in != kind_out) {
      if (k == 0 || kind_in == Gap::Break || kind_out == Gap::Break) return false;
      if (touching_matters(*input.tree, text, pieces[k - 1], p)) return false;
      if (kind_out == Gap::None && !may_join(pieces[k - 1], p)) return false;
    }
    size_t printed_size = p.text.size();
    if (!same_piece(p, output.substr(out_end, p.text.size()))) {
      // A comment may lose the blanks at its line ends (comment_text.hpp); it stays one comment,
      // ends where it ended, and the scanner's look-ahead counts it as one step either way.
      if (!is_comment(p.text)) return false;
      const std::string printed = printed_comment(p.text);
      if (output.substr(out_end, printed.size()) != printed) return false;
      printed_size = printed.size();
    }
    gaps.in.push_back(static_cast<uint32_t>(gap_in.size()));
    gaps.out.push_back(static_cast<uint32_t>(gap_out.size()));
    gaps.kind.push_back(kind_in);
    in_at = p.offset + p.text.size();
    out_at = out_end + printed_size;
  }
  // Only whitespace after the last piece, in both texts (the scanner treats the end of the text
  // alike whatever whitespace comes before it).
  const std::string_view tail_in = text.substr(std::min(in_at, text.size()));
  const std::string_view tail_out = output.substr(std::min(out_at, output.size()));
  if (!std::all_of(tail_in.begin(), tail_in.end(), is_gap_byte)) return false;
  if (!std::all_of(tail_out.begin(), tail_out.end(), is_gap_byte)) return false;
  return scanner_budget_suffices(pieces, gaps);
}

}  // namespace rung::format
