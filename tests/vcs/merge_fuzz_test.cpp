// The three-way merge on random edits of real files (issue 17): the repository's examples and
// container test files and ST seeds of the shared corpus, each edited at random on both sides
// (statements, initial values, types, variables and POUs or methods added and removed, renames,
// the same line on both sides), merged by vcs::merge_file and checked by check_merge
// (merge_properties.hpp): no side's change lost silently, no unreadable file; and where both
// sides changed one line differently, a reported conflict. The edits are deterministic
// (std::mt19937, a seed per file and round); a failing case is written to a temporary folder
// with its seed, to merge again with `rung merge-file`. The MergeProperties tests show the
// checker catching what a broken merge would return.
//
// RUNG_MERGE_FUZZ_ROUNDS=N multiplies the rounds per file for a longer run by hand.
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <iostream>
#include <optional>
#include <random>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "parser/containers/detect.hpp"
#include "tests/support/test_paths.hpp"
#include "tests/vcs/merge_properties.hpp"

namespace rung::test {
namespace {

namespace fs = std::filesystem;
using containers::ContainerKind;

std::string upper(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

std::string_view trimmed(std::string_view text) {
  const size_t first = text.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  const size_t last = text.find_last_not_of(" \t\r");
  return text.substr(first, last - first + 1);
}

bool is_identifier_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_';
}

// "VAR", "VAR_INPUT", "VAR_GLOBAL CONSTANT", "STRUCT": a line after which declarations go.
bool is_block_header(std::string_view code) {
  const std::string u = upper(trimmed(code));
  if (u == "STRUCT") return true;
  if (u.rfind("VAR", 0) != 0) return false;
  for (const char c : u) {
    if (!is_identifier_char(c) && c != ' ' && c != '\t') return false;  // "VAR_INPUT x : INT;" is not one
  }
  return true;
}

// One line of a file, with where the ST code on it is: the whole line for ST and .EXP files;
// for XML the part inside a CDATA section or the text of an <xhtml> element.
struct Line {
  size_t begin = 0;  // of the line
  size_t end = 0;    // before its line end
  size_t next = 0;   // the next line's begin
  size_t code_begin = 0;
  size_t code_end = 0;  // code_begin == code_end: no code
  bool whole = false;   // the whole line is code
  bool in_block = false;
  bool block_header = false;
};

// A change of base bytes [begin, end) to `text`, at base line `line`.
struct Replacement {
  size_t begin = 0;
  size_t end = 0;
  std::string text;
  size_t line = 0;
};

// A file as lines, each knowing where its ST code is and whether it declares (the edits go by
// lines: a line merge is what they must survive).
class SourceModel {
 public:
  SourceModel(std::string path, std::string text) : path_(std::move(path)), text_(std::move(text)) {
    kind_ = containers::detect_container(path_, text_);
    const size_t nl = text_.find('\n');
    eol_ = nl != std::string::npos && nl > 0 && text_[nl - 1] == '\r' ? "\r\n" : "\n";
    std::vector<bool> code(text_.size(), !is_xml());
    if (is_xml()) mark_xml_code(code);
    bool in_block = false;
    for (size_t at = 0; at < text_.size();) {
      Line line;
      line.begin = at;
      const size_t nl_at = text_.find('\n', at);
      line.next = nl_at == std::string::npos ? text_.size() : nl_at + 1;
      line.end = nl_at == std::string::npos ? text_.size() : nl_at;
      if (line.end > line.begin && text_[line.end - 1] == '\r') --line.end;
      // The longest run of code on the line.
      for (size_t i = line.begin; i < line.end;) {
        if (!code[i]) {
          ++i;
          continue;
        }
        size_t j = i;
        while (j < line.end && code[j]) ++j;
        if (j - i > line.code_end - line.code_begin) {
          line.code_begin = i;
          line.code_end = j;
        }
        i = j;
      }
      line.whole = line.code_begin == line.begin && line.code_end == line.end && line.end > line.begin;
      const std::string u = upper(trimmed(code_of(line)));
      if (kind_ == ContainerKind::PlcOpen) {
        // PLCopen declares variables as XML elements; its ST is only in bodies.
      } else if (is_block_header(code_of(line))) {
        line.block_header = true;
        in_block = true;
      } else if (u.rfind("END_VAR", 0) == 0 || u.rfind("END_STRUCT", 0) == 0) {
        in_block = false;
      } else {
        line.in_block = in_block;
      }
      lines_.push_back(line);
      at = line.next;
    }
  }

  const std::string& path() const { return path_; }
  const std::string& text() const { return text_; }
  ContainerKind kind() const { return kind_; }
  const std::vector<Line>& lines() const { return lines_; }
  bool is_xml() const { return kind_ == ContainerKind::TwinCat || kind_ == ContainerKind::PlcOpen; }
  std::string_view code_of(const Line& line) const {
    return std::string_view(text_).substr(line.code_begin, line.code_end - line.code_begin);
  }
  std::string_view line_text(const Line& line) const {
    return std::string_view(text_).substr(line.begin, line.end - line.begin);
  }
  const std::string& eol() const { return eol_; }
  bool parses() const {
    if (!parses_) parses_ = parses_cleanly(path_, text_);
    return *parses_;
  }

