// A source file as rung sees it: raw bytes decoded to UTF-8, unwrapped from a vendor container
// when it is one, parsed to a syntax tree, with its syntax diagnostics.
//
// Two coordinate systems meet here. The *tree text* is what the grammar parsed (for a TwinCAT or
// .EXP container, the reader's virtual text). The *file text* is the decoded file the user opens.
// Diagnostics leave this class in file coordinates, so they point at the container's own lines.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "parser/containers/container_document.hpp"
#include "parser/diagnostic.hpp"
#include "parser/source/decode.hpp"
#include "parser/source/line_index.hpp"
#include "parser/syntax_tree.hpp"

namespace rung {

// 1-based line and column (columns count characters; utf16_column is 0-based, for LSP).
struct FilePosition {
  uint32_t offset = 0;
  uint32_t line = 1;
  uint32_t column = 1;
  uint32_t utf16_column = 0;
};

struct DocumentOptions {
  // Files above this size are not parsed: rung reports S011 instead of exhausting memory.
  size_t max_bytes = 256u << 20;
  SyntaxTree::Options parse;
};

class Document {
 public:
  // Never fails: unreadable content becomes diagnostics (S008 encoding, S009 binary, S010 container).
  static Document from_bytes(std::string path, std::string_view bytes, const DocumentOptions& options = {});
  // Reads the file; nullopt and `error` set when it cannot be read.
  static std::optional<Document> load(const std::filesystem::path& path, std::string* error,
                                      const DocumentOptions& options = {});

  const std::string& path() const { return path_; }
  std::string_view file_text() const { return decoded_->utf8; }
  source::Encoding encoding() const { return decoded_->encoding; }
  bool had_bom() const { return decoded_->had_bom; }
  const source::LineIndex& file_lines() const { return *file_lines_; }

  // Null when the file was not parsed (binary, too large).
  const SyntaxTree* tree() const { return tree_ ? &*tree_ : nullptr; }
  SyntaxTree* mutable_tree() { return tree_ ? &*tree_ : nullptr; }
  const containers::ContainerDocument* container() const { return container_ ? &*container_ : nullptr; }

  // Maps an offset of the tree text to the file text (identity for plain files). Offsets inside
  // text a container reader synthesized map to the start of the next real segment.
  uint32_t file_offset_of(uint32_t tree_offset) const;
  // The same for the END of a range: an end right after real text maps to the end of that text,
  // not to the start of the next real segment (which may be lines further down the XML).
  uint32_t file_end_offset_of(uint32_t tree_end) const;
  // The inverse, for editors that point into the file: nullopt where the file has no parsed text
  // there (XML markup around a TwinCAT declaration, a blanked .EXP visualisation).
  std::optional<uint32_t> tree_offset_of(uint32_t file_offset) const;
  FilePosition position_of_file_offset(uint32_t file_offset) const;
  FilePosition position_of_tree_offset(uint32_t tree_offset) const {
    return position_of_file_offset(file_offset_of(tree_offset));
  }

  // All diagnostics (syntax, encoding, container) with ranges in FILE coordinates, sorted.
  const std::vector<Diagnostic>& diagnostics() const { return diagnostics_; }

  // The text the tree was first read from: the decoded file, or a container's virtual text.
  std::string_view source_text() const { return container_ ? container_->virtual_text : decoded_->utf8; }
  // The same file read from `tree_text`, a rewrite of source_text() with the same length and line
  // ends (conditional compilation blanks its inactive branches): a new tree and new syntax
  // diagnostics; file text, container and encoding findings stay. The first-branch fallback of
  // build() is not tried: the rewrite has already chosen the branches.
  Document reread(std::string tree_text) const;

 private:
  Document() = default;
  void build(std::string_view bytes, const DocumentOptions& options);
  // Parses `tree_text` and adds its syntax diagnostics to the reading ones.
  void parse(std::string tree_text, const DocumentOptions& options, bool try_first_branches);

  std::string path_;
  // Behind a pointer so the text stays put when the Document moves: file_lines_ views it.
  std::unique_ptr<source::DecodedText> decoded_ = std::make_unique<source::DecodedText>();
  std::unique_ptr<source::LineIndex> file_lines_;
  std::optional<containers::ContainerDocument> container_;
  std::optional<SyntaxTree> tree_;
  std::vector<Diagnostic> diagnostics_;
  std::vector<Diagnostic> reading_diagnostics_;  // encoding and container findings (no syntax)
};

}  // namespace rung
