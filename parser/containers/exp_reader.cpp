#include "parser/containers/exp_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "parser/containers/exp_scan.hpp"
#include "parser/source/flat_comments.hpp"

namespace rung::containers {
namespace {

using exp::Line;

struct CodeObject {
  std::string_view keyword;
  std::string_view end;
  std::string_view kind;
  bool has_body;
};

constexpr std::array<CodeObject, 7> code_objects = {{
    {"PROGRAM", "END_PROGRAM", "PROGRAM", true},
    {"FUNCTION_BLOCK", "END_FUNCTION_BLOCK", "FUNCTION_BLOCK", true},
    {"FUNCTION", "END_FUNCTION", "FUNCTION", true},
    {"ACTION", "END_ACTION", "ACTION", true},
    {"TYPE", "END_TYPE", "TYPE", false},
    {"VAR_GLOBAL", "END_VAR", "GVL", false},
    {"VAR_CONFIG", "END_VAR", "VAR_CONFIG", false},
}};

// Top-level sections of an export that are not PLC code. Besides these, every
// top-level word starting with '_' (_ALARMCONFIG, and the other project-resource
// sections CODESYS writes with a leading underscore) opens such a section.
constexpr std::array<std::string_view, 4> non_code_sections = {"VISUALISATION", "LIBRARY", "PLC_CONFIGURATION",
                                                               "RESOURCE"};

// IL operators: a body whose first line is "<operator> operand" without ':=' or ';' is IL.
constexpr std::array<std::string_view, 33> il_operators = {
    "LD",   "LDN", "ST",  "STN",  "S",     "R",   "AND",  "ANDN",  "OR",  "ORN",  "XOR",
    "XORN", "NOT", "ADD", "SUB",  "MUL",   "DIV", "MOD",  "GT",    "GE",  "EQ",   "NE",
    "LE",   "LT",  "JMP", "JMPC", "JMPCN", "CAL", "CALC", "CALCN", "RET", "RETC", "RETCN"};

template <size_t N>
bool contains(const std::array<std::string_view, N>& list, std::string_view word) {
  return std::find(list.begin(), list.end(), word) != list.end();
}

const CodeObject* code_object(std::string_view word) {
  for (const CodeObject& object : code_objects) {
    if (object.keyword == word) return &object;
  }
  return nullptr;
}

bool is_graphical_body(std::string_view word) {
  return word.size() > 6 && word.front() == '_' && word.substr(word.size() - 5) == "_BODY";
}

std::string guess_text_language(std::string_view word, std::string_view line) {
  if (word == "INITIAL_STEP" || word == "STEP") return "SFC";
  const bool statement_like = line.find(":=") != std::string_view::npos || line.find(';') != std::string_view::npos;
  if (!statement_like && contains(il_operators, word)) return "IL";
  return "ST";
}

class ExpReader {
 public:
  explicit ExpReader(std::string_view text) : text_(text), virtual_(text) {}

  ContainerDocument read() {
    const auto size = static_cast<uint32_t>(text_.size());
    for (uint32_t pos = 0; pos < size;) {
      const Line line = exp::line_at(text_, pos);
      dispatch(line);
      pos = line.next;
    }
    if (mode_ == Mode::Code || mode_ == Mode::Body) {
      note_unterminated(fmt::format("ends without {}", end_word_));
    } else if (mode_ == Mode::NonCode) {
      note_unterminated("section runs to the end of the file");
    }

    flatten_comments_where_not_nested();
    ContainerDocument doc = plain_document(virtual_, ContainerKind::CodesysExp);
    doc.objects = std::move(objects_);
    return doc;
  }

 private:
  enum class Mode { TopLevel, Code, Body, NonCode };

  // The markers of the object about to start. "@NESTEDCOMMENTS" opens every
  // header, so it resets the rest; actions following a POU without a header
  // of their own inherit its folder and comment rule.
  struct Header {
    bool fresh = false;  // a header was read and no object has used it yet
    bool nested_comments = true;
    std::string path;
    std::string global_list;
  };

  std::string_view content(const Line& line) const { return text_.substr(line.begin, line.end - line.begin); }

