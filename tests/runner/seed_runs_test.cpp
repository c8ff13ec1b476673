// The manuals' example programs run, and the values their text states compared: the facts are
// the rows of tests/runner/seed_runs.tsv (its header explains the columns), the programs the
// examples of the shared corpus (../shared/corpus/seeds): the CODESYS V3 textbook, the AK800 PLC
// manual, the MP300 motion controller manual and the OpenPCS manual. One test per example, so
// that a failure names the file.
#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include "tests/runner/run_support.hpp"
#include "tests/support/test_paths.hpp"

namespace rung::run::testing {
namespace {

struct Row {
  int line = 0;
  std::string file;
  uint64_t cycles = 1;
  std::string variable;
  std::string expected;
  std::string note;

  bool is_input() const { return expected.rfind(":=", 0) == 0 || expected.rfind('@', 0) == 0; }
  // The value an input row writes ("@1,3:=TRUE" and ":=TRUE" write TRUE).
  std::string input_value() const { return expected.substr(expected.find(":=") + 2); }
  // The cycles before which an input row writes its value: 1 for ":=", the list of "@1,3:=".
  std::vector<uint64_t> input_cycles() const {
    std::vector<uint64_t> at;
    if (expected[0] != '@') return {1};
    const std::string list = expected.substr(1, expected.find(":=") - 1);
    for (size_t start = 0; start < list.size();) {
      size_t comma = list.find(',', start);
      if (comma == std::string::npos) comma = list.size();
      at.push_back(std::strtoull(list.substr(start, comma - start).c_str(), nullptr, 10));
      start = comma + 1;
    }
    return at;
  }
  bool known_difference() const { return note.rfind("KNOWN-DIFFERENCE", 0) == 0; }
};

// One run of an example: the inputs, each written before its cycles, then the facts checked
// after `cycles` cycles.
struct Scenario {
  uint64_t cycles = 1;
  std::vector<Row> inputs;
  std::vector<Row> facts;
};

struct SeedCase {
  std::string file;
  std::vector<Scenario> scenarios;
};

std::filesystem::path table_path() {
  return rung::test::source_dir() / "tests" / "runner" / "seed_runs.tsv";
}

std::filesystem::path seeds_dir() {
  return rung::test::shared_dir() / "corpus" / "seeds";
}

std::vector<std::string> split_tabs(const std::string& line) {
  std::vector<std::string> fields;
  size_t start = 0;
  while (true) {
    const size_t tab = line.find('\t', start);
    fields.push_back(line.substr(start, tab == std::string::npos ? std::string::npos : tab - start));
    if (tab == std::string::npos) break;
    start = tab + 1;
  }
  return fields;
}

// The rows of the table; a malformed line becomes a row with an empty file (reported by the
// table test).
std::vector<Row> table_rows() {
  std::vector<Row> rows;
  std::ifstream in(table_path());
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty() || line[0] == '#' || line.rfind("file\t", 0) == 0) continue;
    const std::vector<std::string> fields = split_tabs(line);
    Row row;
    row.line = number;
    if (fields.size() == 5) {
      row.file = fields[0];
      row.cycles = std::strtoull(fields[1].c_str(), nullptr, 10);
      row.variable = fields[2];
      row.expected = fields[3];
      row.note = fields[4];
    }
    rows.push_back(row);
  }
  return rows;
}

// The rows grouped by file (in table order) and into runs: the rows of a file with the same
// cycles run together, and an input row after a fact starts another run.
std::vector<SeedCase> seed_cases() {
  std::vector<SeedCase> cases;
  std::map<std::string, size_t> index;
  for (const Row& row : table_rows()) {
    if (row.file.empty()) continue;
    auto [it, added] = index.emplace(row.file, cases.size());
    if (added) cases.push_back(SeedCase{row.file, {}});
    std::vector<Scenario>& scenarios = cases[it->second].scenarios;
    const bool fresh = scenarios.empty() || scenarios.back().cycles != row.cycles ||
                       (row.is_input() && !scenarios.back().facts.empty());
    if (fresh) scenarios.push_back(Scenario{row.cycles, {}, {}});
    (row.is_input() ? scenarios.back().inputs : scenarios.back().facts).push_back(row);
  }
  return cases;
}