 private:
  void mark_xml_code(std::vector<bool>& code) const {
    for (size_t at = text_.find("<![CDATA["); at != std::string::npos; at = text_.find("<![CDATA[", at)) {
      const size_t begin = at + 9;
      const size_t end = std::min(text_.find("]]>", begin), text_.size());
      std::fill(code.begin() + static_cast<std::ptrdiff_t>(begin), code.begin() + static_cast<std::ptrdiff_t>(end),
                true);
      at = end;
    }
    // CODESYS writes bodies as escaped text of <xhtml xmlns="...">.
    for (size_t at = text_.find("<xhtml"); at != std::string::npos; at = text_.find("<xhtml", at + 1)) {
      const size_t tag_end = text_.find('>', at);
      if (tag_end == std::string::npos || text_[tag_end - 1] == '/') continue;
      const size_t end = std::min(text_.find('<', tag_end), text_.size());
      std::fill(code.begin() + static_cast<std::ptrdiff_t>(tag_end + 1),
                code.begin() + static_cast<std::ptrdiff_t>(end), true);
    }
  }

  std::string path_;
  std::string text_;
  ContainerKind kind_ = ContainerKind::None;
  std::string eol_;
  std::vector<Line> lines_;
  mutable std::optional<bool> parses_;  // parses_cleanly, asked once per file
};

std::string applied(const std::string& text, std::vector<Replacement> replacements) {
  std::sort(replacements.begin(), replacements.end(), [](const Replacement& a, const Replacement& b) {
    return std::tie(b.begin, b.end) < std::tie(a.begin, a.end);
  });
  std::string out = text;
  for (const Replacement& r : replacements) out.replace(r.begin, r.end - r.begin, r.text);
  return out;
}

// Renames the identifier `from` (any case, as ST does) in the code of a file, and in PLCopen
// the name="..." attributes that declare it.
std::string renamed(const SourceModel& file, const std::string& text, const std::string& from, const std::string& to) {
  const SourceModel model(file.path(), text);
  std::vector<Replacement> replacements;
  const std::string from_upper = upper(from);
  for (const Line& line : model.lines()) {
    const std::string_view code = model.code_of(line);
    for (size_t i = 0; i + from.size() <= code.size(); ++i) {
      if (upper(code.substr(i, from.size())) != from_upper) continue;
      if ((i > 0 && is_identifier_char(code[i - 1])) ||
          (i + from.size() < code.size() && is_identifier_char(code[i + from.size()]))) {
        continue;
      }
      replacements.push_back({line.code_begin + i, line.code_begin + i + from.size(), to, 0});
      i += from.size() - 1;
    }
  }
  if (file.kind() == ContainerKind::PlcOpen) {
    const std::string attribute = fmt::format("name=\"{}\"", from);
    for (size_t at = text.find(attribute); at != std::string::npos; at = text.find(attribute, at + 1)) {
      replacements.push_back({at, at + attribute.size(), fmt::format("name=\"{}\"", to), 0});
    }
  }
  return applied(text, replacements);
}

// Random edits of one file, each kept only when the file still parses afterwards (when the
// base does), so a merge of them has no excuse to produce code that does not.
class Editor {
 public:
  Editor(const SourceModel& file, std::mt19937& random) : file_(file), random_(random) {
    base_parses_ = file_.parses();
  }

  enum class Op { Statement, Value, Type, AddVariable, RemoveVariable, AddPou, RemovePou };

  // An edit of kind `op` away from the lines in `avoid` (and their neighbours), or none.
  std::optional<Replacement> edit(Op op, const std::set<size_t>& avoid, int n) {
    std::vector<size_t> candidates;
    for (size_t i = 0; i < file_.lines().size(); ++i) {
      if (near(avoid, i)) continue;
      if (fits(op, file_.lines()[i])) candidates.push_back(i);
    }
    if (op == Op::AddPou && candidates.empty() && !near(avoid, file_.lines().size()) && !file_.is_xml()) {
      candidates.push_back(file_.lines().size());  // at the end of the file
    }
    std::shuffle(candidates.begin(), candidates.end(), random_);
    for (size_t tries = 0; tries < candidates.size() && tries < 4; ++tries) {
      std::optional<Replacement> r = make(op, candidates[tries], n);
      if (!r) continue;
      const std::vector<size_t> touched = lines_of(*r);
      if (std::any_of(touched.begin(), touched.end(), [&](size_t line) { return near(avoid, line); })) continue;
      if (base_parses_ && !parses_cleanly(file_.path(), applied(file_.text(), {*r}))) continue;
      return r;
    }
    return std::nullopt;
  }

  // The lines a replacement changes (a removal spans several).
  std::vector<size_t> lines_of(const Replacement& r) const {
    std::vector<size_t> out{r.line};
    for (size_t i = 0; i < file_.lines().size(); ++i) {
      const Line& line = file_.lines()[i];
      if (i != r.line && line.begin < r.end && line.next > r.begin) out.push_back(i);
    }
    return out;
  }

