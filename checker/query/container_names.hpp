// Names a vendor container writes outside the code. TwinCAT stores the name of each object
// (POU, DUT, interface, method, property) twice: in the Name attribute of its XML element and in
// the ST declaration inside it; TwinCAT reads the attribute, so a rename must change both.
#pragma once

#include <optional>
#include <string_view>

#include "parser/document.hpp"

namespace rung::check::query {

// The value of the Name attribute (FILE coordinates) of the TwinCAT element whose <Declaration>
// holds `declaration_offset` (a FILE offset), when that value spells `name` (case-insensitively);
// nullopt for any other file or element.
std::optional<TextRange> twincat_name_attribute(const Document& document, uint32_t declaration_offset,
                                                std::string_view name);

}  // namespace rung::check::query
