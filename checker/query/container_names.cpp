#include "checker/query/container_names.hpp"

#include "checker/symbols/names.hpp"

namespace rung::check::query {

std::optional<TextRange> twincat_name_attribute(const Document& document, uint32_t declaration_offset,
                                                std::string_view name) {
  const containers::ContainerDocument* container = document.container();
  if (!container || container->kind != containers::ContainerKind::TwinCat) return std::nullopt;
  const std::string_view text = document.file_text();
  if (declaration_offset > text.size()) return std::nullopt;
  // <POU Name="FB_Valve" Id="{...}">  <Declaration><![CDATA[FUNCTION_BLOCK FB_Valve ...
  const size_t declaration = text.rfind("<Declaration", declaration_offset);
  if (declaration == std::string_view::npos || declaration == 0) return std::nullopt;
  const size_t element = text.rfind('<', declaration - 1);
  if (element == std::string_view::npos) return std::nullopt;
  const size_t element_end = text.find('>', element);
  if (element_end == std::string_view::npos || element_end > declaration) return std::nullopt;
  const std::string_view tag = text.substr(element, element_end - element);
  constexpr std::string_view kAttribute = " Name=\"";
  const size_t attribute = tag.find(kAttribute);
  if (attribute == std::string_view::npos) return std::nullopt;
  const size_t value_begin = attribute + kAttribute.size();
  const size_t value_end = tag.find('"', value_begin);
  if (value_end == std::string_view::npos || !names_equal(tag.substr(value_begin, value_end - value_begin), name)) {
    return std::nullopt;
  }
  const auto begin = static_cast<uint32_t>(element + value_begin);
  return TextRange{begin, static_cast<uint32_t>(begin + (value_end - value_begin))};
}

}  // namespace rung::check::query
