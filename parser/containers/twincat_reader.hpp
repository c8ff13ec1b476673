// TwinCAT 3 PLC object files (.TcPOU, .TcDUT, .TcGVL, .TcIO, .TcITF) as virtual text.
//
// A TwinCAT file is XML: <TcPlcObject><POU|DUT|GVL|Itf Name=...> holding a
// <Declaration> and an <Implementation><ST>, plus <Method>, <Property> (with
// <Get>/<Set>), <Action> and <Transition> children, each with their own
// declaration and body in CDATA. The virtual text puts them one after another:
//
//   declaration \n implementation
//   \n method declaration \n method implementation              (each Method)
//   \n property declaration \n GET\n get declaration \n get body  (and SET\n ...)
//   \n ACTION <Name>:\n action body                              (each Action)
//   \n ACTION <Name>:\n transition body                          (each Transition)
//
// The "\n" separators and the GET/SET/ACTION header lines are synthetic; all
// other text maps 1:1 to the file (CDATA content, or escaped character data
// mapped piece by piece around its entities).
#pragma once

#include <string_view>

#include "parser/containers/container_document.hpp"

namespace rung::containers {

// `text` is the decoded (UTF-8, BOM removed) file text. Never throws; malformed
// XML yields an issue "malformed XML at line L: <cause>" and whatever could be
// read before the damage.
ContainerDocument read_twincat(std::string_view text);

}  // namespace rung::containers
