// The formatter on every example of the seed corpus (../shared/corpus/seeds) that parses: it must
// format it (never refuse it as unsafe) with the default settings and with a set that changes
// every option, and formatting the result again must change nothing.
#include <gtest/gtest.h>

#include <filesystem>

#include "formatter/format.hpp"
#include "parser/document.hpp"
#include "tests/formatter/check_samples.hpp"

namespace rung::format {
namespace {

namespace fs = std::filesystem;

project::FormatSettings non_default_settings() {
  project::FormatSettings s;
  s.keyword_case = project::KeywordCase::Lower;
  s.elementary_types_follow_keyword_case = false;
  s.use_tabs = false;
  s.indent_width = 2;
  s.spaces_around_operators = false;
  s.space_after_comma = false;
  s.align_types = false;
  s.align_initial_values = false;
  s.align_comments = false;
  s.max_line_width = 60;
  s.max_blank_lines = 0;
  s.end_semicolon = project::EndSemicolon::Always;
  s.else_if_to_elsif = true;
  return s;
}

struct SeedRun {
  size_t files = 0;      // files read
  size_t formatted = 0;  // files that parse and were formatted with both settings
};

TEST(SeedFormat, EverySeedThatParsesFormatsSafelyAndIdempotently) {
  const std::vector<fs::path> files = test_samples::seed_files();
  if (files.empty()) GTEST_SKIP() << "seed corpus not found next to the repository";

  const project::FormatSettings settings[] = {project::FormatSettings{}, non_default_settings()};
  SeedRun run;
  for (const fs::path& path : files) {
    std::string error;
    std::optional<Document> doc = Document::load(path, &error);
    if (!doc || !doc->tree()) continue;
    ++run.files;
    const std::string text(doc->source_text());
    bool formatted_both = true;
    for (const project::FormatSettings& s : settings) {
      const FormatResult first = format_text(text, s);
      EXPECT_NE(first.status, Status::Unsafe) << path << ": " << first.message;
      if (first.status != Status::Formatted) {
        formatted_both = false;
        continue;
      }
      const FormatResult second = format_text(first.text, s);
      EXPECT_EQ(second.status, Status::Formatted) << path << ": " << second.message;
      EXPECT_EQ(second.text, first.text) << path << ": formatting twice changes the text";
    }
    if (formatted_both) ++run.formatted;
  }
  // The corpus has about 520 examples, a few of them wrong on purpose.
  EXPECT_GT(run.formatted, 350u);
  std::cout << "[ seeds    ] formatted " << run.formatted << " of " << run.files << " seed files\n";
}

}  // namespace
}  // namespace rung::format
