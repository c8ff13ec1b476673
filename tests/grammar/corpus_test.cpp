// Runs grammar/test/corpus/*.txt (tree-sitter's corpus format) without the tree-sitter CLI:
// each test's input is parsed with the committed parser and its tree compared with the expected
// S-expression. This is what keeps the committed grammar/src honest in CI.
#include <gtest/gtest.h>

#include <cctype>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "parser/syntax_tree.hpp"
#include "parser/tree_printer.hpp"
#include "tests/support/test_paths.hpp"

namespace rung {
namespace {

struct CorpusCase {
  std::string file;
  std::string name;
  std::string input;
  std::string expected;
  bool skip = false;
  bool expect_error = false;  // ':error' tests only assert that the input does not parse
};

bool is_rule(const std::string& line, char c) {
  if (line.size() < 3) return false;
  size_t n = 0;
  while (n < line.size() && line[n] == c) ++n;
  if (n < 3) return false;
  // tree-sitter allows a suffix after the rule characters (e.g. "===|||"); accept trailing text without spaces.
  return line.find(' ', n) == std::string::npos;
}

std::vector<CorpusCase> read_corpus(const std::filesystem::path& path) {
  std::vector<std::string> lines;
  {
    std::istringstream in(test::read_file(path));
    std::string line;
    while (std::getline(in, line)) {
      if (!line.empty() && line.back() == '\r') line.pop_back();
      lines.push_back(line);
    }
  }
  std::vector<CorpusCase> cases;
  size_t i = 0;
  while (i < lines.size()) {
    if (!is_rule(lines[i], '=')) {
      ++i;
      continue;
    }
    CorpusCase c;
    c.file = path.filename().string();
    size_t j = i + 1;
    std::vector<std::string> header;
    while (j < lines.size() && !is_rule(lines[j], '=')) header.push_back(lines[j++]);
    if (j >= lines.size()) break;
    c.name = header.empty() ? "" : header[0];
    for (const auto& h : header)
      if (h == ":skip")
        c.skip = true;
      else if (h == ":error")
        c.expect_error = true;
    ++j;
    // Input runs to the last '---' line before the next header.
    size_t next = j;
    while (next < lines.size() && !(is_rule(lines[next], '=') && next + 2 < lines.size())) ++next;
    size_t sep = next;
    for (size_t k = j; k < next; ++k)
      if (is_rule(lines[k], '-')) sep = k;
    std::string input, expected;
    for (size_t k = j; k < sep; ++k) input += lines[k] + "\n";
    for (size_t k = sep + 1; k < next; ++k) expected += lines[k] + "\n";
    // tree-sitter drops the single newline that precedes the '---' separator.
    if (input.size() >= 2 && input.substr(input.size() - 2) == "\n\n") input.pop_back();
    if (!input.empty() && input.back() == '\n') input.pop_back();
    c.input = input;
    c.expected = expected;
    cases.push_back(std::move(c));
    i = next;
  }
  return cases;
}

// Canonical form of an S-expression: comments (';' to end of line) dropped, whitespace collapsed,
// no space after '(' or before ')', and field labels ("name: ") removed unless `keep_fields`.
std::string normalize(const std::string& sexp, bool keep_fields) {
  std::string s;
  bool in_comment = false;
  bool in_quote = false;
  for (char c : sexp) {
    if (in_quote) {
      s += c;
      if (c == '"') in_quote = false;
      continue;
    }
    if (c == '"' && !in_comment) {
      in_quote = true;
      s += c;
      continue;
    }
    if (in_comment) {
      if (c == '\n')
        in_comment = false;
      else
        continue;
    }
    if (c == ';') {
      in_comment = true;
      continue;
    }
    bool space = c == ' ' || c == '\n' || c == '\t' || c == '\r';
    if (space) {
      if (!s.empty() && s.back() != ' ' && s.back() != '(') s += ' ';
      continue;
    }
    if (c == ')' && !s.empty() && s.back() == ' ') s.pop_back();
    s += c;
    // A field label is a lower-case word followed by ':' at a token start.
    if (c == ':' && !keep_fields) {
      size_t i = s.size() - 1;
      while (i > 0 && (std::islower(static_cast<unsigned char>(s[i - 1])) || s[i - 1] == '_')) --i;
      if (i < s.size() - 1 && (i == 0 || s[i - 1] == ' ' || s[i - 1] == '(')) {
        s.erase(i);
        in_comment = false;
        // swallow the following space
        while (!s.empty() && s.back() == ' ') s.pop_back();
        if (!s.empty() && s.back() != '(') s += ' ';
      }
    }
  }
  while (!s.empty() && s.back() == ' ') s.pop_back();
  return s;
}

TEST(GrammarCorpus, EveryCorpusTestPasses) {
  auto dir = test::source_dir() / "grammar/test/corpus";
  ASSERT_TRUE(std::filesystem::exists(dir));
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    if (e.path().extension() == ".txt") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  size_t total = 0;
  for (const auto& f : files) {
    for (const auto& c : read_corpus(f)) {
      if (c.skip) continue;
      ++total;
      SyntaxTree tree = SyntaxTree::parse(c.input);
      ASSERT_FALSE(tree.aborted());
      if (c.expect_error) {
        EXPECT_TRUE(tree.root().has_error()) << c.file << ": " << c.name << " should not parse";
        continue;
      }
      bool keep_fields = c.expected.find(": (") != std::string::npos;
      std::string actual = normalize(print_sexp(tree.root()), keep_fields);
      std::string expected = normalize(c.expected, keep_fields);
      EXPECT_EQ(actual, expected) << c.file << ": " << c.name;
    }
  }
  EXPECT_GE(total, 100u) << "the corpus should cover every construct of the grammar";
}

}  // namespace
}  // namespace rung
