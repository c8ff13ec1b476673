// XML character data as virtual text: entities unescaped, positions kept.
#pragma once

#include <cstdint>
#include <optional>
#include <pugixml.hpp>
#include <string>
#include <string_view>

#include "parser/containers/container_document.hpp"

namespace rung::containers {

// Appends escaped character data (`raw` as it stands in the file, starting at
// file offset `file_begin`) with its entities replaced. Each run between
// entities is one real segment; each entity's replacement is a real segment
// that starts at the entity's '&', so a diagnostic on "<" lands on "&lt;".
// Unknown or malformed entities are kept verbatim.
void append_escaped_text(VirtualTextBuilder& builder, std::string_view raw, uint32_t file_begin, std::string_view role,
                         std::string_view object_name);

// The unescaped text of an attribute value or character data (no positions).
std::string unescape_xml(std::string_view raw);

// Where markup that starts at `at` (the '<' of a comment, CDATA section, processing instruction
// or doctype) ends: just past its terminator; npos when it is none of these.
size_t skip_special_markup(std::string_view text, size_t at);

// Loads a container's XML so that node offsets are file offsets: CDATA kept as nodes, no line-end
// normalisation, no entity decoding (readers unescape text themselves, mapping it piecewise).
// Returns the issue to report when the XML is malformed (also a raw '<' in an attribute value,
// which pugixml accepts); what could be read stays in `xml`.
std::optional<ContainerIssue> load_container_xml(pugi::xml_document& xml, std::string_view text);

}  // namespace rung::containers
