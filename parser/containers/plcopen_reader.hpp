// PLCopen XML (TC6 XML v2.00/v2.01) projects as virtual text.
//
// PLCopen XML is the exchange format of CODESYS V3 ("Export PLCopenXML") and
// the project file of Beremiz/OpenPLC (plc.xml). Unlike a TwinCAT file it holds
// declarations as XML, not as ST: rung synthesizes the ST for them and takes the
// code bodies from the file as they stand. The virtual text is, in order:
//
//   TYPE <name> : <type>; END_TYPE                       (each types/dataTypes/dataType)
//   PROGRAM|FUNCTION|FUNCTION_BLOCK <name> ...           (each types/pous/pou)
//     VAR_INPUT ... END_VAR ...                          (from interface/*Vars)
//     <ST or IL body>                                    (real text, mapped 1:1)
//     METHOD ... END_METHOD, PROPERTY ... END_PROPERTY   (CODESYS addData methods/properties)
//     ACTION <name>: <body> END_ACTION                   (actions with a textual body)
//     TRANSITION <name>: <body> END_TRANSITION           (transitions with a textual body)
//   END_PROGRAM|END_FUNCTION|END_FUNCTION_BLOCK
//   INTERFACE <name> METHOD ... END_METHOD ... END_INTERFACE  (CODESYS addData interfaces)
//   CONFIGURATION ... RESOURCE ... TASK ... PROGRAM ... END_CONFIGURATION
//     (also for a CODESYS application resource in the project's addData)
//
// CODESYS exports that include the device put POUs and data types into
// resource/addData/data[@name=".../pou" | ".../datatype"]; they are read as if
// they stood in types/. When CODESYS stored a declaration as plain text
// (InterfaceAsPlainText), that text is used instead of a synthesized one.
//
// Synthesized text is synthetic in the segment map, except the names and
// values that come from attributes (POU, variable, type, member and enum value
// names, derived type names, addresses, initial values, array bounds, task and
// instance names): these are real segments on the attribute's value, so a
// diagnostic on a declaration lands on its <variable name="..."> and a later
// rename edits the attribute. Bodies (CDATA or escaped text) are real text.
//
// Repairs of real files: unquoted string initial values (Beremiz) get synthetic
// quotes; a Beremiz ST transition ":= expr;" loses its ':='; <ST> bodies that
// hold C/C++ or Python (OpenPLC Editor v4) are skipped with a note. Reported as
// issues: a raw '<' in an attribute value, a variable name that is not an
// identifier (the variable is left out).
#pragma once

#include <string_view>

#include "parser/containers/container_document.hpp"

namespace rung::containers {

// `text` is the decoded (UTF-8, BOM removed) file text. Never throws; malformed
// XML yields an issue "malformed XML at line L: <cause>" and whatever could be
// read before the damage.
ContainerDocument read_plcopen(std::string_view text);

// Whether `text` looks like a PLCopen XML project: its root element (after the
// XML declaration, comments and doctype) is <project> and the PLCopen TC6 namespace (tc6_0200 or tc6_0201) is declared
// in the first few KB.
bool looks_like_plcopen(std::string_view text);

}  // namespace rung::containers
