// The seed examples of the four manuals and the facts taken from their digests, each checked
// alone against the expectation written for it (tests/checker/seeds/README.md says the format):
// a wrong example must get the code its manual's message corresponds to, a valid one must check
// without errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "checker/check.hpp"
#include "tests/support/test_paths.hpp"

namespace rung::check {
namespace {

namespace fs = std::filesystem;

struct Expectation {
  std::string name;  // the GoogleTest name: seed_000a_016_bool_assign_int_error_st
  fs::path file;
  std::string origin;  // where the expectation is written (tsv file:line or the fact file)
  project::Profile profile = project::Profile::Codesys;
  std::vector<std::string> expect;  // {"clean"}, {"fragment"}, {"-"} or CODE / CODE@LINE items
  std::string status;               // ok, gap, skip
  std::string note;
};

// GoogleTest prints a failing case's parameter: the row or file it comes from.
void PrintTo(const Expectation& expectation, std::ostream* out) {
  *out << expectation.origin;
}

std::string test_name(std::string_view prefix, std::string_view path) {
  std::string name(prefix);
  for (char c : path) name += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  return name;
}

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::string part;
  std::istringstream stream(text);
  while (std::getline(stream, part, separator)) parts.push_back(part);
  return parts;
}

std::string trim(std::string text) {
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string::npos) return {};
  const auto last = text.find_last_not_of(" \t\r");
  return text.substr(first, last - first + 1);
}

std::vector<std::string> words(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream stream(text);
  for (std::string word; stream >> word;) out.push_back(word);
  return out;
}

// An unreadable expectation is itself a failing test (named after where it is written), so a
// typo never silently drops a check.
Expectation malformed(std::string origin, std::string why) {
  Expectation broken;
  broken.name = test_name("malformed_", origin);
  broken.origin = std::move(origin);
  broken.status = "malformed";
  broken.note = std::move(why);
  return broken;
}

void read_seed_table(const fs::path& table, std::vector<Expectation>& out) {
  const fs::path seeds = rung::test::shared_dir() / "corpus" / "seeds";
  std::ifstream in(table);
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    const std::string origin = table.filename().string() + ":" + std::to_string(number);
    if (trim(line).empty() || trim(line)[0] == '#') continue;
    std::vector<std::string> fields = split(line, '\t');
    if (fields.size() < 4) {
      out.push_back(malformed(origin, "a row needs path, profile, expect and status separated by tabs"));
      continue;
    }
    Expectation expectation;
    expectation.name = test_name("seed_", trim(fields[0]));
    expectation.file = seeds / trim(fields[0]);
    expectation.origin = origin;
    auto profile = project::parse_profile(trim(fields[1]));
    if (!profile) {
      out.push_back(malformed(origin, "unknown profile '" + fields[1] + "'"));
      continue;
    }
    expectation.profile = *profile;
    expectation.expect = words(fields[2]);
    expectation.status = trim(fields[3]);
    if (fields.size() > 4) expectation.note = trim(fields[4]);
    out.push_back(std::move(expectation));
  }
}

// First line: (* fact: 000a.md#12 | profile: codesys | expect: E101@4 | status: ok | note: ... *)
void read_fact_file(const fs::path& file, std::vector<Expectation>& out) {
  const std::string origin = fs::relative(file, rung::test::source_dir() / "tests" / "checker" / "facts").string();
  std::ifstream in(file);
  std::string header;
  std::getline(in, header);
  const auto open = header.find("(*");
  const auto close = header.rfind("*)");
  if (open == std::string::npos || close == std::string::npos || close < open) {
    out.push_back(malformed(origin, "the first line must be the (* fact: ... *) header"));
    return;
  }
  Expectation expectation;
  expectation.name = test_name("fact_", origin);
  expectation.file = file;
  expectation.origin = "tests/checker/facts/" + origin;
  for (const std::string& field : split(header.substr(open + 2, close - open - 2), '|')) {
    const auto colon = field.find(':');
    if (colon == std::string::npos) continue;
    const std::string key = trim(field.substr(0, colon));
    const std::string value = trim(field.substr(colon + 1));
    if (key == "profile") {
      auto profile = project::parse_profile(value);
      if (!profile) {
        out.push_back(malformed(origin, "unknown profile '" + value + "'"));
        return;
      }
      expectation.profile = *profile;
    } else if (key == "expect") {
      expectation.expect = words(value);
    } else if (key == "status") {
      expectation.status = value;
    } else if (key == "note") {
      expectation.note = value;
    }
  }
  out.push_back(std::move(expectation));
}

std::vector<Expectation> all_expectations() {
  std::vector<Expectation> all;
  const fs::path checker_tests = rung::test::source_dir() / "tests" / "checker";
  std::vector<fs::path> tables;
  for (const auto& entry : fs::directory_iterator(checker_tests / "seeds")) {
    if (entry.path().extension() == ".tsv") tables.push_back(entry.path());
  }
  std::sort(tables.begin(), tables.end());
  for (const fs::path& table : tables) read_seed_table(table, all);
  std::vector<fs::path> facts;
  if (fs::exists(checker_tests / "facts")) {
    for (const auto& entry : fs::recursive_directory_iterator(checker_tests / "facts")) {
      if (entry.is_regular_file() && entry.path().extension() != ".md") facts.push_back(entry.path());
    }
  }
  std::sort(facts.begin(), facts.end());
  for (const fs::path& fact : facts) read_fact_file(fact, all);
  return all;
}

