// rung.toml [format]: how `rung fmt` lays out code. Plain data: the formatter reads it, the
// project configuration fills it (checker/project/format_settings.cpp reads the TOML table).
#pragma once

#include <cstdint>
#include <string>

namespace rung::project {

enum class KeywordCase { Upper, Lower, Preserve };

// The ';' after END_IF, END_CASE, END_FOR, END_WHILE and END_REPEAT (an empty statement in ST,
// so adding or removing it never changes what a program does).
enum class EndSemicolon { Keep, Always, Never };

struct FormatSettings {
  // Keywords (IF, END_VAR, AND, ...) and, when `elementary_types_follow_keyword_case`, the
  // elementary type names (BOOL, INT, TIME, ...). Identifiers keep their spelling.
  KeywordCase keyword_case = KeywordCase::Upper;
  bool elementary_types_follow_keyword_case = true;
  uint32_t indent_width = 4;
  bool use_tabs = true;  // CODESYS and TwinCAT editors indent with tabs of width 4
  bool spaces_around_operators = true;  // a := b + c  vs  a:=b+c
  bool space_after_comma = true;
  // Column alignment inside one VAR block (a run of declarations without blank lines between).
  bool align_types = true;           // the ':' before the type
  bool align_initial_values = true;  // the ':=' of initial values
  bool align_comments = true;        // trailing comments
  // Lines longer than this are broken: conditions at their top-level AND/OR (one operand per
  // line), calls one argument per line. 0: never break.
  uint32_t max_line_width = 120;
  uint32_t max_blank_lines = 1;  // runs of blank lines are shortened to this
  EndSemicolon end_semicolon = EndSemicolon::Keep;
  // ELSE IF c THEN .. END_IF END_IF becomes ELSIF c THEN .. END_IF when the inner IF is the only
  // statement of the ELSE branch (the one case where both mean the same).
  bool else_if_to_elsif = false;
  // The preset the settings started from: "codesys" (default), "twincat" or "rung" (spaces).
  std::string preset = "codesys";
};

// The defaults of a preset; false when the name is unknown.
bool apply_format_preset(std::string_view preset, FormatSettings& settings);

}  // namespace rung::project
