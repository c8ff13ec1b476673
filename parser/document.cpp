#include "parser/document.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "parser/conditional_branches.hpp"
#include "parser/containers/read_container.hpp"
#include "parser/containers/xml_text.hpp"
#include "parser/diagnostic_codes.hpp"
#include "parser/source/flat_comments.hpp"
#include "parser/syntax_diagnostics.hpp"

namespace rung {

Document Document::from_bytes(std::string path, std::string_view bytes, const DocumentOptions& options) {
  Document doc;
  doc.path_ = std::move(path);
  doc.build(bytes, options);
  return doc;
}

std::optional<Document> Document::load(const std::filesystem::path& path, std::string* error,
                                       const DocumentOptions& options) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    if (error) *error = fmt::format("{}: cannot open file", path.string());
    return std::nullopt;
  }
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) {
    if (error) *error = fmt::format("{}: read error", path.string());
    return std::nullopt;
  }
  return from_bytes(path.string(), buffer.str(), options);
}

namespace {

Diagnostic make(std::string_view code, Severity severity, TextRange range, std::string message, std::string help = {}) {
  Diagnostic d;
  d.code = std::string(code);
  d.severity = severity;
  d.range = range;
  d.message = std::move(message);
  d.help = std::move(help);
  return d;
}

// Whether text starts (after a BOM-less blank prefix) like an XML document.
bool looks_like_xml(std::string_view text) {
  size_t i = text.find_first_not_of(" \t\r\n");
  return i != std::string_view::npos && text.compare(i, 5, "<?xml") == 0;
}

// The name of the root element, skipping the declaration, comments and DOCTYPE.
std::string xml_root_name(std::string_view text) {
  size_t i = 0;
  while ((i = text.find('<', i)) != std::string_view::npos) {
    const size_t skipped = containers::skip_special_markup(text, i);
    if (skipped == std::string_view::npos) {
      const size_t end = text.find_first_of(" \t\r\n/>", i + 1);
      return std::string(text.substr(i + 1, (end == std::string_view::npos ? text.size() : end) - i - 1));
    }
    i = skipped;
  }
  return "?";
}

}  // namespace

void Document::build(std::string_view bytes, const DocumentOptions& options) {
  if (bytes.size() > options.max_bytes) {
    file_lines_ = std::make_unique<source::LineIndex>(std::string_view());
    diagnostics_.push_back(
        make(codes::kParseAborted, Severity::Error, {0, 0},
             fmt::format("file is {} MB; rung parses files up to {} MB", bytes.size() >> 20, options.max_bytes >> 20),
             "split the file, or check that it really is PLC source"));
    return;
  }
  *decoded_ = source::decode(bytes);
  file_lines_ = std::make_unique<source::LineIndex>(decoded_->utf8);
  if (decoded_->is_binary) {
    diagnostics_.push_back(make(codes::kBinaryFile, Severity::Error, {0, 0}, "binary file, not PLC source text",
                                "rung reads text files (.st, .il, .TcPOU, .EXP, ...)"));
    return;
  }
  for (const auto& issue : decoded_->issues) {
    // An issue may sit at the very end of the text (dropped NUL padding): keep the range inside it.
    const auto size = static_cast<uint32_t>(decoded_->utf8.size());
    const uint32_t begin = std::min(issue.offset, size);
    diagnostics_.push_back(make(codes::kEncoding, Severity::Warning, {begin, std::min(begin + 1, size)}, issue.message,
                                "save the file as UTF-8"));
  }

  std::string tree_text;
  auto kind = containers::detect_container(path_, decoded_->utf8);
  if (kind == containers::ContainerKind::None && looks_like_xml(decoded_->utf8)) {
    // An XML file that is no container rung knows: parsing it as ST would only produce noise.
    diagnostics_.push_back(
        make(codes::kContainer, Severity::Error, {0, 0},
             fmt::format("XML file with root <{}> is not a format rung reads", xml_root_name(decoded_->utf8)),
             "rung reads TwinCAT (.TcPOU, ...), CODESYS .EXP and PLCopen XML files"));
    return;
  }
  if (kind == containers::ContainerKind::Unsupported) {
    // A vendor object that holds no PLC source (e.g. a TwinCAT task object): nothing to parse.
    return;
  }
  if (kind != containers::ContainerKind::None) {
    container_ = containers::read_container(kind, path_, decoded_->utf8);
    for (const auto& issue : container_->issues) {
      diagnostics_.push_back(make(codes::kContainer, Severity::Error, {issue.offset, issue.offset}, issue.message));
    }
    tree_text = container_->virtual_text;
  } else {
    tree_text = decoded_->utf8;
  }
  reading_diagnostics_ = diagnostics_;
  parse(std::move(tree_text), options, true);
}

