#include "checker/project/conditional_compilation.hpp"

#include <fmt/format.h>

#include <cctype>
#include <optional>

#include "checker/symbols/names.hpp"
#include "parser/diagnostic_codes.hpp"

namespace rung::project {
namespace {

using check::names_equal;
using check::upper_name;

bool is_word_start(char c) {
  return std::isalpha(static_cast<unsigned char>(c)) || c == '_';
}
bool is_word_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}
bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n';
}

enum class Directive { If, ElsIf, Else, EndIf, Define, Undefine };

// A pragma's content split into its directive word and the rest ("IF defined(X)" -> If, " defined(X)").
struct DirectiveText {
  Directive directive = Directive::If;
  uint32_t rest_begin = 0;  // offset of the text after the word, in the text
  std::string_view rest;
};

std::optional<DirectiveText> read_directive(std::string_view text, TextRange content) {
  uint32_t i = content.begin;
  while (i < content.end && is_space(text[i])) ++i;
  const uint32_t word_begin = i;
  while (i < content.end && is_word_char(text[i])) ++i;
  const std::string word = upper_name(text.substr(word_begin, i - word_begin));
  DirectiveText out;
  if (word == "IF") {
    out.directive = Directive::If;
  } else if (word == "ELSIF") {
    out.directive = Directive::ElsIf;
  } else if (word == "ELSE") {
    out.directive = Directive::Else;
  } else if (word == "END_IF") {
    out.directive = Directive::EndIf;
  } else if (word == "DEFINE") {
    out.directive = Directive::Define;
  } else if (word == "UNDEFINE") {
    out.directive = Directive::Undefine;
  } else {
    return std::nullopt;
  }
  out.rest_begin = i;
  out.rest = text.substr(i, content.end - i);
  return out;
}

// --- Conditions -----------------------------------------------------------------------------

struct CondToken {
  enum class Kind { Name, String, Number, Open, Close, Comma, Colon, End, Bad };
  Kind kind = Kind::End;
  std::string_view text;  // a String's text is without its quotes
  uint32_t begin = 0;     // offsets in the whole text
  uint32_t end = 0;
};

// Reads one condition and, when `evaluate` is set, computes it. Syntax errors are reported once
// (the first one) and make the condition false.
class ConditionReader {
 public:
  ConditionReader(std::string_view text, uint32_t begin, uint32_t end, uint32_t at, bool evaluate,
                  const std::map<std::string, std::string>& defines, const DeclarationOracle& oracle)
      : text_(text), pos_(begin), end_(end), at_(at), evaluate_(evaluate), defines_(defines), oracle_(oracle) {
    advance();
  }

  // The value of the condition; nullopt after a syntax error (`error()` says which).
  std::optional<bool> read() {
    if (token_.kind == CondToken::Kind::End) return fail(token_, "missing condition after {IF}/{ELSIF}");
    std::optional<bool> value = read_or();
    if (!value) return std::nullopt;
    if (token_.kind != CondToken::Kind::End)
      return fail(token_, fmt::format("unexpected '{}' in condition", token_.text));
    return value;
  }
  const std::optional<Diagnostic>& error() const { return error_; }

 private:
  using Kind = CondToken::Kind;

  std::optional<bool> read_or() {
    std::optional<bool> left = read_and();
    while (left && is_keyword("OR")) {
      advance();
      std::optional<bool> right = read_and();
      if (!right) return std::nullopt;
      left = *left || *right;
    }
    return left;
  }

  std::optional<bool> read_and() {
    std::optional<bool> left = read_not();
    while (left && is_keyword("AND")) {
      advance();
      std::optional<bool> right = read_not();
      if (!right) return std::nullopt;
      left = *left && *right;
    }
    return left;
  }

  std::optional<bool> read_not() {
    if (is_keyword("NOT")) {
      advance();
      std::optional<bool> operand = read_not();
      if (!operand) return std::nullopt;
      return !*operand;
    }
    return read_primary();
  }

