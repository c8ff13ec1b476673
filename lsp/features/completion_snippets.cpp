#include "lsp/features/completion_snippets.hpp"

#include <algorithm>
#include <array>

#include "checker/query/source_edits.hpp"

namespace rung::lsp {
namespace {

struct Skeleton {
  std::string_view name;
  std::string_view label;
  std::string_view detail;
  // LSP snippet syntax: ${1:name} placeholders, $0 the final cursor, \t one indentation step.
  // Upper-case words are keywords (written in the project's case); INT and BOOL are types.
  std::string_view body;
};

constexpr auto kSkeletons = std::to_array<Skeleton>({
    {"IF", "IF", "IF … THEN … END_IF", "IF ${1:condition} THEN\n\t$0\nEND_IF"},
    {"CASE", "CASE", "CASE … OF … END_CASE", "CASE ${1:selector} OF\n\t${2:value}:\n\t\t$0\nELSE\n\t\nEND_CASE"},
    {"FOR", "FOR", "FOR … TO … DO … END_FOR", "FOR ${1:i} := ${2:1} TO ${3:10} DO\n\t$0\nEND_FOR"},
    {"WHILE", "WHILE", "WHILE … DO … END_WHILE", "WHILE ${1:condition} DO\n\t$0\nEND_WHILE"},
    {"REPEAT", "REPEAT", "REPEAT … UNTIL … END_REPEAT", "REPEAT\n\t$0\nUNTIL ${1:condition}\nEND_REPEAT"},
    {"PROGRAM", "PROGRAM", "PROGRAM … END_PROGRAM", "PROGRAM ${1:Name}\nVAR\n\t$2\nEND_VAR\n$0\nEND_PROGRAM"},
    {"FUNCTION_BLOCK", "FUNCTION_BLOCK", "FUNCTION_BLOCK … END_FUNCTION_BLOCK",
     "FUNCTION_BLOCK ${1:Name}\nVAR_INPUT\n\t$2\nEND_VAR\nVAR_OUTPUT\n\t$3\nEND_VAR\nVAR\n\t$4\nEND_VAR\n$0\n"
     "END_FUNCTION_BLOCK"},
    {"FUNCTION", "FUNCTION", "FUNCTION … : … END_FUNCTION",
     "FUNCTION ${1:Name} : ${2:INT}\nVAR_INPUT\n\t$3\nEND_VAR\n$0\nEND_FUNCTION"},
    {"INTERFACE", "INTERFACE", "INTERFACE … END_INTERFACE", "INTERFACE ${1:Name}\n$0\nEND_INTERFACE"},
    {"METHOD", "METHOD", "METHOD … : … END_METHOD",
     "METHOD ${1:Name} : ${2:BOOL}\nVAR_INPUT\n\t$3\nEND_VAR\n$0\nEND_METHOD"},
    {"PROPERTY", "PROPERTY", "PROPERTY … : … GET … SET … END_PROPERTY",
     "PROPERTY ${1:Name} : ${2:INT}\nGET\n\t$0\nEND_GET\nSET\n\t\nEND_SET\nEND_PROPERTY"},
    {"STRUCT", "TYPE STRUCT", "TYPE … : STRUCT … END_STRUCT END_TYPE",
     "TYPE ${1:ST_Name} :\nSTRUCT\n\t$0\nEND_STRUCT\nEND_TYPE"},
    {"ENUM", "TYPE ENUM", "TYPE … : ( … ); END_TYPE", "TYPE ${1:E_Name} :\n(\n\t${2:First} := 0,\n\t${3:Second}\n);\nEND_TYPE"},
    {"VAR", "VAR", "VAR … END_VAR", "VAR\n\t$0\nEND_VAR"},
    {"VAR_INPUT", "VAR_INPUT", "VAR_INPUT … END_VAR", "VAR_INPUT\n\t$0\nEND_VAR"},
    {"VAR_OUTPUT", "VAR_OUTPUT", "VAR_OUTPUT … END_VAR", "VAR_OUTPUT\n\t$0\nEND_VAR"},
    {"VAR_IN_OUT", "VAR_IN_OUT", "VAR_IN_OUT … END_VAR", "VAR_IN_OUT\n\t$0\nEND_VAR"},
    {"VAR_TEMP", "VAR_TEMP", "VAR_TEMP … END_VAR", "VAR_TEMP\n\t$0\nEND_VAR"},
    {"VAR_STAT", "VAR_STAT", "VAR_STAT … END_VAR", "VAR_STAT\n\t$0\nEND_VAR"},
    {"VAR_INST", "VAR_INST", "VAR_INST … END_VAR", "VAR_INST\n\t$0\nEND_VAR"},
    {"VAR_EXTERNAL", "VAR_EXTERNAL", "VAR_EXTERNAL … END_VAR", "VAR_EXTERNAL\n\t$0\nEND_VAR"},
    {"VAR_GLOBAL", "VAR_GLOBAL", "VAR_GLOBAL … END_VAR", "VAR_GLOBAL\n\t$0\nEND_VAR"},
    {"VAR_CONFIG", "VAR_CONFIG", "VAR_CONFIG … END_VAR", "VAR_CONFIG\n\t$0\nEND_VAR"},
    {"VAR_ACCESS", "VAR_ACCESS", "VAR_ACCESS … END_VAR", "VAR_ACCESS\n\t$0\nEND_VAR"},
});

bool is_upper_word_char(char c) { return (c >= 'A' && c <= 'Z') || c == '_'; }
bool is_word_char(char c) { return is_upper_word_char(c) || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9'); }

// Writes `body` out: keywords in case, \t as the project's indentation, and without snippet
// syntax for clients that take plain text only (a placeholder keeps its default text).
std::string render(std::string_view body, const project::FormatSettings& settings, std::string_view typed,
                   bool snippet_support) {
  const std::string indent = check::query::indent_unit(settings);
  std::string out;
  for (size_t i = 0; i < body.size();) {
    const char c = body[i];
    if (is_word_char(c)) {
      size_t end = i;
      while (end < body.size() && is_word_char(body[end])) ++end;
      const std::string_view word = body.substr(i, end - i);
      const bool keyword = word.size() > 1 && std::all_of(word.begin(), word.end(), is_upper_word_char);
      out += keyword ? keyword_in_case(word, settings, typed, word == "INT" || word == "BOOL") : std::string(word);
      i = end;
    } else if (c == '\t') {
      out += indent;
      ++i;
    } else if (c == '$' && !snippet_support) {
      // ${1:text} -> text, $0 -> nothing
      if (i + 1 < body.size() && body[i + 1] == '{') {
        const size_t colon = body.find(':', i);
        const size_t close = body.find('}', i);
        out += body.substr(colon + 1, close - colon - 1);
        i = close + 1;
      } else {
        i += 2;
      }
    } else {
      out += c;
      ++i;
    }
  }
  return out;
}

}  // namespace

std::string keyword_in_case(std::string_view keyword, const project::FormatSettings& settings, std::string_view typed,
                            bool elementary_type) {
  if (elementary_type && !settings.elementary_types_follow_keyword_case) return std::string(keyword);
  return check::query::keyword_in_case(keyword, settings, typed);
}

Snippet snippet(std::string_view name, const project::FormatSettings& settings, std::string_view typed,
                bool snippet_support) {
  for (const Skeleton& skeleton : kSkeletons) {
    if (skeleton.name != name) continue;
    return Snippet{.label = keyword_in_case(skeleton.label, settings, typed),
                   .detail = std::string(skeleton.detail),
                   .text = render(skeleton.body, settings, typed, snippet_support)};
  }
  return {};
}

}  // namespace rung::lsp
