// The result of unwrapping a vendor container file.
//
// The grammar parses one text per file. For a container (TwinCAT XML, CODESYS
// .EXP) the reader builds a *virtual text* for the grammar and a list of
// segments that map every virtual byte back to the container file's own
// (decoded) text, so that diagnostics point at the container's own lines.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rung::containers {

enum class ContainerKind {
  None,         // not a container: an ordinary source file, the virtual text is the file text
  TwinCat,      // .TcPOU .TcDUT .TcGVL .TcIO .TcITF
  CodesysExp,   // CODESYS V2.3 .EXP export
  PlcOpen,      // PLCopen XML (TC6 v2.00/v2.01): CODESYS V3 exports, Beremiz/OpenPLC plc.xml
  Unsupported,  // a container holding no PLC source (e.g. .TcTTO task objects): skipped
};

std::string_view container_kind_name(ContainerKind kind);

struct Segment {
  uint32_t virtual_begin = 0;
  uint32_t length = 0;
  // Offset in the decoded file text of the segment's first byte; byte k of the
  // segment is file byte *file_begin + k. nullopt: synthetic text the reader inserted.
  std::optional<uint32_t> file_begin;
  // What the text is: "declaration", "implementation", "method M/declaration",
  // "property P/get/implementation", "action A", "transition T", "separator", ...
  std::string role;
  std::string object_name;  // the POU/DUT/GVL/interface the text belongs to
};

struct ContainerIssue {
  uint32_t offset = 0;  // in the decoded file text
  std::string message;
};

// One object found in the container (several in an .EXP file).
struct ContainerObject {
  std::string name;
  // TwinCAT: "POU", "DUT", "GVL", "ITF", "METHOD", "PROPERTY", "ACTION", "TRANSITION".
  // .EXP: "PROGRAM", "FUNCTION_BLOCK", "FUNCTION", "TYPE", "GVL", "VAR_CONFIG", "ACTION",
  //       and for non-code sections the section keyword, e.g. "VISUALISATION", "LIBRARY".
  std::string kind;
  uint32_t file_offset = 0;     // start of the object in the decoded file text
  std::string path;             // .EXP @PATH folder, "\/" unescaped to "/" ("" at the root)
  bool nested_comments = true;  // .EXP "(* @NESTEDCOMMENTS := 'No' *)" makes it false
  // Language of the implementation: "ST", "IL", "SFC" (text); "LD", "FBD", "CFC",
  // "NWL" (graphical, not given to the grammar); "" when there is none (DUT, GVL...).
  std::string language;
  // A remark that is not an error, e.g. why a body was left out of the virtual text.
  std::string note;
};

struct ContainerDocument {
  ContainerKind kind = ContainerKind::None;
  std::string virtual_text;
  // Sorted by virtual_begin, contiguous, covering virtual_text exactly.
  std::vector<Segment> segments;
  std::vector<ContainerIssue> issues;
  std::vector<ContainerObject> objects;

  // The segment holding a virtual byte (O(log n)); nullptr when there is none.
  const Segment* segment_at(uint32_t virtual_offset) const;

  // Virtual -> file offset. For a byte of real text: the byte it was copied from.
  // For synthetic text: the file offset where the next real segment starts (so a
  // diagnostic on an inserted "GET" line lands on the getter's own text); if no
  // real segment follows, the end of the previous one; nullopt only when the
  // document has no real text at all. The end of the virtual text maps to the
  // end of the last real segment. Offsets past the end clamp to the end.
  std::optional<uint32_t> to_file_offset(uint32_t virtual_offset) const;

  // File -> virtual offset (for the language server: a cursor in the container
  // file). nullopt when the file offset is not inside text the grammar sees
  // (XML markup, a skipped graphical body). The end of a real segment counts as
  // inside it, so a cursor after the last character of a body still maps.
  std::optional<uint32_t> to_virtual_offset(uint32_t file_offset) const;

  // Readers call this once the segments are final; it builds the file-order
  // index behind to_virtual_offset. (Without it, to_virtual_offset falls back
  // to a linear scan.)
  void build_index();

 private:
  std::vector<uint32_t> by_file_;  // indices of real segments, ordered by file_begin
  size_t indexed_segments_ = 0;    // segments.size() when the index was built
};

// Builds a virtual text segment by segment. Adjacent pieces of the same role and
// object merge when both are synthetic or they are contiguous in the file.
class VirtualTextBuilder {
 public:
  void append_real(std::string_view text, uint32_t file_begin, std::string_view role, std::string_view object_name);
  void append_synthetic(std::string_view text, std::string_view role, std::string_view object_name);
  bool empty() const { return doc_.virtual_text.empty(); }
  uint32_t size() const { return static_cast<uint32_t>(doc_.virtual_text.size()); }

  // Hands over the document (index built); the builder is left empty.
  ContainerDocument finish(ContainerKind kind);

 private:
  void append(std::string_view text, std::optional<uint32_t> file_begin, std::string_view role,
              std::string_view object_name);
  ContainerDocument doc_;
};

// A plain text file as a document: one real segment, identity mapping.
ContainerDocument plain_document(std::string_view text, ContainerKind kind = ContainerKind::None);

}  // namespace rung::containers