  void dispatch(const Line& line) {
    switch (mode_) {
      case Mode::TopLevel: top_level(line); break;
      case Mode::Code: code(line); break;
      case Mode::Body: graphical_body(line); break;
      case Mode::NonCode: non_code(line); break;
    }
  }

  void top_level(const Line& line) {
    const std::string_view text = content(line);
    if (comments_.in_comment()) {
      comments_.feed(text);
      return;
    }
    if (const auto marker = exp::parse_marker(text)) {
      read_marker(*marker);
    } else {
      const std::string word = exp::first_word(text);
      if (const CodeObject* object = code_object(word)) {
        start_code_object(*object, line, word);
      } else if (!word.empty() && (word.front() == '_' || contains(non_code_sections, word))) {
        start_non_code(line, word);
        return;
      }
    }
    comments_.feed(text);
  }

  void read_marker(const exp::Marker& marker) {
    if (marker.key == "NESTEDCOMMENTS") {
      header_ = Header{};
      header_.nested_comments = marker.value != "No" && marker.value != "NO" && marker.value != "no";
    } else if (marker.key == "PATH") {
      header_.path = exp::unescape_path(marker.value);
    } else if (marker.key == "GLOBAL_VARIABLE_LIST") {
      header_.global_list = marker.value;
    } else {
      return;  // OBJECTFLAGS, SYMFILEFLAGS, END_DECLARATION, OBJECT_END...: nothing to keep
    }
    header_.fresh = true;
  }

  void start_code_object(const CodeObject& object, const Line& line, std::string_view word) {
    mode_ = Mode::Code;
    end_word_ = std::string(object.end);
    has_body_ = object.has_body;
    // A POU's body starts after "@END_DECLARATION"; an action has no declaration part.
    awaiting_body_ = object.keyword == "ACTION";

    const bool continues_list =
        object.kind == "GVL" && !header_.fresh && current_ < objects_.size() && objects_[current_].kind == "GVL";
    if (continues_list) return;  // a further VAR_GLOBAL block of the same list

    const std::string_view text = content(line);
    const auto word_at = static_cast<uint32_t>(text.find_first_not_of(" \t"));
    ContainerObject entry;
    entry.kind = std::string(object.kind);
    entry.file_offset = line.begin + word_at;
    entry.path = header_.path;
    entry.nested_comments = header_.nested_comments;
    const uint32_t after_word = entry.file_offset + static_cast<uint32_t>(word.size());
    if (object.kind == "GVL" || object.kind == "VAR_CONFIG") {
      entry.name = header_.global_list;
    } else if (object.kind == "ACTION") {
      entry.name = owner_ + "." + exp::name_after(text_, after_word);
    } else {
      entry.name = exp::name_after(text_, after_word);
      if (object.kind != "TYPE") owner_ = entry.name;
    }
    header_.fresh = false;
    comments_.set_nested(entry.nested_comments);
    current_ = objects_.size();
    objects_.push_back(std::move(entry));
  }

  void start_non_code(const Line& line, const std::string& word) {
    mode_ = Mode::NonCode;
    const size_t base_at = word.find_first_not_of('_');
    const std::string base = base_at == std::string::npos ? std::string() : word.substr(base_at);
    section_ends_ = {"END_" + base, "_END_" + base};

    ContainerObject entry;
    entry.kind = word;
    entry.file_offset = line.begin + static_cast<uint32_t>(content(line).find_first_not_of(" \t"));
    entry.path = header_.path;
    entry.nested_comments = header_.nested_comments;
    const std::string_view text = content(line);
    entry.name = exp::name_after(text, static_cast<uint32_t>(text.find_first_not_of(" \t") + word.size()));
    if (entry.name.empty() && word == "LIBRARY") {
      // "LIBRARY\r\nStandard.lib 2.3.10 12:00:00": the library file is on the next line.
      const Line next = exp::line_at(text_, line.next);
      const std::string_view name_line = content(next);
      const size_t begin = name_line.find_first_not_of(" \t");
      if (begin != std::string_view::npos) {
        entry.name = std::string(name_line.substr(begin, name_line.find_first_of(" \t", begin) - begin));
      }
    }
    entry.note = fmt::format("{} section is not PLC code; blanked", word);
    header_.fresh = false;
    current_ = objects_.size();
    objects_.push_back(std::move(entry));
    blank(line);
  }

