#include "checker/semantic/pragma_checker.hpp"

#include <fmt/format.h>

#include <array>
#include <cctype>

#include "checker/project/conditional_compilation.hpp"
#include "parser/diagnostic_codes.hpp"

namespace rung::check {
namespace {

bool is_word_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}

// First words of the pragmas the CODESYS manuals describe besides attributes, messages, conditional
// compilation and regions (which the grammar classifies itself): {include <file>} (002 L13094),
// {bitaccess <constant> <bit> '<comment>'} in a STRUCT (002 L18181), the CODESYS V2.3 pragmas
// {flag ...}, {parameter ...}, {library ...}, and {messageguid ...} of CODESYS exports. From the
// CODESYS V3 and TwinCAT 3 online help: {noflow} and {flow} switch flow control off and on again
// for the code between them, and {analysis -n} / {analysis +n} switch rule n of the static analysis
// off and on. rung has nothing to check for them, but they are not unknown either.
constexpr std::array<std::string_view, 9> kOtherKnownPragmas = {
    "include", "bitaccess", "flag", "parameter", "library", "messageguid", "flow", "noflow", "analysis"};
// What a misspelled pragma word is compared with for "did you mean".
constexpr std::array<std::string_view, 12> kSuggestedWords = {"attribute", "warning", "error",     "info",
                                                              "text",      "define",  "undefine",  "region",
                                                              "endregion", "include", "bitaccess", "library"};

std::string_view first_word(std::string_view content) {
  size_t end = 0;
  while (end < content.size() && is_word_char(content[end])) ++end;
  return content.substr(0, end);
}

// The user's text of a message pragma: the quoted string after the word (and after the warning
// level digit of {warning 1 'text'}), or the rest of the pragma when it has no quotes.
std::string message_text(std::string_view content, std::string_view word) {
  std::string_view rest = content.substr(word.size());
  const size_t quote = rest.find_first_of("'\"");
  if (quote != std::string_view::npos) {
    const size_t close = rest.find(rest[quote], quote + 1);
    if (close != std::string_view::npos) return std::string(rest.substr(quote + 1, close - quote - 1));
    return std::string(rest.substr(quote + 1));
  }
  const size_t begin = rest.find_first_not_of(" \t0123456789");
  if (begin == std::string_view::npos) return {};
  const size_t end = rest.find_last_not_of(" \t\r\n");
  return std::string(rest.substr(begin, end - begin + 1));
}

// {warning disable C0371} and {warning restore C0371} (CODESYS V3, TwinCAT 3): they turn a
// compiler warning off and back on for the code between them; they are no message. `rest` is the
// pragma after its word "warning".
bool is_warning_switch(std::string_view rest) {
  const size_t begin = rest.find_first_not_of(" \t\r\n");
  if (begin == std::string_view::npos) return false;
  const std::string_view action = first_word(rest.substr(begin));
  return names_equal(action, "disable") || names_equal(action, "restore");
}

class PragmaChecker {
 public:
  explicit PragmaChecker(std::vector<Diagnostic>& out) : out_(out) {}

  void run(const SyntaxTree& tree) {
    std::vector<project::ConditionalPragma> conditional;
    for_each_pragma(tree.root(), [&](SyntaxNode pragma) { visit(pragma, conditional); });
    // Conditional pragmas stay in the text even inside inactive branches, so the structure of
    // every group can be checked here; their conditions were evaluated when the file was loaded.
    for (Diagnostic& diagnostic : project::check_conditional_pragmas(tree.text(), conditional)) {
      out_.push_back(std::move(diagnostic));
    }
  }

 private:
  void visit(SyntaxNode pragma, std::vector<project::ConditionalPragma>& conditional) {
    SyntaxNode content;
    for (uint32_t i = 0; i < pragma.named_child_count() && !content; ++i) content = pragma.named_child(i);
    if (!content) return;
    const std::string_view kind = content.kind();
    if (kind == "conditional_pragma") {
      conditional.push_back({pragma.range(), content.range()});
    } else if (kind == "message_pragma") {
      message(pragma, content.text());
    } else if (kind == "generic_pragma") {
      generic(pragma, content.text());
    }
    // attribute_pragma: any name is legal, the user's own attributes included (they are read by
    // hasattribute and by tools); region_pragma: folding only.
  }

