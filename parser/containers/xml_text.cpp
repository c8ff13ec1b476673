#include "parser/containers/xml_text.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <optional>

#include "parser/source/line_index.hpp"
#include "parser/source/utf8.hpp"

namespace rung::containers {
namespace {

struct Entity {
  size_t length;  // bytes from '&' to ';' inclusive
  std::string replacement;
};

std::optional<char32_t> parse_number(std::string_view digits, int base) {
  if (digits.empty() || digits.size() > 8) return std::nullopt;
  char32_t value = 0;
  for (const char c : digits) {
    int d;
    if (c >= '0' && c <= '9')
      d = c - '0';
    else if (base == 16 && c >= 'a' && c <= 'f')
      d = c - 'a' + 10;
    else if (base == 16 && c >= 'A' && c <= 'F')
      d = c - 'A' + 10;
    else
      return std::nullopt;
    value = value * base + static_cast<char32_t>(d);
  }
  // Only scalar values other than NUL may be written as character references.
  if (value == 0 || value > 0x10FFFF || (value >= 0xD800 && value <= 0xDFFF)) return std::nullopt;
  return value;
}

// The entity starting at text[pos] == '&', or nullopt when it is not a valid one.
std::optional<Entity> entity_at(std::string_view text, size_t pos) {
  const size_t semi = text.find(';', pos + 1);
  if (semi == std::string_view::npos || semi - pos > 12) return std::nullopt;
  const std::string_view name = text.substr(pos + 1, semi - pos - 1);
  const size_t length = semi - pos + 1;
  if (name == "lt") return Entity{length, "<"};
  if (name == "gt") return Entity{length, ">"};
  if (name == "amp") return Entity{length, "&"};
  if (name == "quot") return Entity{length, "\""};
  if (name == "apos") return Entity{length, "'"};
  if (name.size() >= 2 && name[0] == '#') {
    const bool hex = name[1] == 'x' || name[1] == 'X';
    const auto cp = hex ? parse_number(name.substr(2), 16) : parse_number(name.substr(1), 10);
    if (!cp) return std::nullopt;
    std::string bytes;
    source::append_utf8(bytes, *cp);
    return Entity{length, std::move(bytes)};
  }
  return std::nullopt;
}

// Calls on_text(run, offset) and on_entity(replacement, offset) in order.
template <typename OnText, typename OnEntity>
void scan(std::string_view raw, OnText&& on_text, OnEntity&& on_entity) {
  size_t run_begin = 0;
  size_t pos = raw.find('&');
  while (pos != std::string_view::npos) {
    if (const auto entity = entity_at(raw, pos)) {
      on_text(raw.substr(run_begin, pos - run_begin), run_begin);
      on_entity(entity->replacement, pos);
      run_begin = pos + entity->length;
      pos = raw.find('&', run_begin);
    } else {
      pos = raw.find('&', pos + 1);
    }
  }
  on_text(raw.substr(run_begin), run_begin);
}

}  // namespace

void append_escaped_text(VirtualTextBuilder& builder, std::string_view raw, uint32_t file_begin, std::string_view role,
                         std::string_view object_name) {
  scan(
      raw,
      [&](std::string_view run, size_t at) {
        builder.append_real(run, file_begin + static_cast<uint32_t>(at), role, object_name);
      },
      [&](std::string_view replacement, size_t at) {
        builder.append_real(replacement, file_begin + static_cast<uint32_t>(at), role, object_name);
      });
}

std::string unescape_xml(std::string_view raw) {
  std::string out;
  out.reserve(raw.size());
  scan(
      raw, [&](std::string_view run, size_t) { out.append(run); },
      [&](std::string_view replacement, size_t) { out.append(replacement); });
  return out;
}

std::optional<ContainerIssue> load_container_xml(pugi::xml_document& xml, std::string_view text) {
  constexpr unsigned kFlags = (pugi::parse_default | pugi::parse_cdata) & ~pugi::parse_eol & ~pugi::parse_escapes;
  const pugi::xml_parse_result parsed = xml.load_buffer(text.data(), text.size(), kFlags, pugi::encoding_utf8);
  if (parsed) return std::nullopt;
  const auto offset = static_cast<uint32_t>(std::min<size_t>(static_cast<size_t>(parsed.offset), text.size()));
  const source::LineIndex lines(text);
  return ContainerIssue{
      offset, fmt::format("malformed XML at line {}: {}", lines.position_of(offset).line + 1, parsed.description())};
}

}  // namespace rung::containers