// "~6.86": the REAL the manual rounds, within half a unit of its last written digit.
bool approximately(const std::string& expected, const std::string& actual, std::string* why) {
  const std::string number = expected.substr(1);
  const size_t e = number.find_first_of("eE");
  const std::string mantissa = number.substr(0, e);
  const long exponent = e == std::string::npos ? 0 : std::strtol(number.c_str() + e + 1, nullptr, 10);
  const size_t point = mantissa.find('.');
  const long decimals = point == std::string::npos ? 0 : static_cast<long>(mantissa.size() - point - 1);
  const double tolerance = 0.5 * std::pow(10.0, static_cast<double>(exponent - decimals));
  char* end = nullptr;
  const double value = std::strtod(actual.c_str(), &end);
  if (end == actual.c_str() || *end != '\0') {
    *why = "not a number";
    return false;
  }
  const double want = std::strtod(number.c_str(), nullptr);
  if (std::fabs(value - want) <= tolerance * (1 + 1e-9)) return true;
  *why = "differs by more than " + std::to_string(tolerance);
  return false;
}

std::string test_name(const ::testing::TestParamInfo<SeedCase>& info) {
  std::string name;
  for (char c : info.param.file) name += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  return name;
}

// Names the example in failure messages instead of printing its bytes.
void PrintTo(const SeedCase& seed, std::ostream* out) {
  *out << seed.file;
}

class SeedRuns : public ::testing::TestWithParam<SeedCase> {};

TEST_P(SeedRuns, ManualValues) {
  const SeedCase& seed = GetParam();
  const std::filesystem::path path = seeds_dir() / seed.file;
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "the seed corpus is not available: " << path;
  const std::string source = rung::test::read_file(path);
  int skipped = 0;
  for (const Scenario& scenario : seed.scenarios) {
    bool all_known = true;
    for (const Row& fact : scenario.facts) all_known = all_known && fact.known_difference();
    if (all_known) {
      skipped += static_cast<int>(scenario.facts.size());
      continue;
    }
    // Writes each input before its cycle (after the initial values for cycle 1), cycle by cycle.
    auto run = run_files({{path.filename().string(), source}}, RunOptions{.cycles = 0});
    ASSERT_CLEAN(run);
    for (uint64_t cycle = 1; cycle <= scenario.cycles; ++cycle) {
      for (const Row& input : scenario.inputs) {
        for (uint64_t at : input.input_cycles()) {
          if (at == cycle) run->set(input.variable, input.input_value());
        }
      }
      ASSERT_TRUE(run->cycles(1)) << run->described_error();
    }
    for (const Row& fact : scenario.facts) {
      if (fact.known_difference()) {
        ++skipped;
        continue;
      }
      const std::string actual = run->text(fact.variable);
      const std::string where = "seed_runs.tsv line " + std::to_string(fact.line) + ": " + fact.variable + " after " +
                                std::to_string(scenario.cycles) + " cycle(s) (" + fact.note + ")";
      if (fact.expected.rfind('~', 0) == 0) {
        std::string why;
        EXPECT_TRUE(approximately(fact.expected, actual, &why))
            << where << ": expected " << fact.expected << ", got " << actual << ": " << why;
      } else {
        EXPECT_EQ(actual, fact.expected) << where;
      }
    }
  }
  if (skipped > 0) std::cout << "[ NOTE     ] " << seed.file << ": " << skipped << " known difference(s) skipped\n";
}

INSTANTIATE_TEST_SUITE_P(Manuals, SeedRuns, ::testing::ValuesIn(seed_cases()), test_name);

TEST(SeedRunsTable, HasFactsAndEveryFileExists) {
  const std::vector<Row> rows = table_rows();
  size_t facts = 0;
  size_t known = 0;
  for (const Row& row : rows) {
    EXPECT_FALSE(row.file.empty()) << "seed_runs.tsv line " << row.line << ": not five TAB-separated fields";
    EXPECT_GT(row.cycles, 0u) << "seed_runs.tsv line " << row.line << ": cycles";
    if (row.is_input()) continue;
    ++facts;
    if (row.known_difference()) ++known;
  }
  EXPECT_GE(facts, 240u);
  EXPECT_GE(seed_cases().size(), 110u);
  std::cout << "[ NOTE     ] seed_runs.tsv: " << facts << " facts, " << known << " known differences\n";
  if (!std::filesystem::exists(seeds_dir())) GTEST_SKIP() << "the seed corpus is not available";
  for (const SeedCase& seed : seed_cases()) {
    EXPECT_TRUE(std::filesystem::is_regular_file(seeds_dir() / seed.file)) << seed.file;
  }
}

}  // namespace
}  // namespace rung::run::testing
