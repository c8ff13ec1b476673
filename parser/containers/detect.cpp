#include "parser/containers/detect.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <string>

#include "parser/containers/plcopen_reader.hpp"

namespace rung::containers {
namespace {

std::string lower_extension(std::string_view path) {
  const size_t slash = path.find_last_of("/\\");
  const std::string_view name = slash == std::string_view::npos ? path : path.substr(slash + 1);
  const size_t dot = name.rfind('.');
  if (dot == std::string_view::npos) return {};
  std::string ext(name.substr(dot + 1));
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

std::string_view skip_blank(std::string_view text) {
  size_t i = 0;
  while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
  return text.substr(i);
}

bool is_twincat_xml(std::string_view text) {
  const std::string_view head = skip_blank(text);
  if (head.empty() || head.front() != '<') return false;
  // The root follows the XML declaration and perhaps comments: a short look suffices.
  return head.substr(0, 4096).find("<TcPlcObject") != std::string_view::npos;
}

bool is_codesys_export(std::string_view text) {
  return skip_blank(text).substr(0, 64).find("(* @NESTEDCOMMENTS") == 0;
}

}  // namespace

ContainerKind detect_container(std::string_view path, std::string_view text) {
  const std::string ext = lower_extension(path);
  constexpr std::array<std::string_view, 5> twincat_source = {"tcpou", "tcdut", "tcgvl", "tcio", "tcitf"};
  // Task objects, visualisations, text lists, type system objects: XML without PLC source.
  constexpr std::array<std::string_view, 5> twincat_other = {"tctto", "tcvis", "tcvmo", "tctlo", "tcgtlo"};
  if (std::find(twincat_source.begin(), twincat_source.end(), ext) != twincat_source.end()) {
    return ContainerKind::TwinCat;
  }
  if (std::find(twincat_other.begin(), twincat_other.end(), ext) != twincat_other.end()) {
    return ContainerKind::Unsupported;
  }
  if (ext == "exp") return ContainerKind::CodesysExp;
  if (looks_like_plcopen(text)) return ContainerKind::PlcOpen;
  if (is_twincat_xml(text)) return ContainerKind::TwinCat;
  if (is_codesys_export(text)) return ContainerKind::CodesysExp;
  return ContainerKind::None;
}

}  // namespace rung::containers
