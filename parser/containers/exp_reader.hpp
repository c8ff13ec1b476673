// CODESYS V2.3 .EXP exports as virtual text.
//
// An .EXP file is plain text holding many objects one after another, each
// preceded by marker comments:
//
//   (* @NESTEDCOMMENTS := 'Yes' *)
//   (* @GLOBAL_VARIABLE_LIST := 'Globals' *)     (global variable lists only)
//   (* @PATH := '\/Folder' *)
//   (* @OBJECTFLAGS := '0, 8' *)
//   (* @SYMFILEFLAGS := '2048' *)
//   FUNCTION_BLOCK FB_X ... (* @END_DECLARATION := '0' *) body END_FUNCTION_BLOCK
//   ACTION A: ... END_ACTION                     (actions follow their POU)
//
// The markers are ordinary comments and stay. Sections that are not code
// (VISUALISATION ... END_VISUALISATION, LIBRARY ... END_LIBRARY, _ALARMCONFIG,
// PLC_CONFIGURATION, RESOURCE task configuration, any "_KEYWORD" section) and
// graphical bodies (_FBD_BODY, _LD_BODY, _CFC_BODY, _SFC_BODY up to the POU's
// END_ keyword) are blanked: every byte except line ends becomes a space, so
// the virtual text keeps the file's length and maps 1:1 (one segment).
#pragma once

#include <string_view>

#include "parser/containers/container_document.hpp"

namespace rung::containers {

// `text` is the decoded file text (.EXP files are usually cp1252, decoded first).
// Each object is listed with its kind, name, @PATH folder, @NESTEDCOMMENTS flag,
// implementation language and the offset of its keyword line.
ContainerDocument read_exp(std::string_view text);

}  // namespace rung::containers