  // A name declared in the file (a variable or a POU), for a rename.
  std::optional<std::string> declared_name() {
    std::vector<std::string> names;
    for (const Line& line : file_.lines()) {
      const std::string_view code = trimmed(file_.code_of(line));
      if (line.in_block && !line.block_header) {
        size_t end = 0;
        while (end < code.size() && is_identifier_char(code[end])) ++end;
        if (end > 0 && std::isdigit(static_cast<unsigned char>(code[0])) == 0) names.emplace_back(code.substr(0, end));
      }
      for (const std::string_view keyword : {"FUNCTION_BLOCK ", "PROGRAM ", "FUNCTION ", "METHOD "}) {
        if (upper(code).rfind(keyword, 0) != 0) continue;
        std::string_view rest = trimmed(code.substr(keyword.size()));
        size_t end = 0;
        while (end < rest.size() && is_identifier_char(rest[end])) ++end;
        if (end > 0) names.emplace_back(rest.substr(0, end));
      }
      if (file_.kind() == ContainerKind::PlcOpen) {
        const std::string_view text = trimmed(file_.line_text(line));
        if (text.rfind("<variable name=\"", 0) == 0) {
          const size_t end = text.find('"', 16);
          if (end != std::string_view::npos) names.emplace_back(text.substr(16, end - 16));
        }
      }
    }
    if (names.empty()) return std::nullopt;
    return names[std::uniform_int_distribution<size_t>(0, names.size() - 1)(random_)];
  }

 private:
  static bool near(const std::set<size_t>& avoid, size_t line) {
    for (const size_t a : avoid) {
      if (line + 2 >= a && line <= a + 2) return true;
    }
    return false;
  }

  bool fits(Op op, const Line& line) const {
    const std::string_view code = trimmed(file_.code_of(line));
    const std::string_view text = trimmed(file_.line_text(line));
    const bool plcopen = file_.kind() == ContainerKind::PlcOpen;
    switch (op) {
      case Op::Statement:
        return !line.in_block && !code.empty() && code.back() == ';' && code.find(":=") != std::string_view::npos;
      case Op::Value:
        if (plcopen) return text.find("<simpleValue value=\"") != std::string_view::npos;
        return line.in_block && !code.empty() && code.back() == ';' && code.find(':') != std::string_view::npos;
      case Op::Type:
        if (plcopen) return is_plcopen_type(text);
        return line.in_block && type_at(code) != std::string_view::npos;
      case Op::AddVariable:
        if (plcopen) return text.size() > 1 && text.substr(text.size() - 2) != "/>" && is_plcopen_var_list(text);
        return line.block_header && line.next > line.end;
      case Op::RemoveVariable:
        if (plcopen) return text.rfind("<variable name=\"", 0) == 0;
        return line.in_block && line.whole && !code.empty() && code.back() == ';' &&
               code.find(':') != std::string_view::npos;
      case Op::RemovePou: return removed_object_end(line) != 0;
      case Op::AddPou:
        switch (file_.kind()) {
          case ContainerKind::TwinCat: return text.rfind("<LineIds", 0) == 0 || text == "</POU>" || text == "</Itf>";
          case ContainerKind::PlcOpen: return text == "<pous>";
          case ContainerKind::CodesysExp: return text.rfind("(* @NESTEDCOMMENTS", 0) == 0;
          default: {
            const std::string u = upper(code);
            return line.whole && !line.in_block &&
                   (u == "END_FUNCTION_BLOCK" || u.rfind("FUNCTION_BLOCK ", 0) == 0 || u.rfind("PROGRAM ", 0) == 0 ||
                    u.rfind("FUNCTION ", 0) == 0);
          }
        }
    }
    return false;
  }

  // The last line of the object (POU, method, action; .EXP export object) that starts on
  // `line`, or 0 when none does.
  size_t removed_object_end(const Line& line) const {
    const std::vector<Line>& lines = file_.lines();
    const size_t first = static_cast<size_t>(&line - lines.data());
    const std::string_view text = trimmed(file_.line_text(line));
    std::function<bool(std::string_view)> is_end;
    switch (file_.kind()) {
      case ContainerKind::TwinCat:
        if (text.rfind("<Method ", 0) == 0 || text.rfind("<Action ", 0) == 0) {
          const std::string close = text.rfind("<Method ", 0) == 0 ? "</Method>" : "</Action>";
          is_end = [close](std::string_view t) { return t == close; };
        }
        break;
      case ContainerKind::PlcOpen:
        if (text.rfind("<pou ", 0) == 0) is_end = [](std::string_view t) { return t == "</pou>"; };
        break;
      case ContainerKind::CodesysExp:
        // To the line before the next object's markers, or the end of the file.
        if (text.rfind("(* @NESTEDCOMMENTS", 0) != 0) return 0;
        for (size_t i = first + 1; i < lines.size(); ++i) {
          if (trimmed(file_.line_text(lines[i])).rfind("(* @NESTEDCOMMENTS", 0) == 0) return i - 1;
        }
        return lines.size() - 1;
      default: {
        const std::string u = upper(trimmed(file_.code_of(line)));
        if (!line.whole || line.in_block) return 0;
        for (const char* keyword : {"FUNCTION_BLOCK", "FUNCTION", "PROGRAM", "METHOD", "ACTION"}) {
          if (u.rfind(std::string(keyword) + " ", 0) != 0) continue;
          const std::string end = std::string("END_") + keyword;
          is_end = [end](std::string_view t) {
            const std::string v = upper(t);
            return v == end || v == end + ";";
          };
          break;
        }
      }
    }
    if (!is_end) return 0;
    for (size_t i = first + 1; i < lines.size(); ++i) {
      if (is_end(trimmed(file_.is_xml() ? file_.line_text(lines[i]) : file_.code_of(lines[i])))) return i;
    }
    return 0;
  }

