#include "checker/query/cursor_context.hpp"

#include <algorithm>
#include <array>

#include "checker/query/position.hpp"

namespace rung::check::query {
namespace {

using namespace std::string_view_literals;

constexpr auto kVarOpeners = std::to_array({"VAR"sv, "VAR_INPUT"sv, "VAR_OUTPUT"sv, "VAR_IN_OUT"sv, "VAR_GLOBAL"sv,
                                            "VAR_EXTERNAL"sv, "VAR_TEMP"sv, "VAR_STAT"sv, "VAR_INST"sv,
                                            "VAR_CONFIG"sv, "VAR_ACCESS"sv});
constexpr auto kVarQualifiers = std::to_array({"CONSTANT"sv, "RETAIN"sv, "NON_RETAIN"sv, "PERSISTENT"sv});
// Reserved words that open a POU (or a configuration) wherever they stand.
constexpr auto kPouOpeners = std::to_array({"PROGRAM"sv, "FUNCTION"sv, "FUNCTION_BLOCK"sv, "FUNCTIONBLOCK"sv,
                                            "CLASS"sv, "INTERFACE"sv, "CONFIGURATION"sv, "RESOURCE"sv});
// Contextual words (real code names variables so): members of a block.
constexpr auto kMemberOpeners = std::to_array({"METHOD"sv, "PROPERTY"sv, "ACTION"sv, "TRANSITION"sv});
constexpr auto kControlOpeners = std::to_array({"IF"sv, "CASE"sv, "FOR"sv, "WHILE"sv, "REPEAT"sv});
constexpr auto kModifiers = std::to_array({"PUBLIC"sv, "PRIVATE"sv, "PROTECTED"sv, "INTERNAL"sv, "ABSTRACT"sv,
                                           "FINAL"sv, "OVERRIDE"sv});
// After these a value begins.
constexpr auto kValueStarters =
    std::to_array({":="sv, "=>"sv, "("sv, ","sv, "["sv, "+"sv, "-"sv, "*"sv, "/"sv, "**"sv, "="sv, "<>"sv, "<"sv,
                   ">"sv, "<="sv, ">="sv, "&"sv, "AND"sv, "OR"sv, "XOR"sv, "NOT"sv, "MOD"sv, "AND_THEN"sv,
                   "OR_ELSE"sv, "IF"sv, "ELSIF"sv, "WHILE"sv, "UNTIL"sv, "CASE"sv, "TO"sv, "BY"sv, "RETURN"sv});

template <size_t N>
std::string_view find_word(const std::array<std::string_view, N>& words, std::string_view upper) {
  for (std::string_view word : words) {
    if (word == upper) return word;
  }
  return {};
}

bool is_word_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
}

bool is_digit(char c) { return c >= '0' && c <= '9'; }

enum class FrameKind : uint8_t { Pou, Var, Type, Struct, Control };

struct Frame {
  FrameKind kind;
  std::string_view keyword;  // upper case, from the tables above
  size_t start = 0;          // index of the opening token
  bool header_open = false;  // Pou: still reading the header line
  bool in_body = false;      // Pou: a statement has begun
};

// Whether the token ends a value: a name, a literal, ')', ']', '^'.
bool ends_operand(const CodeToken& token) {
  if (token.word) return true;
  const std::string_view text = token.text;
  if (text == ")" || text == "]" || text == "^") return true;
  const char first = text.empty() ? '\0' : text.front();
  return is_digit(first) || first == '\'' || first == '"' || first == '%' || text.find('#') != std::string_view::npos;
}

bool newline_between(std::string_view text, uint32_t from, uint32_t to) {
  return from < to && text.substr(from, to - from).find('\n') != std::string_view::npos;
}

class Scanner {
 public:
  Scanner(const std::vector<CodeToken>& tokens, std::string_view text) : tokens_(tokens), text_(text) {}

  void run() {
    for (size_t i = 0; i < tokens_.size(); ++i) step(i);
  }

  const std::vector<Frame>& frames() const { return frames_; }
  size_t statement_start() const { return statement_start_; }
  const std::vector<size_t>& brackets() const { return brackets_; }

