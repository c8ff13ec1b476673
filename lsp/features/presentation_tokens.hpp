// Semantic tokens (LSP 3.17): the legend the server announces, the encoding of classified names
// as the protocol's relative integers, and the previous result of each document that delta
// requests are answered against.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "checker/query/name_classes.hpp"
#include "lsp/json_rpc.hpp"
#include "parser/source/line_index.hpp"

namespace rung::lsp {

// {tokenTypes, tokenModifiers} of SemanticTokensLegend.
Json semantic_tokens_legend();

// The tokens of `names` (FILE ranges of the text `lines` indexes, in file order) as LSP encodes
// them: five integers a token (line delta, start delta in UTF-16 units, length, type, modifiers).
std::vector<uint32_t> encode_semantic_tokens(const source::LineIndex& lines,
                                             const std::vector<check::query::ClassifiedName>& names);

// SemanticTokensEdit[] that turn `before` into `after`: one edit replacing the part between
// their common beginning and common end (none when they are equal).
Json semantic_token_edits(const std::vector<uint32_t>& before, const std::vector<uint32_t>& after);

// The last result sent for each document (by URI), so that a delta request can answer with the
// edits since then. Bounded: the results of the least recently served documents are dropped.
class SemanticTokenResults {
 public:
  // Stores `data` as the document's latest result; returns its resultId.
  std::string remember(const std::string& uri, std::vector<uint32_t> data);
  // The data sent for `uri` under `result_id`, if it is still the latest one.
  const std::vector<uint32_t>* previous(const std::string& uri, const std::string& result_id) const;

  static constexpr size_t kMaxDocuments = 64;

 private:
  struct Entry {
    std::string result_id;
    std::vector<uint32_t> data;
    uint64_t serial = 0;
  };
  std::map<std::string, Entry, std::less<>> entries_;
  uint64_t next_serial_ = 1;
};

}  // namespace rung::lsp
