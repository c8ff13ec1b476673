// Session: the feature API (documents and position conversion) and the notifications it sends.
#include "lsp/session.hpp"

#include "lsp/uri.hpp"

namespace rung::lsp {

Session::Session(Sink sink, check::LoadOptions load_options) : sink_(std::move(sink)), projects_(load_options) {}

std::string Session::key_of_uri(std::string_view uri) const {
  // Non-file URIs (untitled:, a diff view's git:) are keys of their own: such a buffer is
  // checked alone, with the defaults.
  if (const auto path = path_of_uri(uri)) return ProjectSet::key_of(*path);
  return std::string(uri);
}

std::optional<DocumentRef> Session::find_document(std::string_view uri) {
  const auto file = projects_.find(key_of_uri(uri));
  if (!file) return std::nullopt;
  return DocumentRef{file->project, file->source, std::string(uri)};
}

DocumentRef Session::document(const Json& params) {
  const Json* uri = nullptr;
  if (params.is_object()) {
    const auto text_document = params.find("textDocument");
    if (text_document != params.end() && text_document->is_object()) {
      const auto found = text_document->find("uri");
      if (found != text_document->end() && found->is_string()) uri = &*found;
    }
  }
  if (!uri) throw RpcError{ErrorCode::InvalidParams, "params.textDocument.uri is missing"};
  auto document = find_document(uri->get_ref<const std::string&>());
  if (!document) throw RpcError{ErrorCode::InvalidParams, "unknown document " + uri->get<std::string>()};
  return *document;
}

const OpenDocument* Session::open_document(std::string_view uri) const {
  const auto found = open_.find(uri);
  return found == open_.end() ? nullptr : &found->second;
}

uint32_t Session::offset_of(const DocumentRef& document, const Json& position) const {
  if (!position.is_object() || !position.contains("line") || !position.contains("character") ||
      !position["line"].is_number_integer() || !position["character"].is_number_integer() ||
      position["line"].get<int64_t>() < 0 || position["character"].get<int64_t>() < 0) {
    throw RpcError{ErrorCode::InvalidParams, "position must be {line, character} with non-negative integers"};
  }
  const source::LineIndex& lines = document.document().file_lines();
  const uint64_t line = position["line"].get<uint64_t>();
  const uint64_t character = position["character"].get<uint64_t>();
  if (line >= lines.line_count()) return lines.line_end(lines.line_count() - 1);
  return lines.offset_of_utf16(static_cast<uint32_t>(line), static_cast<uint32_t>(std::min<uint64_t>(character, UINT32_MAX)));
}

std::optional<Json> Session::position_from_offset(const Document& document, uint32_t file_offset) const {
  const source::Position position = document.file_lines().position_of(file_offset);
  return Json{{"line", position.line}, {"character", position.utf16_column}};
}

Json Session::position_of(const DocumentRef& document, uint32_t file_offset) const {
  return *position_from_offset(document.document(), file_offset);
}

Json Session::range_of(const DocumentRef& document, TextRange file_range) const {
  return range_in(*document.project, document.source, file_range);
}

Json Session::range_in(const Project& project, check::SourceId source, TextRange file_range) const {
  const Document& document = *project.model().source(source).document;
  return Json{{"start", *position_from_offset(document, file_range.begin)},
              {"end", *position_from_offset(document, std::max(file_range.begin, file_range.end))}};
}

std::string Session::uri_of(const Project& project, check::SourceId source) const {
  const std::string& path = project.model().source(source).document->path();
  // A loose buffer with a non-file URI is known by that URI.
  if (project.loose && path.find(':') != std::string::npos && path.front() != '/') return path;
  return uri_of_path(ProjectSet::key_of(path));
}

Json Session::location_of(const Project& project, const check::query::Location& location) const {
  return Json{{"uri", uri_of(project, location.source)}, {"range", range_in(project, location.source, location.range)}};
}

void Session::notify(std::string_view method, Json params) const {
  sink_(make_notification(method, std::move(params)));
}

void Session::log(int type, std::string_view message) const {
  notify("window/logMessage", Json{{"type", type}, {"message", std::string(message)}});
}

}  // namespace rung::lsp