  std::optional<bool> read_primary() {
    const CondToken token = token_;
    if (token.kind == Kind::Open) {
      advance();
      std::optional<bool> inner = read_or();
      if (!inner) return std::nullopt;
      if (!expect(Kind::Close, "')'")) return std::nullopt;
      return inner;
    }
    if (token.kind == Kind::Number) {
      advance();
      return token.text.find_first_not_of("0_") != std::string_view::npos;
    }
    if (token.kind != Kind::Name) {
      return fail(token, token.kind == Kind::End ? std::string("condition ends too early")
                                                 : fmt::format("unexpected '{}' in condition", token.text));
    }
    if (names_equal(token.text, "TRUE") || names_equal(token.text, "FALSE")) {
      advance();
      return names_equal(token.text, "TRUE");
    }
    advance();
    if (token_.kind != Kind::Open) {
      return fail(token,
                  fmt::format("'{}' is not a condition; a define is tested with defined({})", token.text, token.text));
    }
    advance();
    if (names_equal(token.text, "defined")) return read_defined();
    if (names_equal(token.text, "hasvalue")) return read_hasvalue();
    if (names_equal(token.text, "hasattribute")) return read_hasattribute();
    if (names_equal(token.text, "hastype")) return read_hastype();
    return fail(token, fmt::format("unknown condition operator '{}': rung reads defined, hasvalue, hasattribute, "
                                   "hastype, NOT, AND, OR",
                                   token.text));
  }

  // defined(NAME) or defined(kind: name)
  std::optional<bool> read_defined() {
    const CondToken first = token_;
    if (!expect(Kind::Name, "a name")) return std::nullopt;
    if (token_.kind != Kind::Colon) {
      if (!expect(Kind::Close, "')'")) return std::nullopt;
      return evaluate_ && defines_.count(upper_name(first.text)) > 0;
    }
    advance();
    std::optional<DeclarationQuestion::Kind> kind = kind_of(first, true);
    if (!kind) return std::nullopt;
    const CondToken name = token_;
    if (!expect(Kind::Name, "a name") || !expect(Kind::Close, "')'")) return std::nullopt;
    return ask({DeclarationQuestion::Ask::Defined, *kind, name.text, {}, at_});
  }

  // hasvalue(NAME, 'value')
  std::optional<bool> read_hasvalue() {
    const CondToken name = token_;
    if (!expect(Kind::Name, "a define name") || !expect(Kind::Comma, "','")) return std::nullopt;
    const CondToken value = token_;
    if (!expect(Kind::String, "a quoted value") || !expect(Kind::Close, "')'")) return std::nullopt;
    if (!evaluate_) return false;
    auto found = defines_.find(upper_name(name.text));
    return found != defines_.end() && found->second == value.text;
  }

  // hasattribute(pou: P, 'attr') or hasattribute(variable: v, 'attr')
  std::optional<bool> read_hasattribute() {
    const CondToken kind_token = token_;
    if (!expect(Kind::Name, "'pou' or 'variable'") || !expect(Kind::Colon, "':'")) return std::nullopt;
    std::optional<DeclarationQuestion::Kind> kind = kind_of(kind_token, false);
    if (!kind) return std::nullopt;
    const CondToken name = token_;
    if (!expect(Kind::Name, "a name") || !expect(Kind::Comma, "','")) return std::nullopt;
    const CondToken attribute = token_;
    if (!expect(Kind::String, "a quoted attribute name") || !expect(Kind::Close, "')'")) return std::nullopt;
    return ask({DeclarationQuestion::Ask::HasAttribute, *kind, name.text, attribute.text, at_});
  }

  // hastype(variable: v, TYPE)
  std::optional<bool> read_hastype() {
    const CondToken kind_token = token_;
    if (!expect(Kind::Name, "'variable'") || !expect(Kind::Colon, "':'")) return std::nullopt;
    if (!names_equal(kind_token.text, "variable")) {
      return fail(kind_token, fmt::format("hastype asks about a variable: hastype(variable: name, TYPE), not '{}'",
                                          kind_token.text));
    }
    const CondToken name = token_;
    if (!expect(Kind::Name, "a variable name") || !expect(Kind::Comma, "','")) return std::nullopt;
    const CondToken type = token_;
    if (!expect(Kind::Name, "a type name") || !expect(Kind::Close, "')'")) return std::nullopt;
    return ask({DeclarationQuestion::Ask::HasType, DeclarationQuestion::Kind::Variable, name.text, type.text, at_});
  }

