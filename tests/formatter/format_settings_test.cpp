// rung.toml [format]: every key, bad values, presets and their order independence.
#include "checker/project/format_settings.hpp"

#include <gtest/gtest.h>

#include "checker/project/project_config.hpp"
#include "parser/source/line_index.hpp"

namespace rung::project {
namespace {

LoadedConfig load(const std::string& format_table) {
  return parse_project_config("[format]\n" + format_table, "/proj");
}

FormatSettings settings_of(const std::string& format_table) {
  LoadedConfig loaded = load(format_table);
  EXPECT_TRUE(loaded.diagnostics.empty()) << loaded.diagnostics[0].code << " " << loaded.diagnostics[0].message;
  return loaded.config.format;
}

// "P003 line 2: message | help" per diagnostic, lines 1-based in rung.toml.
std::vector<std::string> findings(const std::string& format_table) {
  LoadedConfig loaded = load(format_table);
  source::LineIndex lines(loaded.text);
  std::vector<std::string> out;
  for (const Diagnostic& d : loaded.diagnostics) {
    out.push_back(d.code + " line " + std::to_string(lines.position_of(d.range.begin).line + 1) + ": " + d.message +
                  " | " + d.help);
  }
  return out;
}

TEST(FormatSettings, DefaultsAreTheCodesysPreset) {
  FormatSettings none = parse_project_config("", "/proj").config.format;
  FormatSettings codesys;
  ASSERT_TRUE(apply_format_preset("codesys", codesys));
  EXPECT_EQ(none.preset, "codesys");
  EXPECT_TRUE(none.use_tabs);
  EXPECT_EQ(none.indent_width, 4u);
  EXPECT_EQ(none.keyword_case, KeywordCase::Upper);
  EXPECT_EQ(none.max_line_width, 120u);
  EXPECT_TRUE(none.align_types && none.align_initial_values && none.align_comments);
  EXPECT_EQ(codesys.use_tabs, none.use_tabs);
  EXPECT_EQ(codesys.max_line_width, none.max_line_width);
}

TEST(FormatSettings, ReadsEveryKey) {
  FormatSettings s = settings_of(R"(
keyword_case = "lower"
elementary_types_follow_keyword_case = false
indent_width = 2
use_tabs = false
spaces_around_operators = false
space_after_comma = false
align_types = false
align_initial_values = false
align_comments = false
max_line_width = 80
max_blank_lines = 2
end_semicolon = "always"
else_if_to_elsif = true
)");
  EXPECT_EQ(s.keyword_case, KeywordCase::Lower);
  EXPECT_FALSE(s.elementary_types_follow_keyword_case);
  EXPECT_EQ(s.indent_width, 2u);
  EXPECT_FALSE(s.use_tabs);
  EXPECT_FALSE(s.spaces_around_operators);
  EXPECT_FALSE(s.space_after_comma);
  EXPECT_FALSE(s.align_types);
  EXPECT_FALSE(s.align_initial_values);
  EXPECT_FALSE(s.align_comments);
  EXPECT_EQ(s.max_line_width, 80u);
  EXPECT_EQ(s.max_blank_lines, 2u);
  EXPECT_EQ(s.end_semicolon, EndSemicolon::Always);
  EXPECT_TRUE(s.else_if_to_elsif);
}

TEST(FormatSettings, EveryWordOfTheWordKeys) {
  EXPECT_EQ(settings_of("keyword_case = \"upper\"").keyword_case, KeywordCase::Upper);
  EXPECT_EQ(settings_of("keyword_case = \"preserve\"").keyword_case, KeywordCase::Preserve);
  EXPECT_EQ(settings_of("keyword_case = \"Lower\"").keyword_case, KeywordCase::Lower);  // case-insensitive
  EXPECT_EQ(settings_of("end_semicolon = \"keep\"").end_semicolon, EndSemicolon::Keep);
  EXPECT_EQ(settings_of("end_semicolon = \"never\"").end_semicolon, EndSemicolon::Never);
}

TEST(FormatSettings, RangeLimitsAreAccepted) {
  EXPECT_EQ(settings_of("indent_width = 1").indent_width, 1u);
  EXPECT_EQ(settings_of("indent_width = 16").indent_width, 16u);
  EXPECT_EQ(settings_of("max_line_width = 0").max_line_width, 0u);  // never break
  EXPECT_EQ(settings_of("max_line_width = 40").max_line_width, 40u);
  EXPECT_EQ(settings_of("max_line_width = 1000").max_line_width, 1000u);
  EXPECT_EQ(settings_of("max_blank_lines = 0").max_blank_lines, 0u);
  EXPECT_EQ(settings_of("max_blank_lines = 10").max_blank_lines, 10u);
}

TEST(FormatSettings, BadValuesAreP003WithAValidExample) {
  // One table per value: TOML does not allow a key twice in a table.
  const std::pair<std::string, std::string> cases[] = {
      {"keyword_case = \"camel\"",
       "'keyword_case' must be \"upper\", \"lower\" or \"preserve\" | keyword_case = \"upper\""},
      {"indent_width = 0", "'indent_width' must be a number from 1 to 16 | indent_width = 4"},
      {"indent_width = 17", "'indent_width' must be a number from 1 to 16 | indent_width = 4"},
      {"indent_width = 4.0", "'indent_width' must be a number from 1 to 16 | indent_width = 4"},
      {"max_line_width = 39", "'max_line_width' must be 0 (off) or a number from 40 to 1000 | max_line_width = 120"},
      {"max_line_width = 1001", "'max_line_width' must be 0 (off) or a number from 40 to 1000 | max_line_width = 120"},
      {"max_blank_lines = 11", "'max_blank_lines' must be a number from 0 to 10 | max_blank_lines = 1"},
      {"max_blank_lines = -1", "'max_blank_lines' must be a number from 0 to 10 | max_blank_lines = 1"},
      {"use_tabs = 1", "'use_tabs' must be true or false | use_tabs = true"},
      {"align_comments = \"yes\"", "'align_comments' must be true or false | align_comments = true"},
      {"else_if_to_elsif = 0", "'else_if_to_elsif' must be true or false | else_if_to_elsif = true"},
      {"end_semicolon = true", "'end_semicolon' must be \"keep\", \"always\" or \"never\" | end_semicolon = \"keep\""},
  };
  for (const auto& [line, expected] : cases) {
    EXPECT_EQ(findings("space_after_comma = true\n" + line + "\n"),
              std::vector<std::string>{"P003 line 3: " + expected})
        << line;
  }
}

TEST(FormatSettings, ABadValueKeepsTheDefault) {
  LoadedConfig loaded = load("indent_width = 99\nkeyword_case = 3\nmax_line_width = 80\n");
  EXPECT_EQ(loaded.diagnostics.size(), 2u);
  EXPECT_EQ(loaded.config.format.indent_width, 4u);
  EXPECT_EQ(loaded.config.format.keyword_case, KeywordCase::Upper);
  EXPECT_EQ(loaded.config.format.max_line_width, 80u);  // the good key still counts
}

TEST(FormatSettings, UnknownKeysAreP002ListingTheKnownOnes) {
  LoadedConfig loaded = load("indent = 2\nuse_tabs = false\n");
  ASSERT_EQ(loaded.diagnostics.size(), 1u);
  const Diagnostic& d = loaded.diagnostics[0];
  EXPECT_EQ(d.code, "P002");
  EXPECT_EQ(d.severity, Severity::Warning);
  EXPECT_EQ(d.message, "unknown key 'indent' in [format]");
  EXPECT_NE(d.help.find("indent_width"), std::string::npos) << d.help;
  EXPECT_NE(d.help.find("else_if_to_elsif"), std::string::npos) << d.help;
  EXPECT_FALSE(loaded.config.format.use_tabs);
}

TEST(FormatSettings, FormatMustBeATable) {
  LoadedConfig loaded = parse_project_config("format = 3\n", "/proj");
  ASSERT_EQ(loaded.diagnostics.size(), 1u);
  EXPECT_EQ(loaded.diagnostics[0].code, "P003");
  EXPECT_EQ(loaded.diagnostics[0].message, "[format] must be a table");
}

TEST(FormatSettings, Presets) {
  FormatSettings rung = settings_of("preset = \"rung\"");
  EXPECT_EQ(rung.preset, "rung");
  EXPECT_FALSE(rung.use_tabs);
  EXPECT_EQ(rung.indent_width, 4u);
  EXPECT_EQ(rung.keyword_case, KeywordCase::Upper);
  EXPECT_TRUE(rung.align_types && rung.align_initial_values && rung.align_comments);
  EXPECT_EQ(rung.max_line_width, 100u);

  FormatSettings twincat = settings_of("preset = \"twincat\"");
  EXPECT_EQ(twincat.preset, "twincat");
  EXPECT_TRUE(twincat.use_tabs);
  EXPECT_EQ(twincat.indent_width, 4u);
  EXPECT_EQ(twincat.keyword_case, KeywordCase::Upper);
  EXPECT_EQ(twincat.max_line_width, 120u);

  FormatSettings codesys = settings_of("preset = \"CODESYS\"");
  EXPECT_EQ(codesys.preset, "codesys");
  EXPECT_TRUE(codesys.use_tabs);
  EXPECT_EQ(codesys.max_line_width, 120u);
}

TEST(FormatSettings, UnknownPresetIsP003) {
  EXPECT_EQ(findings("preset = \"siemens\"\n"),
            std::vector<std::string>{
                "P003 line 2: 'preset' must be \"codesys\", \"twincat\" or \"rung\" | preset = \"codesys\""});
  EXPECT_EQ(findings("preset = 1\n").size(), 1u);
}

TEST(FormatSettings, ExplicitKeysOverrideThePresetWhereverItStands) {
  FormatSettings before = settings_of("preset = \"rung\"\nmax_line_width = 90\nuse_tabs = true\n");
  FormatSettings after = settings_of("max_line_width = 90\nuse_tabs = true\npreset = \"rung\"\n");
  for (const FormatSettings& s : {before, after}) {
    EXPECT_EQ(s.preset, "rung");
    EXPECT_EQ(s.max_line_width, 90u);
    EXPECT_TRUE(s.use_tabs);
    EXPECT_EQ(s.indent_width, 4u);
  }
}

TEST(FormatSettings, ApplyPresetRejectsUnknownNames) {
  FormatSettings s;
  s.indent_width = 7;
  EXPECT_FALSE(apply_format_preset("eclipse", s));
  EXPECT_EQ(s.indent_width, 7u);  // untouched
  EXPECT_TRUE(apply_format_preset("rung", s));
  EXPECT_EQ(s.indent_width, 4u);
}

}  // namespace
}  // namespace rung::project
