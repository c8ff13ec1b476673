// Every editor query in grammar/queries must compile against the committed grammar: a query that
// names a node or field the grammar no longer has breaks highlighting in Neovim and Helix.
#include <gtest/gtest.h>
#include <tree_sitter/api.h>

#include <filesystem>

#include "parser/syntax_tree.hpp"
#include "tests/support/test_paths.hpp"

namespace rung {
namespace {

const char* error_name(TSQueryError e) {
  switch (e) {
    case TSQueryErrorSyntax: return "syntax";
    case TSQueryErrorNodeType: return "unknown node type";
    case TSQueryErrorField: return "unknown field";
    case TSQueryErrorCapture: return "capture";
    case TSQueryErrorStructure: return "impossible pattern";
    case TSQueryErrorLanguage: return "language";
    default: return "none";
  }
}

TEST(GrammarQueries, AllQueriesCompile) {
  auto dir = test::source_dir() / "grammar/queries";
  ASSERT_TRUE(std::filesystem::exists(dir));
  std::vector<std::string> seen;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    if (e.path().extension() != ".scm") continue;
    std::string source = test::read_file(e.path());
    uint32_t offset = 0;
    TSQueryError error = TSQueryErrorNone;
    TSQuery* q =
        ts_query_new(tree_sitter_iec61131(), source.data(), static_cast<uint32_t>(source.size()), &offset, &error);
    EXPECT_NE(q, nullptr) << e.path().filename() << ": " << error_name(error) << " error at byte " << offset << ": "
                          << source.substr(offset, 40);
    if (q) {
      EXPECT_GT(ts_query_pattern_count(q), 0u) << e.path().filename();
      ts_query_delete(q);
    }
    seen.push_back(e.path().stem().string());
  }
  for (const char* required : {"highlights", "locals", "folds", "indents", "injections", "tags"}) {
    EXPECT_NE(std::find(seen.begin(), seen.end(), required), seen.end()) << "missing queries/" << required << ".scm";
  }
}

}  // namespace
}  // namespace rung
