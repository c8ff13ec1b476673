// `rung parse ../shared/corpus/seeds` must report no syntax error in any example whose header does
// not say it is wrong or incomplete. The examples that do fail are pinned, with the reason, in
// seed_corpus_failures.txt; this test fails on any new failure AND on any pinned file that now
// parses (so the list stays honest). RUNG_UPDATE_GOLDEN=1 rewrites the list's file names.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <map>
#include <sstream>

#include "parser/document.hpp"
#include "parser/file_walk.hpp"
#include "tests/support/test_paths.hpp"

namespace rung {
namespace {

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// The sentence of a header that says the example is defective, or "" when none does.
std::string defect_phrase(const std::string& header);

// Words with which the corpus headers say an example is not valid code as written.
bool header_admits_defect(const std::string& header) {
  return !defect_phrase(header).empty();
}

std::string defect_phrase(const std::string& header) {
  static const char* kWords[] = {"wrong",
                                 "incorrect",
                                 "error",
                                 "incomplete",
                                 "fragment",
                                 "typo",
                                 "missing",
                                 "elided",
                                 "elision",
                                 "lost",
                                 "artifact",
                                 "garbled",
                                 "invalid",
                                 "illegal",
                                 "reject",
                                 "not valid",
                                 "omit",
                                 "truncated",
                                 "pseudo",
                                 "not compil",
                                 "broken",
                                 "mistake",
                                 "mangled",
                                 "unbalanced",
                                 "as printed",
                                 "printed without",
                                 "(kept)",
                                 "placeholder",
                                 "not implemented",
                                 "ellipsis",
                                 "does not compile",
                                 "not supported",
                                 "instead of",
                                 "lacks",
                                 "should be"};
  std::string h = lower(header);
  for (const char* w : kWords) {
    size_t at = h.find(w);
    if (at == std::string::npos) continue;
    // The clause around the word, for the pinned list's reason column.
    size_t begin = h.find_last_of(";.\n", at);
    begin = begin == std::string::npos ? 0 : begin + 1;
    size_t end = h.find_first_of(";\n", at);
    std::string phrase = header.substr(begin, (end == std::string::npos ? h.size() : end) - begin);
    size_t first = phrase.find_first_not_of(' ');
    return phrase.substr(first == std::string::npos ? 0 : first, 160);
  }
  return {};
}

// An example whose code has an elision line ("...", "…", a row of dots) is visibly incomplete.
bool body_has_elision(const std::string& text) {
  size_t i = 0;
  while (i < text.size()) {
    size_t eol = text.find('\n', i);
    if (eol == std::string::npos) eol = text.size();
    std::string line = text.substr(i, eol - i);
    size_t a = line.find_first_not_of(" \t\r");
    size_t b = line.find_last_not_of(" \t\r");
    if (a != std::string::npos) {
      std::string core = line.substr(a, b - a + 1);
      if (core == "..." || core == "...." || core == "\xE2\x80\xA6" || core == "......" || core == ".") return true;
    }
    i = eol + 1;
  }
  return false;
}

// The header of a seed example: the comments before its first line of code (source, expected
// behaviour, and notes on what the manual printed).
std::string leading_comments(const std::string& text) {
  size_t i = 0;
  std::string header;
  while (true) {
    while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
    if (text.compare(i, 2, "(*") != 0) break;
    size_t end = text.find("*)", i);
    if (end == std::string::npos) end = text.size();
    header += text.substr(i, end - i) + "\n";
    i = end + 2;
  }
  return header;
}

std::map<std::string, std::string> read_pinned(const std::filesystem::path& path) {
  std::map<std::string, std::string> pinned;
  std::istringstream in(test::read_file(path));
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    size_t sep = line.find(' ');
    std::string file = line.substr(0, sep);
    std::string reason = sep == std::string::npos ? "" : line.substr(line.find_first_not_of(' ', sep));
    pinned[file] = reason;
  }
  return pinned;
}

TEST(SeedCorpus, OnlyExamplesMarkedWrongOrIncompleteFailToParse) {
  auto root = test::shared_dir() / "corpus/seeds";
  ASSERT_TRUE(std::filesystem::exists(root)) << "the shared corpus must be at " << root;
  WalkResult walk = collect_source_files({root});
  ASSERT_GT(walk.files.size(), 400u);

  std::map<std::string, std::string> failing;  // relative path -> first error
  for (const auto& file : walk.files) {
    std::string error;
    auto doc = Document::load(file, &error);
    ASSERT_TRUE(doc) << error;
    for (const auto& d : doc->diagnostics()) {
      if (d.severity != Severity::Error) continue;
      FilePosition p = doc->position_of_file_offset(d.range.begin);
      failing[std::filesystem::relative(file, root).string()] =
          std::to_string(p.line) + ":" + std::to_string(p.column) + " " + d.code + " " + d.message;
      break;
    }
  }

  auto list_path = test::source_dir() / "tests/parser/seed_corpus_failures.txt";
  auto pinned = read_pinned(list_path);
  if (test::update_golden()) {
    std::string out =
        "# Seed examples that do not parse, each with the reason from its own header.\n"
        "# Pinned by tests/parser/seed_corpus_test.cpp; keep it short.\n";
    for (const auto& [file, first_error] : failing) {
      std::string text = test::read_file(root / file);
      std::string phrase = defect_phrase(leading_comments(text));
      if (phrase.empty() && body_has_elision(text)) phrase = "code contains an elision line (...)";
      out += file;
      out += "  ";
      out += phrase.empty() ? "TODO header does not admit a defect" : phrase;
      out += "  [rung: ";
      out += first_error;
      out += "]\n";
    }
    test::write_file(list_path, out);
    return;
  }

  for (const auto& [file, first_error] : failing) {
    EXPECT_TRUE(pinned.count(file)) << file << " no longer parses: " << first_error;
  }
  for (const auto& [file, reason] : pinned) {
    EXPECT_TRUE(failing.count(file)) << file << " parses now: remove it from seed_corpus_failures.txt";
    EXPECT_FALSE(reason.empty() || reason.rfind("TODO", 0) == 0) << file << ": pinned without a reason";
    // The pin is only legitimate if the example's own header says it is wrong or incomplete.
    std::string text = test::read_file(root / file);
    EXPECT_TRUE(header_admits_defect(leading_comments(text)) || body_has_elision(text))
        << file << ": header does not say the example is wrong or incomplete";
  }
}

}  // namespace
}  // namespace rung