  // Whether the header of the innermost POU is still open at `offset` (the cursor).
  bool header_open_at(uint32_t offset) const {
    if (frames_.empty() || frames_.back().kind != FrameKind::Pou || !frames_.back().header_open) return false;
    if (tokens_.empty()) return true;
    const size_t last = tokens_.size() - 1;
    return !newline_between(text_, tokens_[last].range.end, offset) || continues_header(last, frames_.back());
  }

 private:
  bool continues_header(size_t previous, const Frame& frame) const {
    if (previous == frame.start) return true;  // the name on the next line
    const std::string up = tokens_[previous].word ? upper_name(tokens_[previous].text) : std::string(tokens_[previous].text);
    return up == ":" || up == "," || up == "<" || up == "(" || up == "EXTENDS" || up == "IMPLEMENTS" || up == "OF" ||
           up == "TO" || !find_word(kModifiers, up).empty();
  }

  Frame* top() { return frames_.empty() ? nullptr : &frames_.back(); }

  void start_statement(size_t next) {
    statement_start_ = next;
    brackets_.clear();
  }

  // The next token is no assignment or call: the word before it is used as a keyword.
  bool used_as_keyword(size_t i) const {
    if (i + 1 >= tokens_.size()) return true;
    const std::string_view next = tokens_[i + 1].text;
    return next != ":=" && next != "." && next != "(" && next != "[" && next != ";" && next != "^";
  }

  void push(FrameKind kind, std::string_view keyword, size_t i) {
    if (Frame* pou = top(); pou && pou->kind == FrameKind::Pou) pou->header_open = false;
    frames_.push_back(Frame{.kind = kind, .keyword = keyword, .start = i, .header_open = kind == FrameKind::Pou});
  }

  // END_xxx: closes the innermost frame it matches and everything opened inside it.
  bool close(std::string_view closer) {
    if (!closer.starts_with("END_")) return false;
    std::string_view opened = closer.substr(4);
    if (opened == "FUNCTIONBLOCK") opened = "FUNCTION_BLOCK";
    for (size_t f = frames_.size(); f-- > 0;) {
      std::string_view keyword = frames_[f].keyword;
      if (keyword == "FUNCTIONBLOCK") keyword = "FUNCTION_BLOCK";
      const bool matches = opened == "VAR" ? frames_[f].kind == FrameKind::Var : keyword == opened;
      if (matches) {
        frames_.resize(f);
        return true;
      }
    }
    return false;
  }

