#include "formatter/file_range_format.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "formatter/range_format.hpp"

namespace rung::format {
namespace {

size_t line_of(std::string_view text, uint32_t offset) {
  offset = std::min<uint32_t>(offset, static_cast<uint32_t>(text.size()));
  return static_cast<size_t>(std::count(text.begin(), text.begin() + offset, '\n'));
}

bool is_container(containers::ContainerKind kind) {
  return kind == containers::ContainerKind::TwinCat || kind == containers::ContainerKind::CodesysExp ||
         kind == containers::ContainerKind::PlcOpen;
}

}  // namespace

PieceFormatter piece_formatter(const project::FormatSettings& settings, FormatRequest base) {
  return [settings, base](std::string_view piece, const FormatRequest& request) {
    FormatRequest combined = request;
    combined.flat_comments = combined.flat_comments || base.flat_comments;
    return format_text(piece, settings, combined);
  };
}

FileFormatResult format_file_range(containers::ContainerKind kind, std::string_view file_text, TextRange range,
                                   const project::FormatSettings& settings, const FormatRequest& base) {
  if (!is_container(kind)) {
    FileFormatResult plain;
    plain.result = format_range(file_text, range, settings, base);
    plain.pieces = 1;
    return plain;
  }
  const PieceFormatter engine = piece_formatter(settings, base);
  FileFormatResult whole = format_file_text(kind, file_text, engine);
  if (whole.result.status != Status::Formatted || !whole.result.changed) return whole;

  const size_t first = line_of(file_text, range.begin);
  const size_t last = line_of(file_text, range.end > range.begin ? range.end - 1 : range.begin);
  TakenLines taken = take_changed_lines(file_text, whole.result.text, first, last);
  FileFormatResult out;
  out.notes = std::move(whole.notes);
  out.pieces = whole.pieces;
  out.result.changed = taken.text != file_text;
  out.result.text = std::move(taken.text);
  // As in format_range: the lines taken must be the formatter's own line-by-line changes, so the
  // partial file formats to the same file as the whole one did.
  if (out.result.changed && format_file_text(kind, out.result.text, engine).result.text != whole.result.text) {
    out.result.status = Status::Unsafe;
    out.result.text = std::string(file_text);
    out.result.changed = false;
    out.result.message = fmt::format(
        "line {}: the formatting of the range depends on lines outside it; format the whole file instead",
        taken.first_line.value_or(first) + 1);
  }
  return out;
}

}  // namespace rung::format