  void code(const Line& line) {
    const std::string_view text = content(line);
    if (comments_.in_comment()) {
      comments_.feed(text);
      return;
    }
    if (const auto marker = exp::parse_marker(text)) {
      if (next_object_starts(*marker, line)) return;
      if (marker->key == "END_DECLARATION") awaiting_body_ = has_body_;
      comments_.feed(text);
      return;
    }
    const std::string word = exp::first_word(text);
    if (word == end_word_) {
      mode_ = Mode::TopLevel;
      awaiting_body_ = false;
    } else if (awaiting_body_ && !word.empty()) {
      awaiting_body_ = false;
      if (is_graphical_body(word)) {
        const std::string language = word.substr(1, word.size() - 6);
        objects_[current_].language = language;
        objects_[current_].note = fmt::format("{} body is graphical; blanked", language);
        mode_ = Mode::Body;
        blank(line);
        return;
      }
      objects_[current_].language = guess_text_language(word, text);
    }
    comments_.feed(text);
  }

  void graphical_body(const Line& line) {
    const std::string_view text = content(line);
    if (exp::first_word(text) == end_word_) {
      mode_ = Mode::TopLevel;
      return;
    }
    if (const auto marker = exp::parse_marker(text); marker && next_object_starts(*marker, line)) return;
    blank(line);
  }

  void non_code(const Line& line) {
    const std::string_view text = content(line);
    if (const auto marker = exp::parse_marker(text); marker && next_object_starts(*marker, line)) return;
    const std::string word = exp::first_word(text);
    blank(line);
    if (std::find(section_ends_.begin(), section_ends_.end(), word) != section_ends_.end()) mode_ = Mode::TopLevel;
  }

  // A "@NESTEDCOMMENTS" marker inside an object means the next object's header
  // has begun: the current object lacks its end. Recover by reading the line
  // at top level.
  bool next_object_starts(const exp::Marker& marker, const Line& line) {
    if (marker.key != "NESTEDCOMMENTS") return false;
    note_unterminated(mode_ == Mode::NonCode ? std::string("section has no end marker")
                                             : fmt::format("has no {} before the next object", end_word_));
    mode_ = Mode::TopLevel;
    awaiting_body_ = false;
    comments_.reset();
    top_level(line);
    return true;
  }

  void note_unterminated(const std::string& what) {
    if (current_ >= objects_.size()) return;
    std::string& note = objects_[current_].note;
    note = note.empty() ? what : note + "; " + what;
  }

  // rung's grammar nests (* *) comments, as CODESYS V3 does. An object exported with
  // @NESTEDCOMMENTS := 'No' closes a comment at its first '*)', so a '(*' inside such a comment
  // would wrongly open a nested one. The '(' of every such inner '(*' is blanked in the virtual
  // text (same length, so positions stay 1:1; consumers take comment text from the file text).
  void flatten_comments_where_not_nested() {
    for (size_t i = 0; i < objects_.size(); ++i) {
      if (objects_[i].nested_comments) continue;
      const uint32_t begin = objects_[i].file_offset;
      uint32_t end = static_cast<uint32_t>(virtual_.size());
      for (size_t j = i + 1; j < objects_.size(); ++j) {
        if (objects_[j].file_offset > begin) {
          end = objects_[j].file_offset;
          break;
        }
      }
      source::read_comments_flat(virtual_, begin, end);
    }
  }

  void blank(const Line& line) { std::fill(virtual_.begin() + line.begin, virtual_.begin() + line.end, ' '); }

  std::string_view text_;
  std::string virtual_;
  std::vector<ContainerObject> objects_;
  exp::CommentTracker comments_;
  Mode mode_ = Mode::TopLevel;
  Header header_;
  std::string end_word_;
  std::vector<std::string> section_ends_;
  bool has_body_ = false;
  bool awaiting_body_ = false;
  size_t current_ = static_cast<size_t>(-1);
  std::string owner_;  // the last PROGRAM/FUNCTION_BLOCK/FUNCTION: actions belong to it
};

}  // namespace

ContainerDocument read_exp(std::string_view text) {
  return ExpReader(text).read();
}

}  // namespace rung::containers
