// Which container format a file is, from its name and, failing that, its content.
#pragma once

#include <string_view>

#include "parser/containers/container_document.hpp"

namespace rung::containers {

// By extension, case-insensitive: .TcPOU .TcDUT .TcGVL .TcIO .TcITF -> TwinCat;
// .TcTTO and other TwinCAT objects without PLC source (visualisations, type
// libraries) -> Unsupported; .EXP -> CodesysExp. Other names are judged by
// content: an XML file whose root is <TcPlcObject> is TwinCat, a file opening
// with "(* @NESTEDCOMMENTS" is a CODESYS export; everything else is None
// (an ordinary source file).
ContainerKind detect_container(std::string_view path, std::string_view text);

}  // namespace rung::containers