  std::optional<DeclarationQuestion::Kind> kind_of(const CondToken& token, bool any_kind) {
    using K = DeclarationQuestion::Kind;
    if (names_equal(token.text, "variable")) return K::Variable;
    if (names_equal(token.text, "pou")) return K::Pou;
    if (any_kind) {
      if (names_equal(token.text, "type")) return K::Type;
      if (names_equal(token.text, "task")) return K::Task;
      if (names_equal(token.text, "resource")) return K::Resource;
      fail(token, fmt::format("unknown kind '{}': defined(variable|type|pou|task|resource: name)", token.text));
    } else {
      fail(token, fmt::format("unknown kind '{}': hasattribute(pou|variable: name, 'attribute')", token.text));
    }
    return std::nullopt;
  }

  bool ask(const DeclarationQuestion& question) const { return evaluate_ && oracle_ && oracle_(question); }

  bool is_keyword(std::string_view keyword) const {
    return token_.kind == Kind::Name && names_equal(token_.text, keyword);
  }

  bool expect(Kind kind, std::string_view what) {
    if (token_.kind != kind) {
      fail(token_, token_.kind == Kind::End ? fmt::format("expected {} before the end of the condition", what)
                                            : fmt::format("expected {}, found '{}'", what, token_.text));
      return false;
    }
    advance();
    return true;
  }

  std::optional<bool> fail(const CondToken& token, std::string message) {
    if (!error_) {
      const uint32_t end = token.end > token.begin ? token.end : token.begin;
      error_ = make_diagnostic(codes::kConditionalPragma, std::move(message), {token.begin, end},
                               "conditions combine defined(...), hasvalue(...), hasattribute(...), hastype(...) "
                               "with NOT, AND, OR and parentheses");
    }
    return std::nullopt;
  }

  void advance() {
    while (pos_ < end_ && is_space(text_[pos_])) ++pos_;
    CondToken token;
    token.begin = pos_;
    if (pos_ >= end_) {
      token.kind = Kind::End;
      token.end = pos_;
      token_ = token;
      return;
    }
    const char c = text_[pos_];
    if (is_word_start(c)) {
      // Dotted names are one token: defined(variable: GVL.x), defined(pou: PLC_PRG.Action).
      while (pos_ < end_ &&
             (is_word_char(text_[pos_]) || (text_[pos_] == '.' && pos_ + 1 < end_ && is_word_start(text_[pos_ + 1])))) {
        ++pos_;
      }
      token.kind = Kind::Name;
    } else if (std::isdigit(static_cast<unsigned char>(c))) {
      while (pos_ < end_ && is_word_char(text_[pos_])) ++pos_;
      token.kind = Kind::Number;
    } else if (c == '\'' || c == '"') {
      ++pos_;
      while (pos_ < end_ && text_[pos_] != c) pos_ += text_[pos_] == '$' ? 2 : 1;
      if (pos_ >= end_) {
        token.kind = Kind::Bad;
        pos_ = end_;
        token.end = pos_;
        token.text = text_.substr(token.begin, token.end - token.begin);
        token_ = token;
        return;
      }
      ++pos_;
      token.kind = Kind::String;
      token.end = pos_;
      token.text = text_.substr(token.begin + 1, token.end - token.begin - 2);
      token_ = token;
      return;
    } else {
      ++pos_;
      token.kind = c == '('   ? Kind::Open
                   : c == ')' ? Kind::Close
                   : c == ',' ? Kind::Comma
                   : c == ':' ? Kind::Colon
                              : Kind::Bad;
    }
    token.end = pos_;
    token.text = text_.substr(token.begin, token.end - token.begin);
    token_ = token;
  }

  std::string_view text_;
  uint32_t pos_;
  uint32_t end_;
  uint32_t at_;
  bool evaluate_;
  const std::map<std::string, std::string>& defines_;
  const DeclarationOracle& oracle_;
  CondToken token_;
  std::optional<Diagnostic> error_;
};

// --- Groups -----------------------------------------------------------------------------------

struct Group {
  TextRange if_pragma;
  bool parent_active = true;  // the text around the group is compiled
  bool taken = false;         // a branch of the group has been chosen already
  bool active = false;        // the current branch is compiled
  bool seen_else = false;
};