  void step(size_t i) {
    const CodeToken& token = tokens_[i];
    Frame* frame = top();
    if (frame && frame->kind == FrameKind::Pou && frame->header_open && i > 0 &&
        newline_between(text_, tokens_[i - 1].range.end, token.range.begin) && !continues_header(i - 1, *frame)) {
      frame->header_open = false;
    }
    const std::string up = token.word ? upper_name(token.text) : std::string();
    const bool in_pou = frame && frame->kind == FrameKind::Pou;
    const bool declarations = !frame || (in_pou && !frame->in_body);
    if (token.word) {
      if (std::string_view var = find_word(kVarOpeners, up); !var.empty() && (!frame || frame->kind == FrameKind::Pou)) {
        push(FrameKind::Var, var, i);
        start_statement(i + 1);
        return;
      }
      if (close(up)) {
        if (Frame* pou = top(); pou && pou->kind == FrameKind::Pou) pou->header_open = false;
        start_statement(i + 1);
        return;
      }
      if (std::string_view pou = find_word(kPouOpeners, up); !pou.empty() && declarations) {
        push(FrameKind::Pou, pou, i);
        start_statement(i + 1);
        return;
      }
      if (std::string_view member = find_word(kMemberOpeners, up);
          !member.empty() && (!frame || in_pou) && used_as_keyword(i)) {
        push(FrameKind::Pou, member, i);
        start_statement(i + 1);
        return;
      }
      if ((up == "GET" || up == "SET") && in_pou && frame->keyword == "PROPERTY" && used_as_keyword(i)) {
        push(FrameKind::Pou, up == "GET" ? "GET"sv : "SET"sv, i);
        start_statement(i + 1);
        return;
      }
      if (up == "TYPE" && declarations && used_as_keyword(i)) {
        push(FrameKind::Type, "TYPE", i);
        start_statement(i + 1);
        return;
      }
      if ((up == "STRUCT" || up == "UNION") && frame &&
          (frame->kind == FrameKind::Type || frame->kind == FrameKind::Var || frame->kind == FrameKind::Struct)) {
        frames_.push_back(Frame{.kind = FrameKind::Struct, .keyword = up == "STRUCT" ? "STRUCT"sv : "UNION"sv, .start = i});
        start_statement(i + 1);
        return;
      }
    }
    if (in_pou && !frame->in_body && !frame->header_open) {
      frame->in_body = true;  // the first token after the declarations begins the body
      start_statement(i);
    }
    const bool body = frame && ((in_pou && frame->in_body) || frame->kind == FrameKind::Control);
    if (body && token.word) {
      if (std::string_view control = find_word(kControlOpeners, up); !control.empty()) {
        frames_.push_back(Frame{.kind = FrameKind::Control, .keyword = control, .start = i});
        start_statement(control == "REPEAT" ? i + 1 : i);
        return;
      }
      if (up == "ELSIF" || up == "UNTIL") {
        start_statement(i);
        return;
      }
      if (up == "THEN" || up == "ELSE" || up == "DO" || up == "OF") {
        start_statement(i + 1);
        return;
      }
    }
    const std::string_view text = token.text;
    if (text == ";" || (body && text == ":")) {
      start_statement(i + 1);
    } else if (text == "(" || text == "[") {
      brackets_.push_back(i);
    } else if ((text == ")" || text == "]") && !brackets_.empty()) {
      brackets_.pop_back();
    }
  }

  const std::vector<CodeToken>& tokens_;
  std::string_view text_;
  std::vector<Frame> frames_;
  size_t statement_start_ = 0;
  std::vector<size_t> brackets_;  // open '(' and '[' of the current statement
};

// Where the scan starts: the top-level declaration around (or before) the cursor. An ERROR node
// of the file's top level is no clean start; the declaration before it is.
uint32_t scan_start(SyntaxNode root, uint32_t offset) {
  uint32_t start = 0;
  for (SyntaxNode child : root.named_children()) {
    if (child.begin() > offset) break;
    if (!child.is_error() && child.kind() != "comment" && child.kind() != "pragma") start = child.begin();
  }
  return start;
}

// The comment, string or pragma that holds the cursor, if any.
SyntaxNode inert_text_at(SyntaxNode root, uint32_t offset) {
  if (offset == 0) return {};
  SyntaxNode node = root.descendant_for_range(offset - 1, offset);
  for (; node; node = node.parent()) {
    const std::string_view kind = node.kind();
    if (kind == "comment" || kind == "string_literal" || kind == "pragma") break;
    if (node.is_named() && kind != "ERROR") return {};
  }
  if (!node || node.begin() >= offset) return {};
  if (offset < node.end()) return node;
  // At the very end: only a line comment still holds the cursor.
  return node.kind() == "comment" && node.text().starts_with("//") ? node : SyntaxNode();
}

// The formal name an argument's tokens start with (`name :=`, `name =>`).
std::string_view formal_name(const std::vector<CodeToken>& tokens, size_t begin, size_t end, bool* output) {
  if (end - begin < 2 || !tokens[begin].word) return {};
  const std::string_view op = tokens[begin + 1].text;
  if (op != ":=" && op != "=>") return {};
  if (output) *output = op == "=>";
  return tokens[begin].text;
}

// What the cursor means inside the argument list opened by tokens[open].
CallContext call_context(const std::vector<CodeToken>& tokens, size_t open, size_t callee_begin) {
  CallContext call{.callee = {tokens[callee_begin].range.begin, tokens[open - 1].range.end}, .open = tokens[open].range};
  int depth = 0;
  size_t argument_begin = open + 1;
  auto finish_argument = [&](size_t end) {
    if (std::string_view name = formal_name(tokens, argument_begin, end, nullptr); !name.empty()) call.given.push_back(name);
  };
  for (size_t i = open + 1; i < tokens.size(); ++i) {
    const std::string_view text = tokens[i].text;
    if (text == "(" || text == "[") ++depth;
    if ((text == ")" || text == "]") && depth > 0) --depth;
    if (depth == 0 && (text == "," || text == "|")) {
      finish_argument(i);
      ++call.argument_index;
      argument_begin = i + 1;
    }
  }
  call.argument_start = argument_begin == tokens.size();
  call.named = formal_name(tokens, argument_begin, tokens.size(), &call.output);
  return call;
}

// The POU the scan found open when the symbols have no declaration around the cursor (a header
// error recovery could not read): by its name, a member by its owner's.
const Symbol* lexical_scope(const ProjectModel& model, const std::vector<CodeToken>& tokens,
                            const std::vector<Frame>& frames) {
  const Symbol* scope = nullptr;
  for (const Frame& frame : frames) {
    if (frame.kind != FrameKind::Pou || frame.start + 1 >= tokens.size() || !tokens[frame.start + 1].word) continue;
    const std::string_view name = tokens[frame.start + 1].text;
    const Symbol* found = scope ? model.find_member(scope, name) : model.find_global(name);
    if (found) scope = found;
  }
  return scope;
}

}  // namespace

