// Range formatting of a file of any kind, for the language server's range and on-type
// formatting: a plain file through format_range; a vendor container (.TcPOU, .EXP) formatted
// piece by piece as `rung fmt` does (format_file_text), of which only the changed lines that
// touch the range are taken — and kept only if they format to the same file as the whole did,
// the check format_range makes for a plain text.
#pragma once

#include <string_view>

#include "formatter/container_format.hpp"

namespace rung::format {

// The engine (format_text) with `settings`, each piece's request combined with `base` (a
// project whose comments do not nest sets base.flat_comments for every piece).
PieceFormatter piece_formatter(const project::FormatSettings& settings, FormatRequest base = {});

// Formats the lines of `file_text` (the decoded file) that intersect `range` (byte offsets of
// `file_text`; a range ending at the start of a line does not take that line). Every other byte
// stays. Status::Unsafe when the range's layout depends on lines outside it.
FileFormatResult format_file_range(containers::ContainerKind kind, std::string_view file_text, TextRange range,
                                   const project::FormatSettings& settings, const FormatRequest& base = {});

}  // namespace rung::format