const std::vector<Expectation>& expectations() {
  static const std::vector<Expectation> all = all_expectations();
  return all;
}

std::string describe(const FileDiagnostics& result, const Workspace& workspace) {
  std::string text;
  const auto id = result.source;
  for (const Diagnostic& diagnostic : result.diagnostics) {
    const FilePosition position =
        workspace.model().source(id).document->position_of_file_offset(diagnostic.range.begin);
    text += "  " + diagnostic.code + "@" + std::to_string(position.line) + " " +
            (diagnostic.severity == Severity::Error ? "error" : "warning") + ": " + diagnostic.message + "\n";
  }
  return text.empty() ? "  (nothing)\n" : text;
}

class Expectations : public ::testing::TestWithParam<Expectation> {};

TEST_P(Expectations, Check) {
  const Expectation& expectation = GetParam();
  ASSERT_NE(expectation.status, "malformed") << expectation.origin << ": " << expectation.note;
  ASSERT_TRUE(expectation.status == "ok" || expectation.status == "gap" || expectation.status == "skip")
      << expectation.origin << ": status must be ok, gap or skip, not '" << expectation.status << "'";
  if (expectation.status == "skip") GTEST_SKIP() << "nothing to check at compile time: " << expectation.note;
  if (expectation.status == "gap") GTEST_SKIP() << "not reported yet: " << expectation.note;
  ASSERT_FALSE(expectation.expect.empty()) << expectation.origin << ": no expectation";
  ASSERT_TRUE(fs::exists(expectation.file)) << expectation.origin << ": " << expectation.file << " does not exist";

  project::ProjectConfig config;
  config.profile = expectation.profile;
  auto workspace = Workspace::load_files({expectation.file}, config);
  ASSERT_TRUE(workspace->load_errors.empty()) << workspace->load_errors.front();
  const std::vector<FileDiagnostics> results = workspace->check_all(1);
  ASSERT_EQ(results.size(), 1u);
  const FileDiagnostics& result = results.front();
  const Document& document = *workspace->model().source(result.source).document;
  const std::string reported = describe(result, *workspace);
  const std::string where = expectation.origin + " (" + expectation.file.string() + ")\nrung reported:\n" + reported;

  auto is_error = [](const Diagnostic& d) { return d.severity == Severity::Error; };
  if (expectation.expect == std::vector<std::string>{"clean"}) {
    EXPECT_FALSE(std::any_of(result.diagnostics.begin(), result.diagnostics.end(), is_error))
        << "expected no errors: " << where;
    return;
  }
  if (expectation.expect == std::vector<std::string>{"fragment"}) {
    // What an excerpt may miss: declarations of names (E001), types and POUs (E002), members of
    // types it does not show (E005) and the global list behind a VAR_EXTERNAL (E501).
    static const std::set<std::string> kDeclaredElsewhere = {"E001", "E002", "E005", "E501"};
    for (const Diagnostic& diagnostic : result.diagnostics) {
      EXPECT_FALSE(is_error(diagnostic) && !kDeclaredElsewhere.count(diagnostic.code))
          << "a fragment may only lack declarations (E001, E002, E005, E501): " << where;
    }
    return;
  }
  std::set<std::string> listed;
  for (const std::string& item : expectation.expect) {
    const auto at = item.find('@');
    const std::string code = item.substr(0, at);
    listed.insert(code);
    const uint32_t line = at == std::string::npos ? 0 : static_cast<uint32_t>(std::stoul(item.substr(at + 1)));
    const bool found = std::any_of(result.diagnostics.begin(), result.diagnostics.end(), [&](const Diagnostic& d) {
      return d.code == code && (line == 0 || document.position_of_file_offset(d.range.begin).line == line);
    });
    EXPECT_TRUE(found) << "expected " << item << ": " << where;
  }
  for (const Diagnostic& diagnostic : result.diagnostics) {
    EXPECT_FALSE(is_error(diagnostic) && !listed.count(diagnostic.code))
        << "unexpected error " << diagnostic.code << ": " << where;
  }
}

// Every example of the corpus has its row, so a new seed file cannot go unchecked.
TEST(ExpectationTables, EverySeedExampleHasOneRow) {
  std::set<std::string> rows;
  for (const Expectation& expectation : expectations()) {
    if (expectation.name.starts_with("seed_")) rows.insert(expectation.file.lexically_normal().string());
  }
  const fs::path seeds = rung::test::shared_dir() / "corpus" / "seeds";
  ASSERT_TRUE(fs::exists(seeds)) << seeds << " is missing: the tests need ../shared next to the repository";
  size_t files = 0;
  for (const auto& entry : fs::recursive_directory_iterator(seeds)) {
    if (!entry.is_regular_file()) continue;
    ++files;
    EXPECT_TRUE(rows.count(entry.path().lexically_normal().string()))
        << entry.path() << " has no row in tests/checker/seeds/*.tsv";
  }
  EXPECT_EQ(rows.size(), files);
}

INSTANTIATE_TEST_SUITE_P(Manuals, Expectations, ::testing::ValuesIn(expectations()),
                         [](const ::testing::TestParamInfo<Expectation>& info) { return info.param.name; });

}  // namespace
}  // namespace rung::check