std::vector<CodeToken> code_tokens(SyntaxNode root, uint32_t begin, uint32_t end) {
  std::vector<CodeToken> tokens;
  walk_preorder(root, [&](SyntaxNode node) {
    if (node.end() <= begin || node.begin() >= end) return false;
    const std::string_view kind = node.kind();
    if (kind == "comment" || kind == "pragma") return false;
    if (node.child_count() > 0) return true;
    if (node.begin() >= begin && node.end() <= end && node.end() > node.begin()) {
      const std::string_view text = node.text();
      const bool word = !text.empty() && !is_digit(text.front()) && is_word_char(text.front()) &&
                        std::all_of(text.begin(), text.end(), is_word_char);
      const uint32_t previous_end = tokens.empty() ? begin : tokens.back().range.end;
      tokens.push_back({.text = text,
                        .range = node.range(),
                        .word = word,
                        .newline_before = newline_between(root.source(), previous_end, node.begin())});
    }
    return false;
  });
  return tokens;
}

std::optional<size_t> postfix_chain_begin(const std::vector<CodeToken>& tokens, size_t last) {
  size_t i = last;
  for (int guard = 0; guard < 256; ++guard) {
    const std::string_view text = tokens[i].text;
    if (text == ")" || text == "]") {
      const std::string_view open = text == ")" ? "(" : "[";
      int depth = 0;
      size_t j = i;
      for (;; --j) {
        if (tokens[j].text == text) ++depth;
        if (tokens[j].text == open && --depth == 0) break;
        if (j == 0) return std::nullopt;
      }
      if (j > 0 && ends_operand(tokens[j - 1]) && !tokens[j - 1].text.starts_with("'")) {
        i = j - 1;  // F(x), a[i]: the called or indexed expression
        continue;
      }
      if (open == "[") return std::nullopt;
      return j;  // (expression)
    }
    if (text == "^") {
      if (i == 0) return std::nullopt;
      i -= 1;
      continue;
    }
    if (!tokens[i].word) return std::nullopt;
    if (i >= 2 && tokens[i - 1].text == "." && ends_operand(tokens[i - 2]) && !is_digit(tokens[i - 2].text.front()) &&
        !tokens[i - 1].newline_before && !tokens[i].newline_before) {
      i -= 2;
      continue;
    }
    return i;
  }
  return std::nullopt;
}

