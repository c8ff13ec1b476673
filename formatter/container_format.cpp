#include "formatter/container_format.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <optional>

#include "parser/containers/exp_reader.hpp"
#include "parser/containers/exp_scan.hpp"
#include "parser/containers/twincat_reader.hpp"
#include "parser/containers/xml_text.hpp"
#include "parser/keywords.hpp"
#include "parser/source/line_index.hpp"

namespace rung::format {
namespace {

using containers::ContainerDocument;
using containers::ContainerKind;

// One piece of the file to format and how its text is stored there.
struct Piece {
  uint32_t file_begin = 0;  // the stored bytes: file_text[file_begin, file_end)
  uint32_t file_end = 0;
  std::string text;  // what the grammar reads (the stored bytes, XML entities expanded)
  enum class Storage { Verbatim, XmlCdata, XmlEscaped } storage = Storage::Verbatim;
  FormatRequest request;
  std::string name;  // for notes: "FB_Motor method Run/implementation"
  // A part of a container gets the part's line ends and final line end back; a whole file is
  // laid out by the engine alone.
  bool is_whole_file = false;
};

// The line ends a piece uses throughout, so the formatted text can be given the same ones.
enum class LineEnds { Lf, CrLf, Mixed };

LineEnds line_ends_of(std::string_view text) {
  size_t lf = 0, crlf = 0;
  for (size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '\n') continue;
    (i > 0 && text[i - 1] == '\r' ? crlf : lf) += 1;
  }
  if (crlf > 0 && lf > 0) return LineEnds::Mixed;
  return crlf > 0 ? LineEnds::CrLf : LineEnds::Lf;
}

// Gives `formatted` the piece's line ends and its (absence of a) final line end: a TwinCAT
// CDATA section ending in "END_IF]]>" keeps ending that way.
std::string fit_to_piece(std::string formatted, std::string_view original) {
  const LineEnds ends = line_ends_of(original);
  if (ends != LineEnds::Mixed) {
    std::string out;
    out.reserve(formatted.size() + formatted.size() / 16);
    for (size_t i = 0; i < formatted.size(); ++i) {
      const char c = formatted[i];
      if (c == '\r' && i + 1 < formatted.size() && formatted[i + 1] == '\n') continue;  // re-added below
      if (c == '\n' && ends == LineEnds::CrLf) out += '\r';
      out += c;
    }
    formatted = std::move(out);
  }
  const bool had_final_end = !original.empty() && original.back() == '\n';
  if (!had_final_end) {
    while (!formatted.empty() && (formatted.back() == '\n' || formatted.back() == '\r')) formatted.pop_back();
  }
  return formatted;
}

std::string escape_xml_text(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      default: out += c;
    }
  }
  return out;
}

// "line 12: ..." of a piece that starts on file line `first_line` (1-based) -> the file's line.
std::string shift_message(const std::string& message, uint32_t first_line) {
  constexpr std::string_view prefix = "line ";
  if (message.compare(0, prefix.size(), prefix) != 0) return fmt::format("line {}: {}", first_line, message);
  uint32_t line = 0;
  const char* begin = message.data() + prefix.size();
  const char* end = message.data() + message.size();
  const auto [after, error] = std::from_chars(begin, end, line);
  if (error != std::errc() || line == 0) return message;
  return fmt::format("line {}{}", line + first_line - 1, std::string_view(after, static_cast<size_t>(end - after)));
}

class FileFormatter {
 public:
  FileFormatter(std::string_view text, const PieceFormatter& format_piece) : text_(text), format_piece_(format_piece) {}

  FileFormatResult run(ContainerKind kind) {
    switch (kind) {
      case ContainerKind::None: {
        Piece whole;
        whole.file_end = static_cast<uint32_t>(text_.size());
        whole.text = std::string(text_);
        whole.is_whole_file = true;
        pieces_.push_back(std::move(whole));
        break;
      }
      case ContainerKind::TwinCat: collect_twincat(); break;
      case ContainerKind::CodesysExp: collect_exp(); break;
      case ContainerKind::PlcOpen:
        out_.notes.push_back(
            "PLCopen XML is not formatted (its code sits in many XML elements laid out by the "
            "exporting tool)");
        break;
      case ContainerKind::Unsupported: out_.notes.push_back("the file holds no PLC source; not formatted"); break;
    }
    if (!failed_) format_pieces();
    if (!failed_ && out_.result.changed && kind != ContainerKind::None) check_reads_back(kind);
    if (failed_ || !out_.result.changed) {
      out_.result.text = std::string(text_);
      out_.result.changed = false;
    }
    return std::move(out_);
  }

 private:
  void fail(Status status, std::string message) {
    failed_ = true;
    out_.result.status = status;
    out_.result.message = std::move(message);
  }

  // ---- TwinCAT: one piece per run of real text of one role (a declaration, a body, ...)

