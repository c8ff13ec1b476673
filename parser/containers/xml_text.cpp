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

// Where markup that starts at `at` ('<' of a comment, CDATA section, processing
// instruction or doctype) ends: just past its terminator; npos when it is none
// of these or is not terminated.
size_t skip_special_markup(std::string_view text, size_t at) {
  const auto past = [&](std::string_view terminator, size_t from) {
    const size_t end = text.find(terminator, from);
    return end == std::string_view::npos ? text.size() : end + terminator.size();
  };
  if (text.compare(at, 4, "<!--") == 0) return past("-->", at + 4);
  if (text.compare(at, 9, "<![CDATA[") == 0) return past("]]>", at + 9);
  if (text.compare(at, 2, "<?") == 0) return past("?>", at + 2);
  if (text.compare(at, 2, "<!") == 0) {
    // <!DOCTYPE ...>, possibly with an internal subset in [...].
    const size_t bracket = text.find('[', at);
    const size_t close = text.find('>', at);
    if (bracket != std::string_view::npos && bracket < close) return past(">", past("]", bracket));
    return past(">", at + 2);
  }
  return std::string_view::npos;
}

// The offset of the first raw '<' inside an attribute value. pugixml accepts it
// (CODESYS writes creationDateTime="<NORMALIZED>" when told to hide dates), but
// XML forbids it and other tools reject the file.
namespace {

std::optional<size_t> lt_in_attribute(std::string_view text) {
  const auto space = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; };
  size_t at = 0;
  while ((at = text.find('<', at)) != std::string_view::npos) {
    if (const size_t skipped = skip_special_markup(text, at); skipped != std::string_view::npos) {
      at = skipped;
      continue;
    }
    size_t i = at + 1;
    if (i < text.size() && text[i] == '/') {
      at = i;
      continue;
    }
    while (i < text.size() && !space(text[i]) && text[i] != '>' && text[i] != '/') ++i;
    // Attributes: name = "value" ... until '>' or '/>'.
    while (true) {
      while (i < text.size() && space(text[i])) ++i;
      if (i >= text.size() || text[i] == '>' || text[i] == '/' || text[i] == '<') break;
      while (i < text.size() && !space(text[i]) && text[i] != '=' && text[i] != '>' && text[i] != '<') ++i;
      while (i < text.size() && space(text[i])) ++i;
      if (i >= text.size() || text[i] != '=') break;
      ++i;
      while (i < text.size() && space(text[i])) ++i;
      if (i >= text.size() || (text[i] != '"' && text[i] != '\'')) break;
      const char quote = text[i];
      const size_t close = text.find(quote, i + 1);
      if (close == std::string_view::npos) return std::nullopt;
      if (const size_t lt = text.substr(i + 1, close - i - 1).find('<'); lt != std::string_view::npos) {
        return i + 1 + lt;
      }
      i = close + 1;
    }
    at = i;
  }
  return std::nullopt;
}

}  // namespace

std::optional<ContainerIssue> load_container_xml(pugi::xml_document& xml, std::string_view text) {
  constexpr unsigned kFlags = (pugi::parse_default | pugi::parse_cdata) & ~pugi::parse_eol & ~pugi::parse_escapes;
  const pugi::xml_parse_result parsed = xml.load_buffer(text.data(), text.size(), kFlags, pugi::encoding_utf8);
  if (parsed) {
    // pugixml accepts a raw '<' inside an attribute value; XML (and the vendors' tools) do not.
    const auto lt = lt_in_attribute(text);
    if (!lt) return std::nullopt;
    const source::LineIndex lines(text);
    const auto offset = static_cast<uint32_t>(*lt);
    return ContainerIssue{offset, fmt::format("malformed XML at line {}: '<' inside an attribute value",
                                              lines.position_of(offset).line + 1)};
  }
  const auto offset = static_cast<uint32_t>(std::min<size_t>(static_cast<size_t>(parsed.offset), text.size()));
  const source::LineIndex lines(text);
  return ContainerIssue{
      offset, fmt::format("malformed XML at line {}: {}", lines.position_of(offset).line + 1, parsed.description())};
}

}  // namespace rung::containers
