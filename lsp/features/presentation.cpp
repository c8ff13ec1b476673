// Presentation: semantic tokens (full, range, delta), folding ranges and selection ranges. The
// answers come from checker/query (name_classes, folding, selection); this file turns them into
// LSP shapes in the file's own coordinates.
#include <memory>

#include "checker/query/folding.hpp"
#include "checker/query/selection.hpp"
#include "lsp/features/features.hpp"
#include "lsp/features/presentation_tokens.hpp"
#include "lsp/json_util.hpp"
#include "lsp/session.hpp"

namespace rung::lsp {
namespace {

constexpr size_t kMaxSelectionDepth = 100;

bool is_removed(const DocumentRef& document) { return document.project->removed.contains(document.source); }

// The semantic tokens of a FILE range of the document.
std::vector<uint32_t> tokens_of(Session& session, const DocumentRef& document, TextRange file_range) {
  if (is_removed(document)) return {};
  const auto names = check::query::classify_names(document.model(), document.source, file_range,
                                                  [&session] { return session.cancelled(); });
  return encode_semantic_tokens(document.document().file_lines(), names);
}

TextRange whole_file(const DocumentRef& document) {
  return {0, static_cast<uint32_t>(document.document().file_text().size())};
}

Json full_tokens(Session& session, SemanticTokenResults& results, const Json& params) {
  const DocumentRef document = session.document(params);
  std::vector<uint32_t> data = tokens_of(session, document, whole_file(document));
  if (session.cancelled()) return nullptr;  // the server answers RequestCancelled
  Json result{{"data", data}};
  result["resultId"] = results.remember(document.uri, std::move(data));
  return result;
}

Json delta_tokens(Session& session, SemanticTokenResults& results, const Json& params) {
  const DocumentRef document = session.document(params);
  const std::string previous_id = json_string(params, "previousResultId");
  const std::vector<uint32_t>* previous = results.previous(document.uri, previous_id);
  if (!previous) return full_tokens(session, results, params);  // unknown or outdated id: everything
  std::vector<uint32_t> data = tokens_of(session, document, whole_file(document));
  if (session.cancelled()) return nullptr;
  Json result{{"edits", semantic_token_edits(*previous, data)}};
  result["resultId"] = results.remember(document.uri, std::move(data));
  return result;
}

Json range_tokens(Session& session, const Json& params) {
  const DocumentRef document = session.document(params);
  const Json& range = json_at(params, {"range"});
  if (!range.is_object()) throw RpcError{ErrorCode::InvalidParams, "params.range is missing"};
  const uint32_t begin = session.offset_of(document, range.value("start", Json()));
  const uint32_t end = session.offset_of(document, range.value("end", Json()));
  return Json{{"data", tokens_of(session, document, {begin, std::max(begin, end)})}};
}

Json folding_ranges(Session& session, const Json& params) {
  const DocumentRef document = session.document(params);
  Json ranges = Json::array();
  if (is_removed(document)) return ranges;
  const Json& limit = json_at(session.client_capabilities(), {"textDocument", "foldingRange", "rangeLimit"});
  const size_t max_ranges = limit.is_number_unsigned() ? limit.get<size_t>() : SIZE_MAX;
  for (const check::query::Fold& fold : check::query::folding_ranges(document.document())) {
    if (ranges.size() >= max_ranges) break;
    Json range{{"startLine", fold.first_line}, {"endLine", fold.last_line}};
    if (fold.kind == check::query::FoldKind::Comment) range["kind"] = "comment";
    if (fold.kind == check::query::FoldKind::Region) range["kind"] = "region";
    ranges.push_back(std::move(range));
  }
  return ranges;
}

Json selection_ranges(Session& session, const Json& params) {
  const DocumentRef document = session.document(params);
  const Json& positions = json_at(params, {"positions"});
  if (!positions.is_array()) throw RpcError{ErrorCode::InvalidParams, "params.positions must be an array"};
  Json result = Json::array();
  for (const Json& position : positions) {
    const uint32_t offset = session.offset_of(document, position);
    std::vector<TextRange> ranges;
    if (!is_removed(document)) ranges = check::query::selection_ranges(document.document(), offset);
    // The protocol wants one answer per position: where nothing is known, the position itself.
    if (ranges.empty()) ranges.push_back({offset, offset});
    // Each range nests in the next: 10,000 nested parentheses must not become a JSON nesting
    // that deep. The innermost and the outermost ones are the ones people expand through.
    if (ranges.size() > kMaxSelectionDepth) {
      ranges.erase(ranges.begin() + kMaxSelectionDepth - 8, ranges.end() - 8);
    }
    Json selection;  // built from the outermost range inwards
    for (auto range = ranges.rbegin(); range != ranges.rend(); ++range) {
      Json inner{{"range", session.range_of(document, *range)}};
      if (!selection.is_null()) inner["parent"] = std::move(selection);
      selection = std::move(inner);
    }
    result.push_back(std::move(selection));
  }
  return result;
}

}  // namespace

void register_presentation(Router& router) {
  auto results = std::make_shared<SemanticTokenResults>();
  router.capabilities()["semanticTokensProvider"] = {
      {"legend", semantic_tokens_legend()}, {"range", true}, {"full", {{"delta", true}}}};
  router.on_request("textDocument/semanticTokens/full",
                    [results](Session& session, const Json& params) { return full_tokens(session, *results, params); });
  router.on_request("textDocument/semanticTokens/full/delta", [results](Session& session, const Json& params) {
    return delta_tokens(session, *results, params);
  });
  router.on_request("textDocument/semanticTokens/range", range_tokens);

  router.capabilities()["foldingRangeProvider"] = true;
  router.on_request("textDocument/foldingRange", folding_ranges);
  router.capabilities()["selectionRangeProvider"] = true;
  router.on_request("textDocument/selectionRange", selection_ranges);
}

}  // namespace rung::lsp