  void collect_twincat() {
    const ContainerDocument doc = containers::read_twincat(text_);
    objects_before_ = doc.objects;
    if (!doc.issues.empty()) {
      const source::LineIndex lines(text_);
      return fail(Status::SyntaxErrors,
                  fmt::format("line {}: {}", lines.position_of(doc.issues[0].offset).line + 1, doc.issues[0].message));
    }
    for (const containers::ContainerObject& object : doc.objects) {
      if (!object.note.empty()) note_left_alone(object);
    }
    for (size_t i = 0; i < doc.segments.size();) {
      const containers::Segment& first = doc.segments[i];
      size_t end = i + 1;
      if (first.file_begin) {
        while (end < doc.segments.size() && doc.segments[end].file_begin && doc.segments[end].role == first.role &&
               doc.segments[end].object_name == first.object_name) {
          ++end;
        }
        const containers::Segment& last = doc.segments[end - 1];
        std::string_view text(doc.virtual_text);
        add_xml_piece(text.substr(first.virtual_begin, last.virtual_begin + last.length - first.virtual_begin),
                      *first.file_begin, first.object_name + " " + first.role);
      }
      i = end;
    }
  }

  // A piece of XML character data: a CDATA section (stored as read) or escaped text (stored with
  // entities); text spread over several XML nodes is left alone.
  void add_xml_piece(std::string_view text, uint32_t file_begin, std::string name) {
    Piece piece;
    piece.file_begin = file_begin;
    piece.text = std::string(text);
    piece.name = std::move(name);
    constexpr std::string_view cdata_open = "<![CDATA[";
    const bool in_cdata = file_begin >= cdata_open.size() &&
                          text_.substr(file_begin - cdata_open.size(), cdata_open.size()) == cdata_open;
    if (text_.substr(file_begin, text.size()) == text &&
        (in_cdata || text.find_first_of("<&") == std::string_view::npos)) {
      piece.file_end = file_begin + static_cast<uint32_t>(text.size());
      piece.storage = in_cdata ? Piece::Storage::XmlCdata : Piece::Storage::XmlEscaped;
      if (!in_cdata && text_.substr(piece.file_end, cdata_open.size()) == cdata_open) return note_split(piece);
    } else {
      const size_t end = text_.find('<', file_begin);
      const std::string_view raw = text_.substr(file_begin, end == std::string_view::npos ? end : end - file_begin);
      // Character references (&#xD; for a CR, ...) would not survive re-escaping as written.
      if (raw.find("&#") != std::string_view::npos) {
        out_.notes.push_back(fmt::format("{}: holds XML character references; not formatted", piece.name));
        return;
      }
      if (in_cdata || containers::unescape_xml(raw) != text) return note_split(piece);
      piece.file_end = file_begin + static_cast<uint32_t>(raw.size());
      piece.storage = Piece::Storage::XmlEscaped;
    }
    pieces_.push_back(std::move(piece));
  }

  void note_split(const Piece& piece) {
    out_.notes.push_back(fmt::format("{}: text is split over several XML parts; not formatted", piece.name));
  }

  void note_left_alone(const containers::ContainerObject& object) {
    out_.notes.push_back(
        fmt::format("{}: left as it is ({})", object.name.empty() ? object.kind : object.name, object.note));
  }

  // ---- .EXP: each code object from its keyword to the end of its END_ line

  void collect_exp() {
    const ContainerDocument doc = containers::read_exp(text_);
    objects_before_ = doc.objects;
    struct Code {
      std::string_view kind, end;
    };
    constexpr std::array<Code, 7> codes = {{{"PROGRAM", "END_PROGRAM"},
                                            {"FUNCTION_BLOCK", "END_FUNCTION_BLOCK"},
                                            {"FUNCTION", "END_FUNCTION"},
                                            {"ACTION", "END_ACTION"},
                                            {"TYPE", "END_TYPE"},
                                            {"GVL", "END_VAR"},
                                            {"VAR_CONFIG", "END_VAR"}}};
    for (size_t i = 0; i < doc.objects.size(); ++i) {
      const containers::ContainerObject& object = doc.objects[i];
      const auto code = std::find_if(codes.begin(), codes.end(), [&](const Code& c) { return c.kind == object.kind; });
      // A non-code section (blanked by the reader), a graphical body or a missing end.
      if (code == codes.end() || !object.note.empty()) {
        note_left_alone(object);
        continue;
      }
      const uint32_t limit = i + 1 < doc.objects.size() ? doc.objects[i + 1].file_offset : size_of_text();
      FormatRequest request;
      request.flat_comments = !object.nested_comments;
      uint32_t begin = object.file_offset;
      while (true) {
        const std::optional<uint32_t> end = exp_object_end(begin, limit, code->end, object.nested_comments);
        if (!end) break;
        Piece piece;
        piece.file_begin = begin;
        piece.file_end = *end;
        piece.text = std::string(text_.substr(begin, *end - begin));
        piece.request = request;
        piece.name = object.name.empty() ? std::string(object.kind) : object.name;
        pieces_.push_back(std::move(piece));
        // A global variable list may hold several VAR_GLOBAL blocks: each is a piece.
        if (object.kind != "GVL") break;
        const std::optional<uint32_t> next = next_var_global(*end, limit);
        if (!next) break;
        begin = *next;
      }
    }
  }