  // "<INT />", "<derived name="T" />": a PLCopen variable's type, on a line of its own.
  static bool is_plcopen_type(std::string_view text) {
    if (text.rfind("<derived name=", 0) == 0) return text.substr(text.size() - 2) == "/>";
    if (text.size() < 4 || text[0] != '<' || text.substr(text.size() - 2) != "/>") return false;
    const std::string_view tag = trimmed(text.substr(1, text.size() - 3));
    return !tag.empty() && std::all_of(tag.begin(), tag.end(), [](char c) {
      return std::isupper(static_cast<unsigned char>(c)) != 0 || std::isdigit(static_cast<unsigned char>(c)) != 0 ||
             c == '_';
    });
  }

  // Where the type name of a declaration "x : INT ..." starts in `code`, or npos.
  static size_t type_at(std::string_view code) {
    const size_t colon = code.find(':');
    if (colon == std::string_view::npos || code.substr(colon, 2) == ":=") return std::string_view::npos;
    const size_t at = code.find_first_not_of(" \t", colon + 1);
    if (at == std::string_view::npos || std::isalpha(static_cast<unsigned char>(code[at])) == 0) {
      return std::string_view::npos;
    }
    return at;
  }

  static bool is_plcopen_var_list(std::string_view text) {
    for (const std::string_view tag :
         {"<inputVars", "<outputVars", "<inOutVars", "<localVars", "<tempVars", "<externalVars", "<globalVars"}) {
      if (text.rfind(tag, 0) == 0) return true;
    }
    return false;
  }

  std::string indent_of(const Line& line) const {
    const std::string_view text = file_.line_text(line);
    return std::string(text.substr(0, text.find_first_not_of(" \t")));
  }

  std::optional<Replacement> make(Op op, size_t index, int n) const {
    const std::string& eol = file_.eol();
    if (index == file_.lines().size()) {  // a FUNCTION at the end of an ST file
      std::string text = file_.text().empty() || file_.text().back() == '\n' ? "" : eol;
      text += fmt::format("{0}FUNCTION F_Fuzz{1} : INT{0}F_Fuzz{1} := {1};{0}END_FUNCTION{0}", eol, n);
      return Replacement{file_.text().size(), file_.text().size(), text, index};
    }
    const Line& line = file_.lines()[index];
    const std::string_view code = file_.code_of(line);
    const std::string indent = indent_of(line);
    // Before the last ';' of the code on the line.
    const size_t semicolon = line.code_begin + code.rfind(';');
    switch (op) {
      case Op::Statement: return Replacement{semicolon, semicolon, fmt::format(" + {}", n), index};
      case Op::Value:
        if (file_.kind() == ContainerKind::PlcOpen) {
          const size_t at = file_.text().find("<simpleValue value=\"", line.begin) + 20;
          const size_t end = file_.text().find('"', at);
          return Replacement{at, end, std::to_string(n), index};
        }
        return Replacement{
            semicolon, semicolon,
            code.find(":=") != std::string_view::npos ? fmt::format(" + {}", n) : fmt::format(" := {}", n), index};
      case Op::Type: {
        if (file_.kind() == ContainerKind::PlcOpen) {
          return Replacement{line.begin + indent.size(), line.end, fmt::format("<derived name=\"T_Fuzz{}\" />", n),
                             index};
        }
        const size_t at = type_at(code);
        size_t end = at;
        while (end < code.size() && is_identifier_char(code[end])) ++end;
        return Replacement{line.code_begin + at, line.code_begin + end, fmt::format("T_Fuzz{}", n), index};
      }
      case Op::AddVariable:
        if (file_.kind() == ContainerKind::PlcOpen) {
          return Replacement{
              line.next, line.next,
              fmt::format("{0}  <variable name=\"nFuzz{1}\"><type><INT /></type></variable>{2}", indent, n, eol),
              index};
        }
        return Replacement{line.next, line.next, fmt::format("{}    nFuzz{} : INT;{}", indent, n, eol), index};
      case Op::RemoveVariable: {
        if (file_.kind() != ContainerKind::PlcOpen) return Replacement{line.begin, line.next, "", index};
        const std::string_view text = trimmed(file_.line_text(line));
        size_t end = line.next;
        if (text.substr(text.size() - 2) != "/>") {
          const size_t close = file_.text().find("</variable>", line.begin);
          if (close == std::string::npos) return std::nullopt;
          end = file_.text().find('\n', close);
          end = end == std::string::npos ? file_.text().size() : end + 1;
        }
        return Replacement{line.begin, end, "", index};
      }
      case Op::AddPou: return add_pou(line, index, n);
      case Op::RemovePou: return Replacement{line.begin, file_.lines()[removed_object_end(line)].next, "", index};
    }
    return std::nullopt;
  }