CursorContext cursor_context(const ProjectModel& model, SourceId source, uint32_t tree_offset) {
  CursorContext context;
  if (source >= model.source_count()) return context;
  const Document& document = *model.source(source).document;
  const SyntaxTree* tree = document.tree();
  if (!tree || tree->aborted()) return context;
  const std::string_view text = tree->text();
  const SyntaxNode root = tree->root();
  tree_offset = std::min<uint32_t>(tree_offset, static_cast<uint32_t>(text.size()));
  const SyntaxNode inert = inert_text_at(root, tree_offset);
  if (inert && inert.kind() != "string_literal") return context;

  uint32_t word_begin = tree_offset;
  while (word_begin > 0 && is_word_char(text[word_begin - 1])) --word_begin;
  uint32_t word_end = tree_offset;
  while (word_end < text.size() && is_word_char(text[word_end])) ++word_end;
  context.word = {word_begin, word_end};
  context.prefix = text.substr(word_begin, tree_offset - word_begin);
  // In a string or a number nothing is completed, but the call around it is still of interest.
  const bool value = inert || (!context.prefix.empty() && is_digit(context.prefix.front()));

  const std::vector<CodeToken> tokens = code_tokens(root, scan_start(root, word_begin), word_begin);
  Scanner scanner(tokens, text);
  scanner.run();
  const std::vector<Frame>& frames = scanner.frames();
  context.scope = scope_at(model, source, word_begin);
  if (!context.scope) context.scope = lexical_scope(model, tokens, frames);
  for (auto frame = frames.rbegin(); frame != frames.rend(); ++frame) {
    if (frame->kind == FrameKind::Pou) {
      context.pou_keyword = frame->keyword;
      break;
    }
  }

  const size_t n = tokens.size();
  const CodeToken* previous = n > 0 ? &tokens[n - 1] : nullptr;
  const std::string previous_word = previous && previous->word ? upper_name(previous->text) : std::string();
  const std::string_view previous_text = previous ? std::string_view(previous_word.empty() ? previous->text : previous_word)
                                                  : std::string_view();

  const bool body = !frames.empty() && (frames.back().kind == FrameKind::Control ||
                                        (frames.back().kind == FrameKind::Pou && frames.back().in_body));
  if (body && !scanner.brackets().empty()) {
    const size_t open = scanner.brackets().back();
    if (tokens[open].text == "(" && open > 0 && ends_operand(tokens[open - 1])) {
      if (const std::optional<size_t> callee = postfix_chain_begin(tokens, open - 1)) {
        context.call = call_context(tokens, open, *callee);
      }
    }
  }

  if (value) return context;

  // After '.' and '#' on the same line: members of what stands before.
  if ((previous_text == "." || previous_text == "#") && n >= 2 && tokens[n - 2].range.end == previous->range.begin &&
      !newline_between(text, previous->range.end, word_begin)) {
    const std::optional<size_t> begin = postfix_chain_begin(tokens, n - 2);
    if (!begin || (previous_text == "#" && !tokens[n - 2].word)) return context;
    context.place = previous_text == "." ? CursorPlace::Member : CursorPlace::TypedLiteral;
    context.qualifier = {tokens[*begin].range.begin, tokens[n - 2].range.end};
    // Lib.T in a declaration names a type of the library.
    if (*begin > 0) {
      const std::string before = upper_name(tokens[*begin - 1].text);
      context.type_qualifier = !body && (before == ":" || before == "OF" || before == "TO" || before == "EXTENDS" ||
                                         before == "IMPLEMENTS" || before == ",");
    }
    return context;
  }

  if (frames.empty()) {
    context.place = CursorPlace::TopLevel;
    return context;
  }
  const Frame& frame = frames.back();
  const size_t statement = std::min(scanner.statement_start(), n);

  switch (frame.kind) {
    case FrameKind::Var:
    case FrameKind::Struct:
    case FrameKind::Type: {
      context.block_keyword = frame.keyword;
      if (statement == n) {
        context.place = CursorPlace::VarName;
        context.var_qualifiers =
            frame.kind == FrameKind::Var && previous && (n - 1 == frame.start || !find_word(kVarQualifiers, previous_text).empty());
        return context;
      }
      bool colon = false;
      for (size_t i = statement; i < n; ++i) {
        if (tokens[i].text == ":=") {
          context.place = CursorPlace::Expression;
          return context;
        }
        colon = colon || tokens[i].text == ":";
      }
      if (!colon) {
        // Qualifiers right after the block's keyword: VAR CONSTANT |
        bool qualifiers = true;
        for (size_t i = statement; i < n; ++i) qualifiers = qualifiers && !find_word(kVarQualifiers, upper_name(tokens[i].text)).empty();
        if (qualifiers && frame.kind == FrameKind::Var) {
          context.place = CursorPlace::VarName;
          context.var_qualifiers = true;
        }
        return context;  // names being declared
      }
      if (previous_text == ":" || previous_text == "OF" || previous_text == "TO") {
        context.place = CursorPlace::TypeName;
        context.type_constructors = true;
        context.structured_types = frame.kind == FrameKind::Type && previous_text == ":";
      } else if (!scanner.brackets().empty()) {
        context.place = CursorPlace::Expression;  // array bounds, STRING(n)
      }
      return context;
    }
    case FrameKind::Pou:
      if (scanner.header_open_at(word_begin)) {
        if (n - 1 == frame.start || !find_word(kModifiers, previous_text).empty()) return context;  // the name
        bool extends = false, implements = false;
        for (size_t i = frame.start; i < n; ++i) {
          const std::string up = upper_name(tokens[i].text);
          extends = extends || up == "EXTENDS";
          implements = implements || up == "IMPLEMENTS";
        }
        if (previous_text == ":" || previous_text == "OF" || previous_text == "TO") {
          context.place = CursorPlace::TypeName;
          context.type_constructors = true;
        } else if (previous_text == "EXTENDS" || (previous_text == "," && extends && !implements)) {
          context.place = CursorPlace::TypeName;
          context.types = frame.keyword == "INTERFACE" ? TypeFilter::Interfaces : TypeFilter::Blocks;
        } else if (previous_text == "IMPLEMENTS" || (previous_text == "," && implements)) {
          context.place = CursorPlace::TypeName;
          context.types = TypeFilter::Interfaces;
        } else {
          context.place = CursorPlace::PouHeader;
        }
        return context;
      }
      if (!frame.in_body) {
        context.place = CursorPlace::PouDeclarations;
        return context;
      }
      break;
    case FrameKind::Control: break;
  }

  // A body: statements and expressions.
  for (auto open = frames.rbegin(); open != frames.rend() && open->kind == FrameKind::Control; ++open) {
    context.open_blocks.push_back(open->keyword);
  }
  if (statement == n) {
    context.place = CursorPlace::Statement;
    return context;
  }
  if (previous_text == "JMP") return context;  // a label
  if (!find_word(kValueStarters, previous_text).empty()) {
    context.place = CursorPlace::Expression;
    if (previous_text == ":=" && !context.call && n >= 2) {
      if (const std::optional<size_t> target = postfix_chain_begin(tokens, n - 2); target && *target == statement) {
        context.assigned = {tokens[*target].range.begin, tokens[n - 2].range.end};
      }
    }
    return context;
  }
  if (!ends_operand(*previous)) {
    // Something unfinished on an earlier line (`fbTimer.`): the user has moved on to a new statement.
    if (newline_between(text, previous->range.end, word_begin)) context.place = CursorPlace::Statement;
    return context;
  }
  context.place = CursorPlace::Operator;
  const std::string opener = upper_name(tokens[statement].text);
  if (opener == "IF" || opener == "ELSIF") context.continuations = {"THEN"};
  if (opener == "WHILE") context.continuations = {"DO"};
  if (opener == "CASE") context.continuations = {"OF"};
  if (opener == "UNTIL") context.continuations = {"END_REPEAT"};
  if (opener == "FOR") {
    bool to = false;
    for (size_t i = statement; i < n; ++i) to = to || names_equal(tokens[i].text, "TO");
    context.continuations = to ? std::vector<std::string_view>{"BY", "DO"} : std::vector<std::string_view>{"TO"};
  }
  // A value on an earlier line without ';' may be a statement the user has not closed yet.
  if (newline_between(text, previous->range.end, word_begin) && context.continuations.empty() && !context.call) {
    context.place = CursorPlace::Statement;
  }
  return context;
}

}  // namespace rung::check::query