  uint32_t size_of_text() const { return static_cast<uint32_t>(text_.size()); }

  // Just past the line end of the line whose first word is `end_word` (outside comments), or
  // nullopt when there is none before `limit`.
  std::optional<uint32_t> exp_object_end(uint32_t begin, uint32_t limit, std::string_view end_word, bool nested) const {
    containers::exp::CommentTracker comments;
    comments.set_nested(nested);
    // The keyword line itself starts at `begin` (its indentation, if any, stays outside).
    for (uint32_t pos = begin; pos < limit;) {
      const containers::exp::Line line = containers::exp::line_at(text_, pos);
      const std::string_view content = text_.substr(line.begin, line.end - line.begin);
      if (!comments.in_comment() && containers::exp::first_word(content) == end_word) return line.next;
      comments.feed(content);
      pos = line.next;
    }
    return std::nullopt;
  }

  // The next "VAR_GLOBAL" line before `limit`, skipping blank lines; nullopt at anything else.
  std::optional<uint32_t> next_var_global(uint32_t from, uint32_t limit) const {
    for (uint32_t pos = from; pos < limit;) {
      const containers::exp::Line line = containers::exp::line_at(text_, pos);
      const std::string_view content = text_.substr(line.begin, line.end - line.begin);
      const size_t first = content.find_first_not_of(" \t");
      if (first != std::string_view::npos) {
        if (containers::exp::first_word(content) != "VAR_GLOBAL") return std::nullopt;
        return line.begin + static_cast<uint32_t>(first);
      }
      pos = line.next;
    }
    return std::nullopt;
  }

  // ---- formatting and splicing

  void format_pieces() {
    // Splicing goes through the file front to back. The virtual text does not: TwinCAT's reader
    // puts methods before properties, whatever their order in the XML.
    std::sort(pieces_.begin(), pieces_.end(),
              [](const Piece& a, const Piece& b) { return a.file_begin < b.file_begin; });
    std::optional<source::LineIndex> lines;
    std::string result;
    uint32_t copied = 0;  // file bytes before this are in `result`
    for (const Piece& piece : pieces_) {
      FormatResult formatted = format_piece_(piece.text, piece.request);
      ++out_.pieces;
      if (formatted.status != Status::Formatted) {
        if (!lines) lines.emplace(text_);
        return fail(formatted.status, shift_message(formatted.message, lines->position_of(piece.file_begin).line + 1));
      }
      if (formatted.text == piece.text) continue;
      std::string stored =
          piece.is_whole_file ? std::move(formatted.text) : fit_to_piece(std::move(formatted.text), piece.text);
      if (stored == piece.text) continue;
      if (piece.storage == Piece::Storage::XmlEscaped) stored = escape_xml_text(stored);
      if (piece.storage == Piece::Storage::XmlCdata && stored.find("]]>") != std::string::npos) {
        out_.notes.push_back(
            fmt::format("{}: the formatted text would close its CDATA section; not formatted", piece.name));
        continue;
      }
      result.append(text_.substr(copied, piece.file_begin - copied));
      result += stored;
      copied = piece.file_end;
      out_.result.changed = true;
    }
    if (!out_.result.changed) return;
    result.append(text_.substr(copied));
    out_.result.text = std::move(result);
  }

  // The container must read back to the same objects (names, kinds, languages): a splice in the
  // wrong place would show as a lost method or a changed kind. Such a bug must never be written.
  void check_reads_back(ContainerKind kind) {
    const std::string& text = out_.result.text;
    const ContainerDocument doc =
        kind == ContainerKind::TwinCat ? containers::read_twincat(text) : containers::read_exp(text);
    auto same = [](const containers::ContainerObject& a, const containers::ContainerObject& b) {
      // Names compare without case, as IEC identifiers do.
      return keywords::upper(a.name) == keywords::upper(b.name) && a.kind == b.kind && a.language == b.language &&
             a.path == b.path && a.nested_comments == b.nested_comments && a.note == b.note;
    };
    const bool same_objects = doc.objects.size() == objects_before_.size() &&
                              std::equal(doc.objects.begin(), doc.objects.end(), objects_before_.begin(), same);
    if (doc.issues.empty() && same_objects) return;
    fail(Status::Unsafe, "line 1: the formatted container does not read back to the same objects");
    out_.result.changed = false;
  }

  std::string_view text_;
  const PieceFormatter& format_piece_;
  std::vector<containers::ContainerObject> objects_before_;
  std::vector<Piece> pieces_;
  FileFormatResult out_;
  bool failed_ = false;
};

}  // namespace

FileFormatResult format_file_text(containers::ContainerKind kind, std::string_view file_text,
                                  const PieceFormatter& format_piece) {
  return FileFormatter(file_text, format_piece).run(kind);
}

FileFormatResult format_file_text(containers::ContainerKind kind, std::string_view file_text,
                                  const project::FormatSettings& settings) {
  const PieceFormatter engine = [&settings](std::string_view piece, const FormatRequest& request) {
    return format_text(piece, settings, request);
  };
  return format_file_text(kind, file_text, engine);
}

}  // namespace rung::format