  void message(SyntaxNode pragma, std::string_view content) {
    const std::string_view word = first_word(content);
    if (names_equal(word, "warning") && is_warning_switch(content.substr(word.size()))) return;
    std::string text = message_text(content, word);
    if (names_equal(word, "warning")) {
      out_.push_back(make_diagnostic(codes::kPragmaWarning, text.empty() ? "{warning} pragma" : std::move(text),
                                     pragma.range(), "the source asks for this warning; remove the pragma when done"));
    } else if (names_equal(word, "error")) {
      out_.push_back(make_diagnostic(codes::kPragmaError, text.empty() ? "{error} pragma" : std::move(text),
                                     pragma.range(), "the source forbids building this code as it stands"));
    } else if (names_equal(word, "info") || names_equal(word, "text")) {
      // CODESYS prints both in the message window when it compiles (002 L11966-11987): {info} as
      // an information that jumps to the source, {text} as plain text without a position. rung
      // reports both as information (E605), not as a problem: they never fail a check, and the
      // position is where an editor shows them.
      out_.push_back(make_diagnostic(
          codes::kPragmaInfo, text.empty() ? fmt::format("{{{}}} pragma", word) : std::move(text), pragma.range()));
    } else {
      unknown(pragma, content);  // the grammar also reads {message ...}, which no manual of ours describes
    }
  }

  void generic(SyntaxNode pragma, std::string_view content) {
    // Beremiz/MATIEC embed C code as {{ ... }}: the content starts with the inner brace.
    if (content.starts_with("{")) return;
    const std::string_view word = first_word(content);
    for (std::string_view known : kOtherKnownPragmas) {
      if (!word.empty() && names_equal(word, known)) return;
    }
    unknown(pragma, content);
  }

  void unknown(SyntaxNode pragma, std::string_view content) {
    const std::string_view word = first_word(content);
    std::string shown(pragma.text().substr(0, 60));
    if (pragma.text().size() > 60) shown += "...";
    std::string help =
        "rung reads {attribute ...}, {warning/error/info/text '...'}, {warning disable/restore ...}, "
        "{IF}/{ELSIF}/{ELSE}/{END_IF}, {define}/{undefine}, {region}, {flow}/{noflow} and {analysis ...}; "
        "like CODESYS it ignores other pragmas";
    if (!word.empty()) {
      const std::string_view close = closest_name(word, kSuggestedWords);
      if (!close.empty()) help = fmt::format("did you mean {{{} ...}}?", close);
    }
    out_.push_back(make_diagnostic(codes::kUnknownPragma, fmt::format("unknown pragma {} is ignored", shown),
                                   pragma.range(), std::move(help)));
  }

  std::vector<Diagnostic>& out_;
};

// The obsolete declaration a declared type is made of, looking through ARRAY OF, POINTER TO and
// REFERENCE TO; nullptr when there is none.
const Symbol* obsolete_part(const Type* type) {
  for (int depth = 0; type && depth < 16; ++depth) {
    type = underlying(type);
    if (type->declaration && type->declaration->has(kObsolete)) return type->declaration;
    if (type->kind != TypeKind::Array && type->kind != TypeKind::Pointer && type->kind != TypeKind::Reference) break;
    type = type->element;
  }
  return nullptr;
}

bool declared_inside(const Symbol& symbol, const Symbol* scope) {
  for (const Symbol* s = symbol.owner; s; s = s->owner) {
    if (s == scope) return true;
  }
  return false;
}

std::string_view last_segment(std::string_view name) {
  const size_t dot = name.rfind('.');
  return dot == std::string_view::npos ? name : name.substr(dot + 1);
}

// CODESYS warns wherever an obsolete type is used, declarations included (002 L12791-12807:
// `fbinst : fb1` with fb1 marked obsolete). Uses in bodies are reported when they are typed.
void check_obsolete_types(const Source& file, std::vector<Diagnostic>& out) {
  for (const Symbol& symbol : file.symbols.storage) {
    if (symbol.kind == SymbolKind::Variable || (is_pou_kind(symbol.kind) && symbol.result_type)) {
      const Symbol* obsolete = obsolete_part(symbol.kind == SymbolKind::Variable ? symbol.type : symbol.result_type);
      if (obsolete && symbol.type_node && !declared_inside(symbol, obsolete)) {
        out.push_back(obsolete_use(*obsolete, symbol.type_node.range()));
      }
    }
    for (const Symbol* base : symbol.bases) {
      if (!base->has(kObsolete)) continue;
      for (SyntaxNode written : symbol.base_nodes) {
        if (names_equal(last_segment(written.text()), base->name)) out.push_back(obsolete_use(*base, written.range()));
      }
    }
  }
}

}  // namespace

Diagnostic obsolete_use(const Symbol& obsolete, TextRange where) {
  const Attribute* attribute = obsolete.attribute("obsolete");
  return make_diagnostic(codes::kObsolete,
                         fmt::format("'{}' is obsolete{}", obsolete.name,
                                     attribute && !attribute->value.empty() ? ": " + attribute->value : std::string()),
                         where);
}

void check_pragmas(const ProjectModel& model, SourceId source, std::vector<Diagnostic>& out) {
  const Source& file = model.source(source);
  if (file.library || !file.document->tree()) return;
  PragmaChecker(out).run(*file.document->tree());
  check_obsolete_types(file, out);
}

}  // namespace rung::check
