// The project model's configuration: rung.toml. A project is a folder; rung.toml (optional) says
// which files belong to it, which semantics profile applies, which libraries to load, which
// conditional-compilation symbols are defined and how severe each diagnostic code is.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "checker/project/format_settings.hpp"
#include "checker/project/lint_settings.hpp"
#include "parser/diagnostic.hpp"

namespace rung::project {

// Where vendors disagree (REAL_TO_INT ties, short-circuit AND, TON boundary, ...), the profile
// picks one behaviour; checker and runner read the same table.
enum class Profile { Codesys, Iec, Twincat, Openpcs };
std::string_view profile_name(Profile profile);
std::optional<Profile> parse_profile(std::string_view name);

struct ProjectConfig {
  std::filesystem::path root;  // the project folder (holds rung.toml if any)
  std::optional<std::filesystem::path> config_file;
  std::string name;  // [project] name; default: the folder's name
  Profile profile = Profile::Codesys;
  std::vector<std::string> sources{"."};         // files/folders relative to root
  std::vector<std::string> exclude;              // glob patterns relative to root ("**", "*", "?")
  std::vector<std::filesystem::path> libraries;  // folders of declaration-only ST, absolute
  std::map<std::string, std::string> defines;    // {IF defined(NAME)} symbols and their values
  // Per-code severity; nullopt turns the code off.
  std::map<std::string, std::optional<Severity>> severity_overrides;
  uint32_t max_string_length = 255;  // [target] longest STRING(n) the target allows
  // [target] addressing: how %I/%Q/%M numbers map to bytes, "byte" (CODESYS V3: %MW1 = bytes
  // 2..3, bits 0..7), "word" (word.bit, bits 0..15) or "byte-offset" (%MW1 = bytes 1..2);
  // empty: the profile's.
  std::string addressing;
  FormatSettings format;  // [format]: rung fmt
  LintSettings lint;      // [lint]: rung lint
};

struct LoadedConfig {
  ProjectConfig config;
  std::string text;                     // rung.toml as read ("" without one)
  std::vector<Diagnostic> diagnostics;  // ranges are byte offsets in `text`
};

// Reads `folder`/rung.toml if present; without it, the defaults for that folder. Never throws:
// a broken rung.toml gives diagnostics (P001 syntax, P002 unknown key, P003 bad value) and the
// defaults for what could not be read.
LoadedConfig load_project_config(const std::filesystem::path& folder);

// Parses rung.toml text (for tests and the language server's unsaved buffers).
LoadedConfig parse_project_config(std::string text, const std::filesystem::path& folder);

// The nearest folder at or above `start` that holds a rung.toml, if any.
std::optional<std::filesystem::path> find_project_root(const std::filesystem::path& start);

// The commented rung.toml that `rung init` writes.
std::string default_config_text(std::string_view project_name);

// Whether a path relative to the project root (with '/' separators) matches a glob pattern:
// '*' matches within one path segment, '**' across segments, '?' one character.
bool glob_match(std::string_view pattern, std::string_view path);

// The project's source files: every file kind rung reads below `sources`, minus `exclude`,
// sorted. Library folders are not included.
std::vector<std::filesystem::path> project_source_files(const ProjectConfig& config,
                                                        std::vector<std::string>* errors = nullptr);

}  // namespace rung::project