std::string trim(std::string_view text) {
  size_t begin = 0;
  size_t end = text.size();
  while (begin < end && is_space(text[begin])) ++begin;
  while (end > begin && is_space(text[end - 1])) --end;
  return std::string(text.substr(begin, end - begin));
}

Diagnostic structure_error(std::string message, TextRange range, std::string help) {
  return make_diagnostic(codes::kConditionalPragma, std::move(message), range, std::move(help));
}

class Evaluator {
 public:
  Evaluator(std::string_view text, const Defines& defines, const DeclarationOracle& oracle)
      : text_(text), oracle_(oracle) {
    for (const auto& [name, value] : defines) defines_[upper_name(name)] = value;
    result_.text = std::string(text);
  }

  ConditionalResult run(std::span<const ConditionalPragma> pragmas) {
    uint32_t cursor = 0;
    for (const ConditionalPragma& pragma : pragmas) {
      std::optional<DirectiveText> directive = read_directive(text_, pragma.content);
      if (!directive) continue;  // not a directive after all (should not happen for conditional pragmas)
      if (!active()) blank(cursor, pragma.range.begin);
      cursor = pragma.range.end;
      apply(*directive, pragma);
    }
    if (!active()) blank(cursor, static_cast<uint32_t>(text_.size()));
    for (const Group& group : groups_) {
      result_.diagnostics.push_back(
          structure_error("{IF} without {END_IF}", group.if_pragma, "close the group with {END_IF}"));
    }
    return std::move(result_);
  }

 private:
  bool active() const { return groups_.empty() || groups_.back().active; }

  void apply(const DirectiveText& directive, const ConditionalPragma& pragma) {
    switch (directive.directive) {
      case Directive::If: {
        Group group;
        group.if_pragma = pragma.range;
        group.parent_active = active();
        const bool holds = condition(directive, pragma, group.parent_active);
        group.active = group.parent_active && holds;
        group.taken = holds;
        groups_.push_back(group);
        break;
      }
      case Directive::ElsIf: {
        if (groups_.empty()) return unopened("{ELSIF}", pragma);
        Group& group = groups_.back();
        if (group.seen_else) {
          result_.diagnostics.push_back(
              structure_error("{ELSIF} after {ELSE}", pragma.range, "{ELSE} must be the last branch of a group"));
        }
        const bool evaluate = group.parent_active && !group.taken;
        const bool holds = condition(directive, pragma, evaluate);
        group.active = evaluate && holds;
        group.taken = group.taken || group.active;
        break;
      }
      case Directive::Else: {
        no_text_after(directive, "{ELSE}");
        if (groups_.empty()) return unopened("{ELSE}", pragma);
        Group& group = groups_.back();
        if (group.seen_else) {
          result_.diagnostics.push_back(
              structure_error("second {ELSE} in one group", pragma.range, "a group has at most one {ELSE}"));
        }
        group.seen_else = true;
        group.active = group.parent_active && !group.taken;
        group.taken = true;
        break;
      }
      case Directive::EndIf:
        no_text_after(directive, "{END_IF}");
        if (groups_.empty()) return unopened("{END_IF}", pragma);
        groups_.pop_back();
        break;
      case Directive::Define:
      case Directive::Undefine: define(directive, pragma); break;
    }
  }

  // Conditions are always read (syntax errors count everywhere) but only evaluated where their
  // answer matters: the oracle is not asked about code that is not compiled anyway.
  bool condition(const DirectiveText& directive, const ConditionalPragma& pragma, bool evaluate) {
    ConditionReader reader(text_, directive.rest_begin, pragma.content.end, pragma.range.begin, evaluate, defines_,
                           oracle_);
    std::optional<bool> value = reader.read();
    if (reader.error()) result_.diagnostics.push_back(*reader.error());
    return value.value_or(false);
  }