  std::optional<Replacement> add_pou(const Line& line, size_t index, int n) const {
    const std::string& eol = file_.eol();
    const std::string indent = indent_of(line);
    switch (file_.kind()) {
      case ContainerKind::TwinCat: {
        // A method, before the LineIds or the end of the POU (interface).
        const std::string in = trimmed(file_.line_text(line)).rfind("</", 0) == 0 ? indent + "  " : indent;
        const bool itf = file_.text().find("<Itf ") != std::string::npos;
        std::string method = fmt::format(
            "{0}<Method Name=\"M_Fuzz{1}\" Id=\"{{{1:08x}-0000-4000-8000-00000000f022}}\">{2}"
            "{0}  <Declaration><![CDATA[METHOD M_Fuzz{1} : BOOL{2}]]></Declaration>{2}",
            in, n, eol);
        if (!itf) {
          method += fmt::format(
              "{0}  <Implementation>{2}{0}    <ST><![CDATA[M_Fuzz{1} := TRUE;]]></ST>{2}"
              "{0}  </Implementation>{2}",
              in, n, eol);
        }
        method += fmt::format("{}</Method>{}", in, eol);
        return Replacement{line.begin, line.begin, method, index};
      }
      case ContainerKind::PlcOpen: {
        const bool codesys = file_.text().find("<xhtml xmlns=") != std::string::npos;
        const std::string body =
            codesys ? fmt::format("<xhtml xmlns=\"http://www.w3.org/1999/xhtml\">F_Fuzz{0} := {0};</xhtml>", n)
                    : fmt::format("<xhtml:p><![CDATA[F_Fuzz{0} := {0};]]></xhtml:p>", n);
        return Replacement{line.next, line.next,
                           fmt::format("{0}  <pou name=\"F_Fuzz{1}\" pouType=\"function\">{3}"
                                       "{0}    <interface><returnType><INT /></returnType></interface>{3}"
                                       "{0}    <body><ST>{2}</ST></body>{3}"
                                       "{0}  </pou>{3}",
                                       indent, n, body, eol),
                           index};
      }
      case ContainerKind::CodesysExp:
        return Replacement{
            line.begin, line.begin,
            fmt::format("(* @NESTEDCOMMENTS := 'Yes' *){0}(* @PATH := '' *){0}(* @OBJECTFLAGS := '0, 8' *){0}"
                        "(* @SYMFILEFLAGS := '2048' *){0}FUNCTION F_Fuzz{1} : INT{0}VAR_INPUT{0}END_VAR{0}"
                        "(* @END_DECLARATION := '0' *){0}F_Fuzz{1} := {1};{0}END_FUNCTION{0}{0}{0}",
                        eol, n),
            index};
      default:
        if (upper(trimmed(file_.code_of(line))) == "END_FUNCTION_BLOCK") {
          return Replacement{line.begin, line.begin,
                             fmt::format("METHOD M_Fuzz{1} : BOOL{0}M_Fuzz{1} := TRUE;{0}END_METHOD{0}", eol, n),
                             index};
        }
        return Replacement{line.begin, line.begin,
                           fmt::format("FUNCTION F_Fuzz{1} : INT{0}F_Fuzz{1} := {1};{0}END_FUNCTION{0}{0}", eol, n),
                           index};
    }
  }

  const SourceModel& file_;
  std::mt19937& random_;
  bool base_parses_ = false;  // then so must every edited version
};

// One side's edits: replacements of base lines, then maybe a rename.
struct Side {
  std::vector<Replacement> replacements;
  std::set<size_t> lines;
  std::string rename_from;
  std::string rename_to;
  std::vector<std::string> log;  // what was done, for the failure message

