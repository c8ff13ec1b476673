// Formatting a source file of any kind `rung fmt` reads: a plain ST/IL file as one text; a vendor
// container (TwinCAT .TcPOU/.TcDUT/.TcGVL/.TcIO/.TcITF, CODESYS V2.3 .EXP) piece by piece, so that
// only the ST/IL text inside changes and every other byte of the file (XML markup, ids, export
// markers, visualisations) stays exactly as the vendor tool wrote it.
//
// The pieces are the texts the grammar reads on their own: for TwinCAT each declaration and each
// implementation (of the object, its methods, property accessors, actions and transitions); for
// .EXP each code object (PROGRAM ... END_PROGRAM, ACTION ... END_ACTION, TYPE ... END_TYPE, each
// VAR_GLOBAL ... END_VAR block). PLCopen XML is not formatted: its bodies are spread over many
// XML elements whose layout belongs to the exporting tool.
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "checker/project/format_settings.hpp"
#include "formatter/format.hpp"
#include "parser/containers/container_document.hpp"

namespace rung::format {

// Formats one piece (format_text with the project's settings; tests pass a fake).
using PieceFormatter = std::function<FormatResult(std::string_view piece, const FormatRequest& request)>;

struct FileFormatResult {
  // The whole (decoded) file text. Unless Status::Formatted, the input unchanged; `message` then
  // starts with "line N:" counted in the file, not in the piece.
  FormatResult result;
  // Parts left as they are and why, e.g. "FB_Motor.Run: LD implementation is graphical; not
  // formatted", "PLCopen XML is not formatted".
  std::vector<std::string> notes;
  size_t pieces = 0;  // texts handed to the piece formatter
};

// `file_text` is the decoded file (UTF-8, no BOM); `kind` what containers::detect_container says.
FileFormatResult format_file_text(containers::ContainerKind kind, std::string_view file_text,
                                  const PieceFormatter& format_piece);

// The same with the real engine (format_text) and `settings`.
FileFormatResult format_file_text(containers::ContainerKind kind, std::string_view file_text,
                                  const project::FormatSettings& settings);

}  // namespace rung::format
