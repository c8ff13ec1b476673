#include "checker/project/project_config.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include "parser/source/line_index.hpp"
#include "tests/support/test_paths.hpp"

namespace rung::project {
namespace {

std::filesystem::path temp_project(const std::string& name) {
  auto dir = std::filesystem::temp_directory_path() / ("rung_project_" + name + "_" + std::to_string(getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

TEST(ProjectConfig, DefaultsWithoutRungToml) {
  auto dir = temp_project("defaults");
  LoadedConfig loaded = load_project_config(dir);
  EXPECT_TRUE(loaded.diagnostics.empty());
  EXPECT_FALSE(loaded.config.config_file.has_value());
  EXPECT_EQ(loaded.config.profile, Profile::Codesys);
  EXPECT_EQ(loaded.config.sources, std::vector<std::string>{"."});
  EXPECT_EQ(loaded.config.name, dir.filename().string());
  std::filesystem::remove_all(dir);
}

TEST(ProjectConfig, ReadsEverySetting) {
  LoadedConfig loaded = parse_project_config(R"(
[project]
name = "Cell 1"
profile = "TwinCAT"
sources = ["src", "gvl"]
exclude = ["src/generated/**"]
libraries = ["stubs/Tc2_MC2"]
[defines]
SIMULATION = true
DEBUG = false
LEVEL = 3
[diagnostics]
s008 = "off"
S003 = "warning"
[target]
max_string_length = 80
)",
                                             "/proj");
  EXPECT_TRUE(loaded.diagnostics.empty()) << loaded.diagnostics[0].message;
  const ProjectConfig& c = loaded.config;
  EXPECT_EQ(c.name, "Cell 1");
  EXPECT_EQ(c.profile, Profile::Twincat);
  EXPECT_EQ(c.sources, (std::vector<std::string>{"src", "gvl"}));
  ASSERT_EQ(c.libraries.size(), 1u);
  EXPECT_EQ(c.libraries[0], std::filesystem::path("/proj/stubs/Tc2_MC2"));
  EXPECT_EQ(c.defines.count("SIMULATION"), 1u);
  EXPECT_EQ(c.defines.count("DEBUG"), 0u);  // false means not defined
  EXPECT_EQ(c.defines.at("LEVEL"), "3");
  ASSERT_EQ(c.severity_overrides.count("S008"), 1u);
  EXPECT_FALSE(c.severity_overrides.at("S008").has_value());
  EXPECT_EQ(c.severity_overrides.at("S003"), Severity::Warning);
  EXPECT_EQ(c.max_string_length, 80u);
}

TEST(ProjectConfig, BrokenTomlGivesAPositionedDiagnostic) {
  std::string text = "[project]\nname = \"x\"\nprofile = \n";
  LoadedConfig loaded = parse_project_config(text, "/proj");
  ASSERT_EQ(loaded.diagnostics.size(), 1u);
  EXPECT_EQ(loaded.diagnostics[0].code, "P001");
  source::LineIndex lines(loaded.text);
  EXPECT_EQ(lines.position_of(loaded.diagnostics[0].range.begin).line, 2u);  // 0-based: line 3
}

TEST(ProjectConfig, UnknownKeysWarnAndBadValuesError) {
  LoadedConfig loaded = parse_project_config(
      "[project]\nprofil = \"iec\"\nprofile = \"siemens\"\nsources = 3\n[diagnostics]\nX999 = \"off\"\nS001 = "
      "\"loud\"\n",
      "/proj");
  std::vector<std::string> codes;
  for (const auto& d : loaded.diagnostics) codes.push_back(d.code + ":" + std::string(severity_name(d.severity)));
  EXPECT_EQ(codes,
            (std::vector<std::string>{"P002:warning", "P003:error", "P003:error", "P002:warning", "P003:error"}));
  EXPECT_EQ(loaded.config.profile, Profile::Codesys);  // the bad value left the default
}

TEST(ProjectConfig, GlobPatterns) {
  EXPECT_TRUE(glob_match("src/generated/**", "src/generated/a/b.st"));
  EXPECT_TRUE(glob_match("**/*.TcPOU", "a/b/FB_X.TcPOU"));
  EXPECT_TRUE(glob_match("**/*.TcPOU", "FB_X.TcPOU"));
  EXPECT_TRUE(glob_match("*.st", "main.st"));
  EXPECT_FALSE(glob_match("*.st", "src/main.st"));
  EXPECT_TRUE(glob_match("src/?.st", "src/a.st"));
  EXPECT_FALSE(glob_match("src/?.st", "src/ab.st"));
  EXPECT_FALSE(glob_match("src/**", "lib/x.st"));
}

TEST(ProjectConfig, SourceFilesHonourSourcesAndExcludes) {
  auto dir = temp_project("files");
  test::write_file(dir / "src/Main.st", "");
  test::write_file(dir / "src/generated/Gen.st", "");
  test::write_file(dir / "other/Skip.st", "");
  test::write_file(dir / "rung.toml", "[project]\nsources = [\"src\"]\nexclude = [\"src/generated/**\"]\n");
  LoadedConfig loaded = load_project_config(dir);
  ASSERT_TRUE(loaded.diagnostics.empty());
  auto files = project_source_files(loaded.config);
  ASSERT_EQ(files.size(), 1u);
  EXPECT_EQ(files[0].filename(), "Main.st");
  EXPECT_EQ(find_project_root(dir / "src/generated"), dir);
  std::filesystem::remove_all(dir);
}

TEST(ProjectConfig, InitTemplateParsesToTheDefaults) {
  LoadedConfig loaded = parse_project_config(default_config_text("demo"), "/proj");
  EXPECT_TRUE(loaded.diagnostics.empty()) << loaded.diagnostics[0].message;
  EXPECT_EQ(loaded.config.name, "demo");
  EXPECT_EQ(loaded.config.profile, Profile::Codesys);
  EXPECT_EQ(loaded.config.max_string_length, 255u);
}

}  // namespace
}  // namespace rung::project
