// Formatting: whole document, a range, and on-type formatting after ';' and a line break. The
// formatter decides everything (formatter/: format_file_text, format_file_range), including
// its safety check: a file with syntax errors, or a result whose tokens differ from the input,
// gives no edits.
#include <filesystem>

#include "formatter/file_range_format.hpp"
#include "lsp/features/features.hpp"
#include "lsp/features/formatting_edits.hpp"
#include "lsp/json_util.hpp"
#include "lsp/session.hpp"

namespace rung::lsp {
namespace {

containers::ContainerKind kind_of(const Document& document) {
  return document.container() ? document.container()->kind : containers::ContainerKind::None;
}

format::FormatRequest request_of(const DocumentRef& document) {
  // OpenPCS comments do not nest; `rung fmt` reads them the same way.
  return format::FormatRequest{.flat_comments = document.settings().profile == project::Profile::Openpcs};
}

bool is_removed(const DocumentRef& document) { return document.project->removed.contains(document.source); }

// The file as the log names it: its path in the project.
std::string display_name(const DocumentRef& document) {
  const std::filesystem::path path = std::filesystem::path(document.document().path()).lexically_normal();
  const std::filesystem::path relative = path.lexically_relative(document.project->root.lexically_normal());
  return relative.empty() || *relative.begin() == ".." ? path.generic_string() : relative.generic_string();
}

// The edits of a formatting result; a file left unformatted is said in the log when the user
// asked for formatting explicitly (on-type formatting stays quiet: half-typed code is normal).
Json edits_of(const Session& session, const DocumentRef& document, const format::FileFormatResult& formatted,
              bool explain) {
  if (formatted.result.status != format::Status::Formatted) {
    if (explain) {
      const bool unsafe = formatted.result.status == format::Status::Unsafe;
      session.log(unsafe ? 2 : 3, display_name(document) + " not formatted: " + formatted.result.message);
    }
    return Json::array();
  }
  return line_edits(session, document, formatted.result.text);
}

project::FormatSettings settings_of(const DocumentRef& document, const Json& params) {
  return formatting_settings(document.project->config, json_at(params, {"options"}));
}

Json format_document(Session& session, const Json& params) {
  const DocumentRef document = session.document(params);
  if (is_removed(document)) return Json::array();
  const Document& file = document.document();
  const format::FileFormatResult formatted = format::format_file_text(
      kind_of(file), file.file_text(), format::piece_formatter(settings_of(document, params), request_of(document)));
  return edits_of(session, document, formatted, true);
}

Json format_lines(Session& session, const DocumentRef& document, const Json& params, TextRange range, bool explain) {
  const Document& file = document.document();
  const format::FileFormatResult formatted = format::format_file_range(
      kind_of(file), file.file_text(), range, settings_of(document, params), request_of(document));
  return edits_of(session, document, formatted, explain);
}

Json format_range(Session& session, const Json& params) {
  const DocumentRef document = session.document(params);
  const Json& range = json_at(params, {"range"});
  if (!range.is_object()) throw RpcError{ErrorCode::InvalidParams, "params.range is missing"};
  const uint32_t begin = session.offset_of(document, range.value("start", Json()));
  const uint32_t end = session.offset_of(document, range.value("end", Json()));
  if (is_removed(document)) return Json::array();
  return format_lines(session, document, params, {begin, std::max(begin, end)}, true);
}

// Where the statement or declaration that ends at the ';' before `file_offset` starts; the
// start of the ';''s line when it ends none.
uint32_t statement_start(const Document& file, uint32_t file_offset) {
  const source::LineIndex& lines = file.file_lines();
  const uint32_t line_start = lines.line_start(lines.position_of(file_offset).line);
  const SyntaxTree* tree = file.tree();
  const std::optional<uint32_t> at = file_offset > 0 ? file.tree_offset_of(file_offset - 1) : std::nullopt;
  if (!tree || tree->aborted() || !at) return line_start;
  for (SyntaxNode node = tree->root().descendant_for_range(*at, *at + 1); node; node = node.parent()) {
    const std::string_view kind = node.kind();
    if (kind.ends_with("_statement") || kind == "var_declaration") {
      return std::min(line_start, file.file_offset_of(node.begin()));
    }
  }
  return line_start;
}

Json format_on_type(Session& session, const Json& params) {
  const DocumentRef document = session.document(params);
  const uint32_t offset = session.offset_of(document, json_at(params, {"position"}));
  if (is_removed(document)) return Json::array();
  const Document& file = document.document();
  const source::LineIndex& lines = file.file_lines();
  const std::string typed = json_string(params, "ch");
  if (typed == ";") return format_lines(session, document, params, {statement_start(file, offset), offset}, false);
  if (typed == "\n") {
    // The line just ended; the new line (the cursor's) keeps the indentation the editor gave it.
    const uint32_t line = lines.position_of(offset).line;
    if (line == 0) return Json::array();
    return format_lines(session, document, params, {lines.line_start(line - 1), lines.line_end(line - 1)}, false);
  }
  return Json::array();
}

}  // namespace

void register_formatting(Router& router) {
  router.capabilities()["documentFormattingProvider"] = true;
  router.on_request("textDocument/formatting", format_document);
  router.capabilities()["documentRangeFormattingProvider"] = true;
  router.on_request("textDocument/rangeFormatting", format_range);
  router.capabilities()["documentOnTypeFormattingProvider"] = {{"firstTriggerCharacter", ";"},
                                                               {"moreTriggerCharacter", {"\n"}}};
  router.on_request("textDocument/onTypeFormatting", format_on_type);
}

}  // namespace rung::lsp