  void define(const DirectiveText& directive, const ConditionalPragma& pragma) {
    const bool is_define = directive.directive == Directive::Define;
    uint32_t i = directive.rest_begin;
    while (i < pragma.content.end && is_space(text_[i])) ++i;
    const uint32_t name_begin = i;
    while (i < pragma.content.end && is_word_char(text_[i])) ++i;
    if (i == name_begin) {
      result_.diagnostics.push_back(
          structure_error(fmt::format("{{{}}} needs a name", is_define ? "define" : "undefine"), pragma.range,
                          is_define ? "write {define NAME} or {define NAME value}" : "write {undefine NAME}"));
      return;
    }
    if (!active()) return;  // a define in code that is not compiled defines nothing
    const std::string name = upper_name(text_.substr(name_begin, i - name_begin));
    if (!is_define) {
      defines_.erase(name);  // undefining an unknown name is allowed and does nothing
      return;
    }
    std::string value = trim(text_.substr(i, pragma.content.end - i));
    if (value.size() >= 2 && (value.front() == '\'' || value.front() == '"') && value.back() == value.front()) {
      value = value.substr(1, value.size() - 2);
    }
    defines_[name] = std::move(value);
  }

  void unopened(std::string_view what, const ConditionalPragma& pragma) {
    result_.diagnostics.push_back(structure_error(fmt::format("{} without {{IF}}", what), pragma.range,
                                                  "open the group with {IF condition} or remove this pragma"));
  }

  void no_text_after(const DirectiveText& directive, std::string_view what) {
    const std::string rest = trim(directive.rest);
    if (rest.empty()) return;
    const uint32_t begin = directive.rest_begin + static_cast<uint32_t>(directive.rest.find_first_not_of(" \t\r\n"));
    result_.diagnostics.push_back(structure_error(
        fmt::format("unexpected '{}' after {}", rest, what), {begin, begin + static_cast<uint32_t>(rest.size())},
        what == "{ELSE}" ? "a condition belongs to {ELSIF condition}" : "remove the text"));
  }

  void blank(uint32_t from, uint32_t to) {
    if (from >= to) return;
    bool any = false;
    for (uint32_t k = from; k < to; ++k) {
      char& c = result_.text[k];
      if (c == '\n' || c == '\r') continue;
      if (c != ' ' && c != '\t') any = true;
      c = ' ';
    }
    if (any) result_.inactive.push_back({from, to});
  }

  std::string_view text_;
  const DeclarationOracle& oracle_;
  std::map<std::string, std::string> defines_;  // upper-case names
  std::vector<Group> groups_;
  ConditionalResult result_;
};

}  // namespace

std::vector<ConditionalPragma> find_conditional_pragmas(const SyntaxTree& tree) {
  std::vector<ConditionalPragma> out;
  if (!tree.root()) return out;
  std::vector<SyntaxNode> stack{tree.root()};
  while (!stack.empty()) {
    SyntaxNode node = stack.back();
    stack.pop_back();
    if (node.kind() == "pragma") {
      if (SyntaxNode content = node.first_child_of_kind("conditional_pragma"))
        out.push_back({node.range(), content.range()});
      continue;
    }
    for (uint32_t i = node.child_count(); i-- > 0;) stack.push_back(node.child(i));
  }
  return out;
}

ConditionalResult evaluate_conditionals(std::string_view text, std::span<const ConditionalPragma> pragmas,
                                        const Defines& defines, const DeclarationOracle& oracle) {
  return Evaluator(text, defines, oracle).run(pragmas);
}

ConditionalResult apply_conditional_compilation(std::string_view text, const Defines& defines,
                                                const DeclarationOracle& oracle) {
  if (!may_have_conditional_pragmas(text)) return {std::string(text), {}, {}};
  const SyntaxTree tree = SyntaxTree::parse(std::string(text));
  return evaluate_conditionals(text, find_conditional_pragmas(tree), defines, oracle);
}

std::vector<Diagnostic> check_conditional_pragmas(std::string_view text, std::span<const ConditionalPragma> pragmas) {
  if (pragmas.empty()) return {};
  return evaluate_conditionals(text, pragmas, {}, {}).diagnostics;
}

bool may_have_conditional_pragmas(std::string_view text) {
  for (size_t at = text.find('{'); at != std::string_view::npos; at = text.find('{', at + 1)) {
    size_t i = at + 1;
    while (i < text.size() && is_space(text[i])) ++i;
    size_t end = i;
    while (end < text.size() && is_word_char(text[end])) ++end;
    const std::string_view word = text.substr(i, end - i);
    for (std::string_view directive : {"IF", "ELSIF", "ELSE", "END_IF", "DEFINE", "UNDEFINE"}) {
      if (names_equal(word, directive)) return true;
    }
  }
  return false;
}

}  // namespace rung::project