Document Document::reread(std::string tree_text) const {
  Document doc;
  doc.path_ = path_;
  *doc.decoded_ = *decoded_;
  doc.file_lines_ = std::make_unique<source::LineIndex>(doc.decoded_->utf8);
  doc.container_ = container_;
  doc.reading_diagnostics_ = reading_diagnostics_;
  doc.diagnostics_ = reading_diagnostics_;
  doc.parse(std::move(tree_text), {}, false);
  return doc;
}

void Document::parse(std::string tree_text, const DocumentOptions& options, bool try_first_branches) {
  tree_.emplace(SyntaxTree::parse(std::move(tree_text), options.parse));
  if (tree_->aborted()) {
    diagnostics_.push_back(make(codes::kParseAborted, Severity::Error, {0, 0},
                                "parsing stopped: the file is too large or too deeply nested for rung's time limit",
                                "split the file into smaller POUs"));
    tree_.reset();
    return;
  }

  SyntaxDiagnosticOptions syntax_options;
  syntax_options.describe_position = [this](uint32_t offset) {
    FilePosition p = position_of_tree_offset(offset);
    return fmt::format("{}:{}", p.line, p.column);
  };
  std::vector<Diagnostic> syntax = collect_syntax_diagnostics(*tree_, syntax_options);

  // MATIEC/Beremiz and CODESYS 2.3 do not nest comments: there "(* old (* code *)" is one whole
  // comment, while the nesting reading leaves it open and swallows code. When a plain file does
  // not parse and holds such a '(*' inside a comment, read its comments flat too and keep the
  // reading with fewer errors (containers say how their comments nest).
  auto errors_in = [](const std::vector<Diagnostic>& list) {
    return std::count_if(list.begin(), list.end(), [](const Diagnostic& d) { return d.severity == Severity::Error; });
  };
  if (!container_ && errors_in(syntax) > 0) {
    std::string flat = tree_->text();
    if (source::read_comments_flat(flat, 0, flat.size()) > 0) {
      SyntaxTree reparsed = SyntaxTree::parse(std::move(flat), options.parse);
      if (!reparsed.aborted()) {
        std::vector<Diagnostic> flat_syntax = collect_syntax_diagnostics(reparsed, syntax_options);
        if (errors_in(flat_syntax) < errors_in(syntax)) {
          tree_.emplace(std::move(reparsed));
          syntax = std::move(flat_syntax);
        }
      }
    }
  }

  // Conditional-compilation branches may split a statement ({IF defined(X)} IF a THEN {ELSE}
  // IF b THEN {END_IF}); when the file does not parse as written, read only the first branch of
  // each group, and keep that reading if it has fewer errors.
  if (try_first_branches && errors_in(syntax) > 0) {
    std::string first_branches = tree_->text();
    if (keep_first_conditional_branches(*tree_, first_branches) > 0) {
      SyntaxTree reparsed = SyntaxTree::parse(std::move(first_branches), options.parse);
      if (!reparsed.aborted()) {
        std::vector<Diagnostic> branch_syntax = collect_syntax_diagnostics(reparsed, syntax_options);
        if (errors_in(branch_syntax) < errors_in(syntax)) {
          tree_.emplace(std::move(reparsed));
          syntax = std::move(branch_syntax);
        }
      }
    }
  }

  for (Diagnostic& d : syntax) {
    bool empty = d.range.end == d.range.begin;
    d.range = {file_offset_of(d.range.begin), empty ? file_offset_of(d.range.begin) : file_end_offset_of(d.range.end)};
    if (d.range.end < d.range.begin) d.range.end = d.range.begin;
    for (auto& label : d.labels) {
      label.range = {file_offset_of(label.range.begin), file_end_offset_of(label.range.end)};
      if (label.range.end < label.range.begin) label.range.end = label.range.begin;
    }
    diagnostics_.push_back(std::move(d));
  }
  sort_diagnostics(diagnostics_);
}

uint32_t Document::file_offset_of(uint32_t tree_offset) const {
  if (!container_) return tree_offset;
  auto mapped = container_->to_file_offset(tree_offset);
  return mapped ? *mapped : static_cast<uint32_t>(decoded_->utf8.size());
}

uint32_t Document::file_end_offset_of(uint32_t tree_end) const {
  if (!container_ || tree_end == 0) return file_offset_of(tree_end);
  const containers::Segment* before = container_->segment_at(tree_end - 1);
  if (before && before->file_begin) {
    auto mapped = container_->to_file_offset(tree_end - 1);
    if (mapped) return *mapped + 1;
  }
  return file_offset_of(tree_end);
}

std::optional<uint32_t> Document::tree_offset_of(uint32_t file_offset) const {
  if (!container_) return file_offset;
  return container_->to_virtual_offset(file_offset);
}

FilePosition Document::position_of_file_offset(uint32_t file_offset) const {
  auto p = file_lines_->position_of(file_offset);
  FilePosition out;
  out.offset = file_offset;
  out.line = p.line + 1;
  out.column = p.char_column + 1;
  out.utf16_column = p.utf16_column;
  return out;
}

}  // namespace rung