  std::string text(const SourceModel& file) const {
    std::string out = applied(file.text(), replacements);
    if (!rename_from.empty()) out = renamed(file, out, rename_from, rename_to);
    return out;
  }
};

const char* op_name(Editor::Op op) {
  switch (op) {
    case Editor::Op::Statement: return "statement";
    case Editor::Op::Value: return "initial value";
    case Editor::Op::Type: return "type";
    case Editor::Op::AddVariable: return "add variable";
    case Editor::Op::RemoveVariable: return "remove variable";
    case Editor::Op::AddPou: return "add POU/method";
    case Editor::Op::RemovePou: return "remove POU/method";
  }
  return "?";
}

enum class Scenario { Independent, SameLine, Rename, AddOnBothSides, Anything };
constexpr int kScenarios = 5;

const char* scenario_name(Scenario s) {
  switch (s) {
    case Scenario::Independent: return "independent edits";
    case Scenario::SameLine: return "the same line on both sides";
    case Scenario::Rename: return "a rename against edits";
    case Scenario::AddOnBothSides: return "additions on both sides";
    case Scenario::Anything: return "edits anywhere";
  }
  return "?";
}

struct Case {
  Scenario scenario = Scenario::Anything;
  std::string ours;
  std::string theirs;
  std::string log;
  bool forced_conflict = false;  // both sides changed one line differently
};

// Adds up to `count` random edits to `side`, away from the lines in `avoid` when given.
void add_edits(Editor& editor, std::mt19937& random, Side& side, int count, const std::set<size_t>* avoid, int& n,
               const std::vector<Editor::Op>& ops) {
  for (int i = 0; i < count; ++i) {
    const Editor::Op op = ops[std::uniform_int_distribution<size_t>(0, ops.size() - 1)(random)];
    std::set<size_t> away = side.lines;
    if (avoid != nullptr) away.insert(avoid->begin(), avoid->end());
    if (std::optional<Replacement> r = editor.edit(op, away, ++n)) {
      for (const size_t line : editor.lines_of(*r)) side.lines.insert(line);
      side.log.push_back(fmt::format("{} at line {}", op_name(op), r->line + 1));
      side.replacements.push_back(std::move(*r));
    }
  }
}

Case make_case(const SourceModel& file, Scenario scenario, uint32_t seed) {
  std::mt19937 random(seed);
  Editor editor(file, random);
  using Op = Editor::Op;
  const std::vector<Op> all = {Op::Statement,      Op::Value,  Op::Type,     Op::AddVariable,
                               Op::RemoveVariable, Op::AddPou, Op::RemovePou};
  const std::vector<Op> changes = {Op::Statement, Op::Value, Op::Type, Op::AddVariable, Op::RemoveVariable};
  Side ours;
  Side theirs;
  int n = static_cast<int>(seed % 1000) * 10;  // numbers in new names and values
  const auto count = [&]() { return std::uniform_int_distribution<int>(1, 3)(random); };
  Case c;
  c.scenario = scenario;
  switch (scenario) {
    case Scenario::Independent:
      add_edits(editor, random, ours, count(), nullptr, n, all);
      add_edits(editor, random, theirs, count(), &ours.lines, n, all);
      break;
    case Scenario::SameLine: {
      const Op op =
          std::vector<Op>{Op::Statement, Op::Value, Op::Type}[std::uniform_int_distribution<size_t>(0, 2)(random)];
      if (std::optional<Replacement> r = editor.edit(op, {}, ++n)) {
        // The same place, another number: a conflict the merge must report.
        std::optional<Replacement> other = *r;
        other->text = r->text;
        const std::string number = std::to_string(n);
        const size_t at = other->text.rfind(number);
        other->text.replace(at, number.size(), std::to_string(n + 5000));
        if (file.parses() && !parses_cleanly(file.path(), applied(file.text(), {*other}))) other.reset();
        if (other) {
          c.forced_conflict = true;
          ours.lines.insert(r->line);
          theirs.lines.insert(r->line);
          ours.log.push_back(fmt::format("{} at line {} (as theirs, differently)", op_name(op), r->line + 1));
          theirs.log.push_back(fmt::format("{} at line {} (as ours, differently)", op_name(op), r->line + 1));
          ours.replacements.push_back(std::move(*r));
          theirs.replacements.push_back(std::move(*other));
        }
      }
      std::set<size_t> taken = ours.lines;
      add_edits(editor, random, ours, 1, &taken, n, changes);
      taken.insert(ours.lines.begin(), ours.lines.end());
      add_edits(editor, random, theirs, 1, &taken, n, changes);
      break;
    }
    case Scenario::Rename:
      if (std::optional<std::string> name = editor.declared_name()) {
        ours.rename_from = *name;
        ours.rename_to = fmt::format("{}_R{}", *name, ++n);
        ours.log.push_back(fmt::format("rename {} to {}", ours.rename_from, ours.rename_to));
      }
      add_edits(editor, random, theirs, count(), nullptr, n, all);
      break;
    case Scenario::AddOnBothSides:
      add_edits(editor, random, ours, 1, nullptr, n, {Op::AddPou, Op::AddVariable});
      add_edits(editor, random, theirs, 1, nullptr, n, {Op::AddPou, Op::AddVariable});
      add_edits(editor, random, ours, 1, nullptr, n, all);
      add_edits(editor, random, theirs, 1, nullptr, n, all);
      break;
    case Scenario::Anything:
      add_edits(editor, random, ours, count(), nullptr, n, all);
      add_edits(editor, random, theirs, count(), nullptr, n, all);
      break;
  }
  c.ours = ours.text(file);
  c.theirs = theirs.text(file);
  c.log = fmt::format("ours: {}; theirs: {}", fmt::join(ours.log, ", "), fmt::join(theirs.log, ", "));
  return c;
}

// ---- the checker itself: it must catch what a broken merge would return ----

const char* kTwoBlocks =
    "FUNCTION_BLOCK FB_A\nVAR\n    x : INT;\nEND_VAR\nx := 1;\nEND_FUNCTION_BLOCK\n\n"
    "FUNCTION_BLOCK FB_B\nVAR\n    y : INT;\n    z : INT;\nEND_VAR\ny := 2;\nEND_FUNCTION_BLOCK\n";

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

bool mentions(const std::string& violation, const std::string& what) {
  return violation.find(what) != std::string::npos;
}

TEST(MergeProperties, HoldForTheMergeAndCatchLostChanges) {
  const std::string base = kTwoBlocks;
  const std::string ours = replaced(base, "x := 1;", "x := 10;");
  const std::string theirs = replaced(replaced(base, "y := 2;", "y := 20;"), "z : INT;", "z : INT := 5;");
  const MergeCheck good = check_merge("x.st", base, ours, theirs);
  EXPECT_EQ(good.violation, "");
  EXPECT_EQ(good.merge.conflicts, 0u);

  vcs::MergeResult lost;  // their object change dropped: ours as the result
  lost.text = ours;
  std::string v = merge_violations("x.st", base, ours, theirs, lost);
  EXPECT_TRUE(mentions(v, "object pou:FB_B: their change is lost")) << v;

  // In an object both changed, one declaration field of theirs dropped.
  const std::string ours_b = replaced(base, "y : INT;", "y : DINT;");
  lost.text = replaced(replaced(base, "y : INT;", "y : DINT;"), "y := 2;", "y := 20;");
  v = merge_violations("x.st", base, ours_b, theirs, lost);
  EXPECT_TRUE(mentions(v, "initial value of Z in pou:FB_B: their change is lost")) << v;

  vcs::MergeResult unchanged_touched = good.merge;  // the merge changed what nobody did
  unchanged_touched.text = replaced(good.merge.text, "x : INT;", "x : SINT;");
  v = merge_violations("x.st", base, ours, replaced(base, "y := 2;", "y := 20;"), unchanged_touched);
  EXPECT_TRUE(mentions(v, "object pou:FB_A: our change is lost")) << v;

  vcs::MergeResult failed;  // a failed merge must leave ours
  failed.error = "cannot";
  failed.text = base;
  EXPECT_TRUE(mentions(merge_violations("x.st", base, ours, theirs, failed), "did not keep ours"));
}

TEST(MergeProperties, CatchHiddenAndUnreportedConflicts) {
  const std::string base = kTwoBlocks;
  const std::string ours = replaced(replaced(base, "x := 1;", "x := 10;"), "y := 2;", "y := 3;");
  const std::string theirs = replaced(base, "x := 1;", "x := 11;");
  const MergeCheck good = check_merge("x.st", base, ours, theirs);
  EXPECT_EQ(good.violation, "");
  ASSERT_EQ(good.merge.conflicts, 1u);

  vcs::MergeResult unreported = good.merge;  // markers, but a clean report
  unreported.conflicts = 0;
  std::string v = merge_violations("x.st", base, ours, theirs, unreported);
  EXPECT_TRUE(mentions(v, "0 conflicts reported, but the file holds 1 marked regions")) << v;

  vcs::MergeResult hidden = good.merge;  // a conflict reported, ours taken, no markers
  hidden.text = ours;
  v = merge_violations("x.st", base, ours, theirs, hidden);
  EXPECT_TRUE(mentions(v, "1 conflicts reported, but the file holds 0 marked regions")) << v;

  vcs::MergeResult dropped = good.merge;  // our one-sided change outside the region lost
  dropped.text = replaced(good.merge.text, "y := 3;", "y := 2;");
  v = merge_violations("x.st", base, ours, theirs, dropped);
  EXPECT_TRUE(mentions(v, "object pou:FB_B: our change is lost")) << v;

  vcs::MergeResult broken_markers = good.merge;
  broken_markers.text = replaced(good.merge.text, ">>>>>>> theirs\n", "");
  v = merge_violations("x.st", base, ours, theirs, broken_markers);
  EXPECT_TRUE(mentions(v, "a conflict region is not closed")) << v;
}

TEST(MergeProperties, CatchUnreadableResults) {
  const std::string base = kTwoBlocks;
  const std::string ours = replaced(base, "x := 1;", "x := 10;");
  vcs::MergeResult unparsable;  // every object as ours has it, and a stray line between them
  unparsable.text = replaced(ours, "\nFUNCTION_BLOCK FB_B", "\nEND_IF\nFUNCTION_BLOCK FB_B");
  const std::string v = merge_violations("x.st", base, ours, base, unparsable);
  EXPECT_TRUE(mentions(v, "the clean merge does not parse")) << v;

  const std::string motor = read_file(source_dir() / "tests/parser/containers/data/FB_Motor.TcPOU");
  vcs::MergeResult cut;
  cut.text = motor.substr(0, motor.size() / 2);
  EXPECT_TRUE(mentions(merge_violations("FB_Motor.TcPOU", motor, motor, motor, cut), "not well-formed XML"));
  vcs::MergeResult twin_ids;
  twin_ids.text = replaced(motor, "{8c1e1f7a-3b4c-4d5e-9f60-1a2b3c4d5e70}", "{8c1e1f7a-3b4c-4d5e-9f60-1a2b3c4d5e6f}");
  EXPECT_TRUE(mentions(merge_violations("FB_Motor.TcPOU", motor, motor, motor, twin_ids), "is used twice"));
}

// ---- random edits of real files ----

struct RealFile {
  std::string label;  // where it came from, for messages and seeds
  fs::path path;
  int rounds = 0;  // merges of it (repository files are few and varied: more)
};

bool is_plc_file(const fs::path& path) {
  static const std::set<std::string> kExtensions = {".ST",    ".TCPOU", ".TCDUT", ".TCGVL", ".TCIO",
                                                    ".TCITF", ".EXP",   ".XML",   ".TCTTO"};
  return kExtensions.count(upper(path.extension().string())) > 0;
}

std::vector<fs::path> files_under(const fs::path& dir) {
  std::vector<fs::path> out;
  if (!fs::is_directory(dir)) return out;
  for (const fs::directory_entry& e : fs::recursive_directory_iterator(dir)) {
    if (e.is_regular_file() && is_plc_file(e.path())) out.push_back(e.path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

uint32_t fnv(std::string_view text) {
  uint32_t h = 2166136261u;
  for (const char c : text) h = (h ^ static_cast<unsigned char>(c)) * 16777619u;
  return h;
}

// Writes a failing case where it can be merged again by hand.
fs::path write_case(const std::string& name, uint32_t seed, const std::string& base, const Case& c,
                    const std::string& merged) {
  const fs::path dir = fs::temp_directory_path() / "rung-merge-fuzz" / fmt::format("{}-{}", name, seed);
  const std::string ext = fs::path(name).extension().string();
  write_file(dir / ("base" + ext), base);
  write_file(dir / ("ours" + ext), c.ours);
  write_file(dir / ("theirs" + ext), c.theirs);
  write_file(dir / ("merged" + ext), merged);
  return dir;
}

TEST(MergeFuzz, RandomEditsOfRealFilesLoseNothingAndStayReadable) {
  std::vector<RealFile> files;
  for (const char* dir : {"examples", "tests/parser/containers/data"}) {
    for (const fs::path& p : files_under(source_dir() / dir)) {
      files.push_back({fs::relative(p, source_dir()).generic_string(), p, 8});
    }
  }
  const size_t repository_files = files.size();
  ASSERT_GE(repository_files, 20u) << "the repository's example and container files are missing";
  // The shared corpus's ST seeds: every one that declares a POU, and a spread of the snippets
  // without one (which the merge takes line by line as a whole), about 20.
  const fs::path seed_dir = shared_dir() / "corpus" / "seeds";
  std::vector<fs::path> snippets;
  for (const fs::path& p : files_under(seed_dir)) {
    if (p.extension() != ".st") continue;
    const std::string u = upper(read_file(p));
    if (u.find("END_PROGRAM") != std::string::npos || u.find("END_FUNCTION") != std::string::npos) {
      files.push_back({"seeds/" + fs::relative(p, seed_dir).generic_string(), p, 5});
    } else {
      snippets.push_back(p);
    }
  }
  const size_t step = std::max<size_t>(1, snippets.size() / 20);
  for (size_t i = 0; i < snippets.size(); i += step) {
    files.push_back({"seeds/" + fs::relative(snippets[i], seed_dir).generic_string(), snippets[i], 2});
  }
  if (files.size() == repository_files) std::cout << "note: no ST seeds under " << seed_dir << "\n";

  int scale = 1;
  if (const char* env = std::getenv("RUNG_MERGE_FUZZ_ROUNDS")) scale = std::max(1, std::atoi(env));
  size_t merges = 0;
  size_t clean = 0;
  size_t conflicted = 0;
  size_t failed = 0;
  size_t forced = 0;
  size_t compared = 0;
  const auto started = std::chrono::steady_clock::now();
  for (size_t f = 0; f < files.size(); ++f) {
    const RealFile& real = files[f];
    const std::string name = real.path.filename().string();
    const SourceModel file(name, read_file(real.path));
    const int rounds = real.rounds * scale;
    for (int round = 0; round < rounds; ++round) {
      const uint32_t seed = fnv(real.label) ^ static_cast<uint32_t>(round * 7919);
      const auto scenario = static_cast<Scenario>((fnv(real.label) + static_cast<uint32_t>(round)) % kScenarios);
      const Case c = make_case(file, scenario, seed);
      const MergeCheck check = check_merge(name, file.text(), c.ours, c.theirs);
      ++merges;
      if (!check.merge.error.empty()) {
        ++failed;
      } else if (check.merge.conflicts > 0) {
        ++conflicted;
      } else {
        ++clean;
      }
      std::string violation = check.violation;
      if (c.forced_conflict && check.merge.error.empty() && check.merge.conflicts == 0) {
        violation += "both sides changed the same line differently, but the merge reports no conflict\n";
      }
      forced += c.forced_conflict ? 1 : 0;
      compared += check.objects_compared ? 1 : 0;
      if (!violation.empty()) {
        const fs::path dir = write_case(name, seed, file.text(), c, check.merge.text);
        ADD_FAILURE() << real.label << ", seed " << seed << " (" << scenario_name(scenario) << "; " << c.log << "):\n"
                      << violation << "base, ours, theirs and the merged file: " << dir.string()
                      << "\n  (rung merge-file base ours theirs " << name << " merges them again)";
      }
    }
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  std::cout << fmt::format(
      "{} merges of {} files in {:.1f} s: {} clean, {} with conflicts ({} forced), {} not merged; objects compared "
      "in {}\n",
      merges, files.size(), seconds, clean, conflicted, forced, failed, compared);
  // The edits must reach both outcomes often, and the object model must see most merges, or the
  // properties are checked on too little.
  EXPECT_GE(clean, merges / 4);
  EXPECT_GE(conflicted, merges / 10);
  EXPECT_GE(forced, merges / 10);
  EXPECT_GE(compared, merges / 2);
}

}  // namespace
}  // namespace rung::test
